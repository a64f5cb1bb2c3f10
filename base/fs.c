#define _POSIX_C_SOURCE 200809L
#include "fs.h"

#include <errno.h>
#include <string.h>
#include <sys/stat.h>

static bool is_dir(const char* path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

bool tv_mkdirs(const char* dir)
{
    char buf[4096];
    size_t n = strlen(dir);
    if (n == 0 || n >= sizeof buf)
        return false;
    memcpy(buf, dir, n + 1);
    for (char* p = buf + 1; *p; p++) {
        if (*p != '/')
            continue;
        *p = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST)
            return false;
        *p = '/';
    }
    if (mkdir(buf, 0777) != 0 && errno != EEXIST)
        return false;
    return is_dir(buf);
}
