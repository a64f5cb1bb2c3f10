/* cli_loop.h - the options `trimvr replay` and `trimvr demo` share: the
 * predicted-viewcell loop's method, predictor, viewcell policy and eyes, as
 * one block of option rows, one validation and one mapping onto the descs. */
#ifndef TRIMVR_APP_CLI_LOOP_H
#define TRIMVR_APP_CLI_LOOP_H

#include "args.h"
#include "method.h"
#include "predictor.h"
#include "viewcell.h"

#include <stdbool.h>

typedef struct tv_loop_opts {
    const char *method, *predictor, *policy, *kb_layout;
    unsigned pvs_res[2]; /* 0x0: 512x512 */
    float fov, ipd, delta, fov_pvs, quantile, head_acc, head_ang_acc, latency_ms;
    int k, k_deep, k_regions, samples;
} tv_loop_opts;

#define TV_LOOP_OPTS_DEFAULT                                                                                     \
    {.method = "tr", .predictor = "cv", .policy = "adaptive", .fov = 60.0f, .ipd = 0.063f, .delta = 0.10f,     \
     .quantile = 0.99f, .latency_ms = 50.0f, .k = TV_ARGS_DEFAULT_K, .samples = TV_ARGS_DEFAULT_SAMPLES}

/* The rows of those options, written to rows[0..TV_LOOP_ARG_COUNT). */
#define TV_LOOP_ARG_COUNT 17
void tv_loop_args(tv_loop_opts* o, tv_arg rows[TV_LOOP_ARG_COUNT]);

/* False after a one-line error naming the first option out of range. */
bool tv_loop_validate(const tv_loop_opts* o);

/* Maps the options onto the descs (eye images of the given aspect). False
 * after a one-line error when a method, predictor or policy name is unknown. */
bool tv_loop_fill(const tv_loop_opts* o, float aspect, pvs_method_desc* method, pred_predictor_desc* predictor,
                  pred_viewcell_desc* viewcell);

#endif
