/* scene_test_dir.h - a private temporary folder for tests that write files. */
#ifndef TRIMVR_SCENE_TEST_DIR_H
#define TRIMVR_SCENE_TEST_DIR_H

#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Creates /tmp/<prefix>_XXXXXX into dir (mkdtemp needs _DEFAULT_SOURCE in
 * the including file). */
static inline bool scene_test_dir_create(char* dir, size_t size, const char* prefix)
{
    snprintf(dir, size, "/tmp/%s_XXXXXX", prefix);
    if (mkdtemp(dir))
        return true;
    perror("mkdtemp");
    return false;
}

static inline void scene_test_dir_remove(const char* dir)
{
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", dir);
}

#endif
