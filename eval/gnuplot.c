#define _POSIX_C_SOURCE 200809L
#include "gnuplot.h"

#include "log.h"

#include <stdlib.h>

FILE* tv_gnuplot_begin(const char* dir, const char* name, const char* writer)
{
    char script[4200];
    snprintf(script, sizeof script, "%s/%s", dir, name);
    FILE* f = fopen(script, "w");
    if (!f)
        tv_log(TV_LOG_WARN, "%s: cannot write the plot script", script);
    else
        fprintf(f, "# gnuplot script written by %s; run: gnuplot %s (in this folder)\n", writer, name);
    return f;
}

void tv_gnuplot_finish(FILE* f, const char* dir, const char* name, const char* kept)
{
    fclose(f);
    char cmd[8600];
    snprintf(cmd, sizeof cmd, "cd '%s' && gnuplot %s 2>/dev/null", dir, name);
    if (system(cmd) != 0)
        tv_log(TV_LOG_WARN, "gnuplot failed or is not installed: no plots (run scripts/setup.sh); %s are complete",
               kept);
}
