/* interrupt.h - SIGINT/SIGTERM as a request to stop cleanly. A long run
 * installs the handler, checks tv_interrupted() between units of work (a
 * frame, a viewcell), finishes the unit it is in, writes what it computed and
 * exits non-zero. A second signal ends the process at once (the default
 * action), for a run stuck inside one unit. */
#ifndef TRIMVR_APP_INTERRUPT_H
#define TRIMVR_APP_INTERRUPT_H

/* Installs the handler for SIGINT and SIGTERM and clears the flag. */
void tv_interrupt_install(void);

/* The signal received since tv_interrupt_install, or 0. */
int tv_interrupted(void);

/* The conventional exit status of a run stopped by signal sig: 128 + sig. */
int tv_interrupt_status(int sig);

#endif
