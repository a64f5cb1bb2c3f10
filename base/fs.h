/* fs.h - file-system helpers for output folders. */
#ifndef TRIMVR_FS_H
#define TRIMVR_FS_H

#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Creates `dir` and any missing parents (like mkdir -p). True if it exists
 * as a folder afterwards. */
bool tv_mkdirs(const char* dir);

#ifdef __cplusplus
}
#endif

#endif
