/* trimvr bench merge: part files of a sharded sweep into the report a
 * serial run writes (docs/bench.md). */
#include "bench_part.h"
#include "log.h"

#include "fs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int by_row_then_index(const void* a, const void* b)
{
    const tv_bench_cell *x = a, *y = b;
    if (x->row != y->row)
        return (x->row > y->row) - (x->row < y->row);
    return (x->index > y->index) - (x->index < y->index);
}

/* Names the first option on which two settings strings (NAME=VALUE;...) differ. */
static void settings_differ(const char* a, const char* sa, const char* b, const char* sb)
{
    size_t i = 0, start = 0;
    while (sa[i] && sa[i] == sb[i]) {
        if (sa[i] == ';')
            start = i + 1;
        i++;
    }
    int la = (int)strcspn(sa + start, ";"), lb = (int)strcspn(sb + start, ";");
    tv_log(TV_LOG_ERROR, "%s and %s: parts of different settings (%.*s vs %.*s)", a, b, la,
            sa + start, lb, sb + start);
}

/* One line naming the two files when part i disagrees with part 0 or
 * repeats another's shard. */
static bool check_parts(const tv_bench_part* p, char* const* files, int n)
{
    int* seen = calloc((size_t)p[0].shards, sizeof *seen);
    bool ok = seen != NULL;
    for (int i = 0; ok && i < n; i++) {
        const char *a = files[0], *b = files[i];
        if (strcmp(p[i].version, p[0].version) != 0)
            tv_log(TV_LOG_ERROR, "%s (version %s) and %s (version %s): parts of different "
                            "trimvr versions", a, p[0].version, b, p[i].version);
        else if (strcmp(p[i].settings, p[0].settings) != 0)
            settings_differ(a, p[0].settings, b, p[i].settings);
        else if (p[i].shards != p[0].shards)
            tv_log(TV_LOG_ERROR, "%s (%d shards) and %s (%d shards): parts of different "
                            "slicings", a, p[0].shards, b, p[i].shards);
        else if (seen[p[i].shard])
            tv_log(TV_LOG_ERROR, "%s and %s: both are shard %d/%d", files[seen[p[i].shard] - 1],
                    b, p[i].shard, p[i].shards);
        ok = strcmp(p[i].version, p[0].version) == 0 && strcmp(p[i].settings, p[0].settings) == 0 &&
             p[i].shards == p[0].shards && !seen[p[i].shard];
        seen[p[i].shard] = i + 1;
    }
    for (int s = 0; ok && s < p[0].shards; s++)
        if (!seen[s]) {
            tv_log(TV_LOG_ERROR, "shard %d/%d is missing (%d part files given)", s,
                    p[0].shards, n);
            ok = false;
        }
    free(seen);
    return ok;
}

/* The report of all parts' cells, with the header fields a serial run
 * would have: one device when all agree, the latest date, wall time summed. */
static bool write_merged(const tv_bench_part* p, int n, const char* out)
{
    int total = 0;
    for (int i = 0; i < n; i++)
        total += p[i].count;
    tv_bench_cell* cells = malloc(((size_t)total + 1) * sizeof *cells);
    if (!cells) {
        tv_log(TV_LOG_ERROR, "out of memory for %d viewcell results", total);
        return false;
    }
    char devices[1024] = "", merged[256];
    const char* date = p[0].date;
    double wall = 0.0;
    for (int i = 0, k = 0; i < n; i++) {
        memcpy(&cells[k], p[i].cells, (size_t)p[i].count * sizeof *cells);
        k += p[i].count;
        wall += p[i].wall_s;
        if (strcmp(p[i].date, date) > 0)
            date = p[i].date;
        if (p[i].device[0] && !strstr(devices, p[i].device))
            snprintf(devices + strlen(devices), sizeof devices - strlen(devices), "%s%s", devices[0] ? "; " : "",
                     p[i].device);
    }
    qsort(cells, (size_t)total, sizeof *cells, by_row_then_index);
    bool ok = true;
    for (int i = 1; ok && i < total; i++)
        if (by_row_then_index(&cells[i - 1], &cells[i]) == 0) {
            tv_log(TV_LOG_ERROR, "row %d viewcell %d appears twice", cells[i].row,
                    cells[i].index);
            ok = false;
        }
    tv_bench_row* rows = NULL;
    int nrows = ok ? tv_bench_rows(cells, total, &rows) : -1;
    snprintf(merged, sizeof merged, "merged from %d parts (wall time summed over them)", n);
    tv_bench_info info = {.command_line = p[0].command, .date = date, .device = devices, .version = p[0].version,
                          .merged = merged, .res = {p[0].res[0], p[0].res[1]},
                          .pvs_res = {p[0].pvs_res[0], p[0].pvs_res[1]}, .samples = p[0].samples, .fov = p[0].fov,
                          .fov_pvs = p[0].fov_pvs, .wall_s = wall};
    char err[4300];
    if (ok && nrows <= 0) {
        tv_log(TV_LOG_ERROR, "%s", nrows < 0 ? "out of memory" : "the parts hold no results");
        ok = false;
    }
    if (ok && !(ok = tv_mkdirs(out)))
        tv_log(TV_LOG_ERROR, "%s: cannot create the output folder", out);
    if (ok && !(ok = tv_bench_write(out, &info, rows, nrows, err, sizeof err)))
        tv_log(TV_LOG_ERROR, "%s", err);
    if (ok) {
        tv_bench_plots(out, rows, nrows);
        printf("trimvr bench merge: %d parts, %d rows -> %s/bench.md, bench.csv, bench.json\n", n, nrows, out);
    }
    free(rows);
    free(cells);
    return ok;
}

int tv_cmd_bench_merge(int argc, char** argv)
{
    const char* out = NULL;
    char** files = calloc((size_t)argc + 1, sizeof *files);
    int n = 0;
    for (int i = 0; files && i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            printf("usage: trimvr bench merge --out DIR PART.json...\n\nMerges the part files of a sharded "
                   "`trimvr bench` (--jobs, --shard) into DIR/bench.md,\nbench.csv, bench.json and plots, as the "
                   "serial run writes them. The parts must come from\none build and one set of options, every "
                   "shard once. See docs/bench.md.\n");
            free(files);
            return 0;
        }
        if (strcmp(argv[i], "--out") == 0 && i + 1 < argc)
            out = argv[++i];
        else if (strncmp(argv[i], "--out=", 6) == 0)
            out = argv[i] + 6;
        else if (strncmp(argv[i], "--", 2) == 0) {
            tv_log(TV_LOG_ERROR, "unknown option '%s' (see trimvr bench merge --help)",
                    argv[i]);
            free(files);
            return 2;
        } else
            files[n++] = argv[i];
    }
    if (!out || n == 0) {
        tv_log(TV_LOG_ERROR, "need --out DIR and at least one part file");
        free(files);
        return 2;
    }
    tv_bench_part* parts = calloc((size_t)n, sizeof *parts);
    bool ok = parts != NULL;
    char err[4400];
    int read = 0;
    for (; ok && read < n; read++)
        if (!(ok = tv_bench_part_read(files[read], &parts[read], err, sizeof err)))
            tv_log(TV_LOG_ERROR, "%s", err);
    ok = ok && check_parts(parts, files, n) && write_merged(parts, n, out);
    for (int i = 0; parts && i < read; i++)
        tv_bench_part_free(&parts[i]);
    free(parts);
    free(files);
    return ok ? 0 : 1;
}
