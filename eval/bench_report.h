/* bench_report.h - the outputs of `trimvr bench`: one row per scene x delta x
 * method, written as DIR/bench.csv, DIR/bench.json and DIR/bench.md (one
 * markdown table per scene, plus the trim-region method's per-phase table),
 * and gnuplot PNGs in the style of the paper's Figures 14-16. */
#ifndef TRIMVR_EVAL_BENCH_REPORT_H
#define TRIMVR_EVAL_BENCH_REPORT_H

#include "eval_common.h"

#include <stdbool.h>
#include <stddef.h>

/* One viewcell of one grid cell (scene x method x delta): what a run
 * measures, what part files carry, and what rows are aggregated from. */
typedef struct tv_bench_cell {
    int row;                /* report row in run order (scene, method, delta; app/bench_shard.h) */
    int index;              /* viewcell index within the scene */
    char scene[64];
    pvs_method_kind method;
    float delta;
    tv_eval_cell c;         /* the viewcell, its metrics and the method's stats */
    double full_ms[3];      /* full-scene draws at the PVS resolution and FOV from the centre (timing) */
} tv_bench_cell;

typedef struct tv_bench_row {
    char scene[64];         /* the scene spec as given (builtin:city, sponza, oa:oasago2) */
    pvs_method_kind method;
    float delta;
    int cells;
    tv_eval_cell mean;      /* tv_eval_mean over the viewcells */
    uint32_t views;         /* id-buffer views the method rendered per viewcell (gt, sas, frompoint) */
    double full_pvsres_ms;  /* median full-scene draw at the PVS resolution and FOV, same run */
    /* the worst viewcell: its FN pixels per view (fraction of the image) and
     * the PSNR of its views' mean squared error (the bar holds "at
     * every sampled viewcell") */
    double fng_fraction_worst_cell, psnr_worst_cell_db;
    /* 95 % t-intervals over the viewcells (half-widths; NaN under 2 cells):
     * mean FNG pixels, and PVS/GT as a ratio of means (bench_stats.c) */
    double fng_ci95, pvs_over_gt_ci95;
    tv_eval_cell worst;     /* the viewcell with the most FN pixels per view (then the lowest PSNR) */
    int worst_index;        /* its index within the scene */
} tv_bench_row;

/* Rows from viewcell results sorted by (row, index): one row per row index,
 * means (tv_eval_mean), intervals and the worst cell. Full-render time is
 * the median of every viewcell's draws. malloc'ed into *rows; returns the
 * count, -1 when out of memory. */
int tv_bench_rows(const tv_bench_cell* cells, int n, tv_bench_row** rows);

typedef struct tv_bench_info {
    const char* command_line;
    const char* date;       /* UTC */
    const char* device;     /* Vulkan device name */
    const char* version;    /* trimvr's code version (git describe at build time) */
    const char* merged;     /* NULL for one run; else what was merged ("12 parts from ...") */
    const char* stopped;    /* NULL for a whole sweep; else why it stopped early (the rows are those completed) */
    unsigned res[2], pvs_res[2];
    int samples;
    float fov, fov_pvs;
    double wall_s;
} tv_bench_info;

/* Writes DIR/bench.csv, DIR/bench.json and DIR/bench.md. Rows of one scene
 * and method must be contiguous and in ascending delta (the plots draw them
 * as lines). False with "FILE: cannot write" in err. */
bool tv_bench_write(const char* dir, const tv_bench_info* info, const tv_bench_row* rows, int n, char* err,
                    size_t err_size);

/* Writes DIR/bench.gp and runs gnuplot on DIR/bench.csv: per scene,
 * fig14_runtime_<scene>.png (PVS ms per method vs delta, full render for
 * scale), fig15_size_<scene>.png (PVS size and FP rate vs delta) and
 * fig16_fng_<scene>.png (false-negative pixels vs delta with the 0.005 %
 * line). A missing gnuplot is a warning: the tables are the results. */
void tv_bench_plots(const char* dir, const tv_bench_row* rows, int n);

#endif
