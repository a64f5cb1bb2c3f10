#include "log.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static tv_log_sink g_sink;
static void* g_sink_user;
static int g_level = -1; /* -1: not yet read from the environment */
static char g_program[64] = "trimvr";

static const char* level_name(tv_log_level level)
{
    switch (level) {
    case TV_LOG_DEBUG: return "debug";
    case TV_LOG_INFO: return "info";
    case TV_LOG_WARN: return "warning";
    default: return "error";
    }
}

void tv_log_set_sink(tv_log_sink sink, void* user)
{
    g_sink = sink;
    g_sink_user = user;
}

void tv_log_set_program(const char* name)
{
    snprintf(g_program, sizeof g_program, "%s", name ? name : "trimvr");
}

void tv_log_set_level(tv_log_level level) { g_level = (int)level; }

static int current_level(void)
{
    if (g_level < 0) {
        const char* env = getenv("TRIMVR_LOG");
        g_level = (env && strcmp(env, "debug") == 0) ? TV_LOG_DEBUG : TV_LOG_INFO;
    }
    return g_level;
}

void tv_logv(tv_log_level level, const char* fmt, va_list args)
{
    if ((int)level < current_level())
        return;
    char message[1024];
    vsnprintf(message, sizeof message, fmt, args);
    if (g_sink) {
        g_sink(level, message, g_sink_user);
        return;
    }
    /* one fprintf per line so lines from different threads do not interleave */
    fprintf(stderr, "%s: %s: %s\n", g_program, level_name(level), message);
}

void tv_log(tv_log_level level, const char* fmt, ...)
{
    va_list args;
    va_start(args, fmt);
    tv_logv(level, fmt, args);
    va_end(args);
}
