#define _POSIX_C_SOURCE 200809L
#include "interrupt.h"

#include <signal.h>
#include <string.h>

/* the only state a signal handler may touch portably */
static volatile sig_atomic_t g_signal;

static void on_signal(int sig) { g_signal = sig; }

void tv_interrupt_install(void)
{
    g_signal = 0;
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    /* SA_RESTART: a write of frames.csv in progress completes; SA_RESETHAND:
     * the second signal takes the default action */
    sa.sa_flags = SA_RESTART | SA_RESETHAND;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
}

int tv_interrupted(void) { return (int)g_signal; }

int tv_interrupt_status(int sig) { return 128 + sig; }
