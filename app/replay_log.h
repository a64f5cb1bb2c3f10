/* replay_log.h - the replay's outputs: frames.csv (one row per evaluated
 * frame and eye, plus unrendered rows for uncovered frames that were not
 * evaluated; flushed row by row so an interrupted run keeps every finished
 * frame), pvs.csv (one row per PVS taken into use: its viewcell, exactly
 * enough to compute it again with `trimvr pvs`), the running summary,
 * summary.json and the end-of-run table. Column meanings: docs/replay.md. */
#ifndef TRIMVR_APP_REPLAY_LOG_H
#define TRIMVR_APP_REPLAY_LOG_H

#include "pose.h"
#include "viewcell.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

typedef struct tv_frame_row {
    uint64_t frame;
    double t;                /* display time of the frame, s */
    int eye;                 /* 0 left, 1 right */
    pred_pose pose;          /* late-latched eye pose used to render */
    double pose_age_ms;      /* submit time minus the latched sensor sample's time */
    pred_pose predicted;     /* this eye as predicted when the current PVS was requested */
    double pred_err_pos_m, pred_err_rot_deg;
    double pred_horizon_ms;  /* frame time minus that request time */
    double delta_m, fov_pvs_deg;
    uint32_t pvs_id;
    double pvs_age_ms;       /* frame time minus the PVS's request time */
    bool inside;             /* eye covered by the PVS's viewcell */
    const char* miss_reason; /* "covered", "axial", "radial", "frustum" */
    uint32_t pvs_tris;
    double pvs_fraction;
    double psnr_db;          /* +inf when identical */
    uint64_t fn_pixels;      /* pixels whose full-render triangle is not in the PVS */
    uint64_t diff_pixels;    /* pixels whose colour differs at all */
    double pvs_compute_ms;   /* wall clock of the PVS on the worker */
    double render_pvs_ms, render_full_ms;
    double ssim;             /* mean SSIM, PVS render against full render (eval/ssim.h); NaN: image under 11 px */
    bool rendered;           /* false: a coverage-only row, the image columns (and ssim) are empty */
    int pvs_frusta;          /* frusta of the PVS's viewcell (1, or 6 for every direction) */
    bool whole_scene;        /* drawn with every triangle (tv_pvs_pipeline_whole_scene) */
    double static_pvs_fraction;  /* the PVS's static triangles over the scene's (summary only) */
    double dynamic_pvs_fraction; /* the PVS's moving triangles over the scene's; 0 without movers */
    uint64_t dynamic_fn_pixels;  /* fn_pixels on moving triangles */
} tv_frame_row;

typedef struct tv_replay_log tv_replay_log;

/* One PVS taken into use. */
typedef struct tv_pvs_row {
    uint32_t id;               /* the request's sequence number (frames.csv pvs_id) */
    double t_request, t_available;
    const pred_viewcell* vc;   /* what it was computed for */
    uint32_t tris;
    double compute_ms;
} tv_pvs_row;

/* Creates DIR/frames.csv and DIR/pvs.csv with their headers. NULL (message
 * in err) on failure. */
tv_replay_log* tv_replay_log_open(const char* dir, char* err, size_t err_size);

/* Appends and flushes one row; accumulates the summary (rendered rows
 * only). False on a write error. */
bool tv_replay_log_row(tv_replay_log* log, const tv_frame_row* row);

/* Per display frame: whether both eyes were covered by the viewcell (or
 * the frame drew the whole scene), and what it drew with: the PVS's share
 * of the scene (1 for the whole scene) and, when drawn from a computed PVS,
 * its viewcell's delta and FOV (the summary's means are over display frames). */
void tv_replay_log_coverage(tv_replay_log* log, bool covered, bool whole_scene, double pvs_fraction, double delta_m,
                            double fov_pvs_deg);

/* Per-PVS accounting and its pvs.csv row, flushed (once per delivered PVS;
 * a whole-scene one is only counted, its listing time is no PVS compute
 * time). False on a write error. */
bool tv_replay_log_pvs(tv_replay_log* log, const tv_pvs_row* row);

/* Per display frame (not only evaluated ones): prediction error of the head
 * at the frame time relative to the PVS request's prediction, for the p99s. */
void tv_replay_log_prediction(tv_replay_log* log, double pos_err_m, double rot_err_deg);

typedef struct tv_replay_meta {
    const char* scene;
    const char* path;
    const char* method;
    const char* predictor;
    const char* policy;
    const char* latency_model;
    uint32_t scene_tris;
    uint32_t dynamic_tris; /* the scene's moving triangles */
    unsigned width, height;
    double eye_fov_deg;
    uint64_t display_frames;
    uint32_t probe_requests; /* measured latency: PVSs requested as probes (pvs_pipeline.h) */
    double wall_s;
    bool interrupted; /* stopped by a signal: frames < the frames asked for */
} tv_replay_meta;

/* Writes DIR/summary.json and prints the one-screen table to `table`
 * (may be NULL). Closes frames.csv and pvs.csv and frees the log. */
bool tv_replay_log_finish(tv_replay_log* log, const char* dir, const tv_replay_meta* meta, FILE* table,
                          char* err, size_t err_size);

/* Summary values the caller may want after the run (valid until finish). */
double tv_replay_log_worst_psnr(const tv_replay_log* log);

#endif
