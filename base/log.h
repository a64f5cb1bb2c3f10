/* log.h - the one logging path of trimvr.
 *
 * Every module reports through tv_log(); the default sink writes
 * "<program>: <level>: <message>" lines to stderr (program "trimvr" unless
 * tv_log_set_program names the subcommand). Tests install their own sink
 * to capture and assert on messages (for example validation-layer output).
 */
#ifndef TRIMVR_LOG_H
#define TRIMVR_LOG_H

#include <stdarg.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum tv_log_level {
    TV_LOG_DEBUG = 0,
    TV_LOG_INFO = 1,
    TV_LOG_WARN = 2,
    TV_LOG_ERROR = 3
} tv_log_level;

typedef void (*tv_log_sink)(tv_log_level level, const char* message, void* user);

/* Replaces the sink (NULL restores the stderr sink). Not thread-safe against
 * concurrent tv_log calls: set it once at start-up or in a test's set-up. */
void tv_log_set_sink(tv_log_sink sink, void* user);

/* The first word of the default sink's lines, such as "trimvr replay"
 * (copied; NULL restores "trimvr"). Set once at start-up, like the sink. */
void tv_log_set_program(const char* name);

/* Messages below this level are dropped (default TV_LOG_INFO; TRIMVR_LOG=debug lowers it). */
void tv_log_set_level(tv_log_level level);

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
void tv_log(tv_log_level level, const char* fmt, ...);

void tv_logv(tv_log_level level, const char* fmt, va_list args);

#ifdef __cplusplus
}
#endif

#endif
