/* fuzz_common.h - what the libFuzzer targets share: the loaders under test
 * read files, so each input goes through a per-process temporary file, and
 * their warnings are silenced (a finding is a crash or a sanitizer report,
 * not a message). */
#ifndef TRIMVR_FUZZ_COMMON_H
#define TRIMVR_FUZZ_COMMON_H

#define _DEFAULT_SOURCE /* getpid */
#include "log.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static void _fuzz_quiet(tv_log_level level, const char* message, void* user)
{
    (void)level, (void)message, (void)user;
}

/* Writes the input to /tmp/trimvr_fuzz_PID.EXT; returns the path (static
 * storage) or NULL. */
static inline const char* fuzz_write_input(const uint8_t* data, size_t size, const char* ext)
{
    static char file[96];
    tv_log_set_sink(_fuzz_quiet, NULL);
    snprintf(file, sizeof file, "/tmp/trimvr_fuzz_%d.%s", (int)getpid(), ext);
    FILE* f = fopen(file, "wb");
    if (!f)
        return NULL;
    size_t written = fwrite(data, 1, size, f);
    fclose(f);
    return written == size ? file : NULL;
}

#endif
