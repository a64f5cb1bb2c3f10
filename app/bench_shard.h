/* bench_shard.h - the grid of a `trimvr bench` sweep and its slices
 * (docs/bench.md). A row is one scene x method x delta, numbered in run
 * order: scenes as listed, then methods as listed, then deltas; q3vis exists
 * on oa: scenes only. A unit is a row's viewcells, or with cells_per_unit a
 * run of that many of them. The numbering depends on the options alone (no
 * file is opened), so every shard of a sweep agrees on it. */
#ifndef TRIMVR_APP_BENCH_SHARD_H
#define TRIMVR_APP_BENCH_SHARD_H

#include "method.h"

#include <stdbool.h>
#include <stdio.h>

typedef struct tv_bench_unit {
    int scene, method, delta; /* indices into the option lists */
    int row;                  /* the report row it belongs to */
    int first_cell, end_cell; /* its viewcells: [first_cell, end_cell) of the scene's (at most max_cells) */
} tv_bench_unit;

/* The most units a sweep has, and the most shards --shard takes. */
#define TV_BENCH_MAX_UNITS 1000000

/* Fills units (may be NULL) and returns how many there are: one per row
 * when cells_per_unit is 0, else ceil(max_cells / cells_per_unit) per row
 * (a unit past a scene's last viewcell is empty); -1, filling nothing, when
 * that is more than TV_BENCH_MAX_UNITS. max_cells >= 1. */
int tv_bench_units(char* const* scenes, int nscene, const pvs_method_kind* methods, int nmethod, int ndelta,
                   int max_cells, int cells_per_unit, tv_bench_unit* units);

/* Parses --shard "I/N" with 0 <= I < N. */
bool tv_bench_shard_parse(const char* s, int* i, int* n);

/* Slice i of n over `units` units: [*first, *end), contiguous, sizes differ
 * by one at most (empty when n > units). */
void tv_bench_slice(int units, int i, int n, int* first, int* end);

/* Prints one line per unit u: `exe bench ARGS --shard u/units`, ARGS being
 * argv without --jobs, each word quoted for sh where it needs it. */
void tv_bench_print_jobs(FILE* f, const char* exe, int argc, char** argv, int units);

#endif
