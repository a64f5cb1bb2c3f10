/* bench_report.h - the outputs of `trimvr bench`: one row per scene x delta x
 * method, written as DIR/bench.csv, DIR/bench.json and DIR/bench.md (one
 * markdown table per scene, plus the trim-region method's per-phase table),
 * and gnuplot PNGs in the style of the paper's Figures 14-16. */
#ifndef TRIMVR_EVAL_BENCH_REPORT_H
#define TRIMVR_EVAL_BENCH_REPORT_H

#include "eval_common.h"

#include <stdbool.h>
#include <stddef.h>

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
} tv_bench_row;

typedef struct tv_bench_info {
    const char* command_line;
    const char* date;       /* UTC */
    const char* device;     /* Vulkan device name */
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
