/* replay.h - the simulated HMD loop (`trimvr replay`, the main job).
 *
 * A simulated headset follows a path on a simulated clock: sensor samples
 * (1 kHz, noise) feed a predictor; the loop sizes a viewcell for the next
 * PVS's use window and hands it to the asynchronous PVS worker; every display
 * frame latches the newest pose at submit time, and every `every`-th frame is
 * rendered per eye from the current PVS and from the full scene and compared.
 * docs/replay.md describes the timeline and every output. */
#ifndef TRIMVR_APP_REPLAY_H
#define TRIMVR_APP_REPLAY_H

#include "hmd.h"
#include "method.h"
#include "predictor.h"
#include "pvs_worker.h"
#include "viewcell.h"

#include <stdbool.h>
#include <stdint.h>

typedef struct tv_replay_desc {
    const char* scene;       /* scene spec (app_scene.h aliases allowed) */
    const char* path;        /* head-motion path file */
    const char* out_dir;
    pvs_method_desc method;
    pred_predictor_desc predictor;
    pred_viewcell_desc viewcell; /* policy, fixed delta/FOV, quantile, limits, display FOV */
    hmd_desc hmd;
    tv_latency_model latency_model;
    double latency_s;        /* fixed model: request -> availability */
    double latency_factor;   /* measured model: factor on the compute time */
    unsigned width, height;  /* eye image resolution */
    float near_m, far_m;
    int every;               /* evaluate every Nth display frame */
    uint64_t max_frames;     /* 0: the whole path */
    double cpu_ms;           /* simulated CPU time from frame start to submit */
    bool no_late_latch;      /* latch the pose at frame start instead of at submit */
    bool progress;           /* progress bar on stderr */
    bool plots;              /* write PNG plots with gnuplot */
    bool coverage_only;      /* no PVS computed, no frame rendered: sizing and coverage only
                                (fixed latency model; tv_pvs_pipeline_desc.no_pvs) */
} tv_replay_desc;

/* Runs the replay and writes DIR/frames.csv, DIR/summary.json, plots and the
 * worst frame's images; prints the summary table. Returns the process exit
 * status (0 on success; errors are printed as one line). */
int tv_replay_run(const tv_replay_desc* desc);

#endif
