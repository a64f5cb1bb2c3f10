/* clock.h - monotonic wall-clock time for timings. */
#ifndef TRIMVR_CLOCK_H
#define TRIMVR_CLOCK_H

#ifdef __cplusplus
extern "C" {
#endif

/* Milliseconds from an arbitrary fixed origin (CLOCK_MONOTONIC). */
double tv_now_ms(void);

#ifdef __cplusplus
}
#endif

#endif
