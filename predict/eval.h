/* eval.h - offline prediction-error evaluation of a path (trimvr predict-eval).
 *
 * Replays `path` through a simulated HMD into a predictor; at every display
 * refresh t_f it predicts the head at t_f + h for each horizon h and records
 * the error against the noise-free path at that time (position metres,
 * rotation degrees). Predictions whose target lies past the path's end are
 * skipped. */
#ifndef TRIMVR_PRED_EVAL_H
#define TRIMVR_PRED_EVAL_H

#include "error_tracker.h"
#include "hmd.h"
#include "predictor.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pred_eval_desc {
    const pred_path* path; /* required */
    hmd_desc hmd;
    pred_predictor_desc predictor;
    pred_error_tracker_desc horizons; /* zero: 10..100 ms; its window is ignored (all errors kept) */
} pred_eval_desc;

typedef struct pred_eval_result {
    int horizon_count;
    double horizons_s[PRED_MAX_HORIZONS];
    pred_error_stats pos[PRED_MAX_HORIZONS]; /* metres */
    pred_error_stats rot[PRED_MAX_HORIZONS]; /* degrees */
    uint64_t samples, dropped_samples, frames;
} pred_eval_result;

/* False with a one-line message on invalid horizons or out of memory. */
bool pred_eval_run(const pred_eval_desc* desc, pred_eval_result* out, char* err, size_t err_size);

/* The markdown error table of docs/prediction.md: its header, then one row
 * per horizon of a result (millimetres and degrees). */
void pred_eval_print_header(FILE* f);
void pred_eval_print_rows(FILE* f, const char* path_name, pred_kind kind, const pred_eval_result* r);

#ifdef __cplusplus
}
#endif

#endif
