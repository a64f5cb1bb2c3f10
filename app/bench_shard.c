#include "bench_shard.h"

#include <stdlib.h>
#include <string.h>

int tv_bench_units(char* const* scenes, int nscene, const pvs_method_kind* methods, int nmethod, int ndelta,
                   int max_cells, int cells_per_unit, tv_bench_unit* units)
{
    int n = 0, row = 0, step = cells_per_unit > 0 ? cells_per_unit : max_cells;
    long long per_row = ((long long)max_cells + step - 1) / step, rows = 0;
    for (int s = 0; s < nscene; s++)
        for (int m = 0; m < nmethod; m++)
            rows += methods[m] != PVS_METHOD_Q3VIS || strncmp(scenes[s], "oa:", 3) == 0 ? ndelta : 0;
    if (rows * per_row > TV_BENCH_MAX_UNITS)
        return -1;
    for (int s = 0; s < nscene; s++)
        for (int m = 0; m < nmethod; m++) {
            if (methods[m] == PVS_METHOD_Q3VIS && strncmp(scenes[s], "oa:", 3) != 0)
                continue;
            for (int d = 0; d < ndelta; d++, row++)
                for (int c = 0, end; c < max_cells; c = end, n++) {
                    end = max_cells - c > step ? c + step : max_cells; /* c + step may pass INT_MAX */
                    if (units)
                        units[n] = (tv_bench_unit){s, m, d, row, c, end};
                }
        }
    return n;
}

bool tv_bench_shard_parse(const char* s, int* i, int* n)
{
    char* end;
    long a = strtol(s, &end, 10);
    if (end == s || *end != '/')
        return false;
    const char* rest = end + 1;
    long b = strtol(rest, &end, 10);
    if (end == rest || *end || a < 0 || b < 1 || a >= b || b > TV_BENCH_MAX_UNITS)
        return false;
    *i = (int)a;
    *n = (int)b;
    return true;
}

void tv_bench_slice(int units, int i, int n, int* first, int* end)
{
    *first = (int)((long long)units * i / n);
    *end = (int)((long long)units * (i + 1) / n);
}

/* Single quotes unless the word is made of characters sh leaves alone. */
static void put_word(FILE* f, const char* w)
{
    bool plain = *w != 0;
    for (const char* c = w; *c && plain; c++)
        plain = strchr("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_./:,=+-@%", *c) != NULL;
    if (plain) {
        fputs(w, f);
        return;
    }
    fputc('\'', f);
    for (const char* c = w; *c; c++)
        fputs(*c == '\'' ? "'\\''" : (char[]){*c, 0}, f);
    fputc('\'', f);
}

void tv_bench_print_jobs(FILE* f, const char* exe, int argc, char** argv, int units)
{
    for (int u = 0; u < units; u++) {
        put_word(f, exe);
        fputs(" bench", f);
        for (int i = 0; i < argc; i++) {
            if (strcmp(argv[i], "--jobs") == 0)
                continue;
            fputc(' ', f);
            put_word(f, argv[i]);
        }
        fprintf(f, " --shard %d/%d\n", u, units);
    }
}
