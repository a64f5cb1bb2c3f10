#include "cli_loop.h"

#include "log.h"
#include "render.h"

#include <string.h>

void tv_loop_args(tv_loop_opts* o, tv_arg rows[TV_LOOP_ARG_COUNT])
{
    const tv_arg r[TV_LOOP_ARG_COUNT] = {
        TV_ARG_METHOD(&o->method),
        {"predictor", TV_ARG_STRING, &o->predictor, "P", "cv, ca or kalman (default cv)"},
        {"policy", TV_ARG_STRING, &o->policy, "P", "viewcell sizing: adaptive or fixed (default adaptive)"},
        {"delta", TV_ARG_FLOAT, &o->delta, "M", "fixed policy: viewcell radius (default 0.10)"},
        {"fov-pvs", TV_ARG_FLOAT, &o->fov_pvs, "DEG", "fixed policy: PVS FOV, square frustum (default 90)"},
        {"quantile", TV_ARG_FLOAT, &o->quantile, "Q", "adaptive policy: error quantile (default 0.99)"},
        {"head-acc", TV_ARG_FLOAT, &o->head_acc, "M/S2", "adaptive policy: physical bound's head acceleration (default 3)"},
        {"head-ang-acc", TV_ARG_FLOAT, &o->head_ang_acc, "DEG/S2",
         "adaptive policy: its angular acceleration (default 2100)"},
        {"latency-ms", TV_ARG_FLOAT, &o->latency_ms, "MS", "fixed latency model: request to use (default 50)"},
        {"fov", TV_ARG_FLOAT, &o->fov, "DEG", "per-eye horizontal FOV (default 60, the paper's target)"},
        {"ipd", TV_ARG_FLOAT, &o->ipd, "M", "inter-pupillary distance (default 0.063)"},
        TV_ARG_PVS_RES("pvs-res", o->pvs_res),
        TV_ARG_K(&o->k),
        TV_ARG_K_DEEP(&o->k_deep),
        TV_ARG_K_REGIONS(&o->k_regions),
        TV_ARG_KBUFFER_LAYOUT(&o->kb_layout),
        TV_ARG_SAMPLES(&o->samples),
    };
    memcpy(rows, r, sizeof r);
}

bool tv_loop_validate(const tv_loop_opts* o)
{
    return tv_arg_kbuffer_layout(o->kb_layout) >= 0 && tv_arg_k(o->k, o->k_deep, o->k_regions) &&
           tv_arg_require("samples", o->samples, o->samples >= 1, ">= 1") &&
           tv_arg_require("fov", o->fov, o->fov > 1.0f && o->fov < 170.0f, "in (1, 170) degrees") &&
           tv_arg_require("ipd", o->ipd, o->ipd >= 0.0f && o->ipd <= 1.0f, "in [0, 1] m") &&
           tv_arg_require("delta", o->delta, o->delta >= 0.0f, ">= 0") &&
           tv_arg_require("fov-pvs", o->fov_pvs, o->fov_pvs == 0.0f || (o->fov_pvs >= o->fov && o->fov_pvs < 179.0f),
                          "at least --fov and below 179 degrees") &&
           tv_arg_require("quantile", o->quantile, o->quantile > 0.0f && o->quantile <= 1.0f, "in (0, 1]") &&
           tv_arg_require("head-acc", o->head_acc, o->head_acc >= 0.0f, ">= 0 (0: the default)") &&
           tv_arg_require("head-ang-acc", o->head_ang_acc, o->head_ang_acc >= 0.0f, ">= 0 (0: the default)") &&
           /* a fixed latency beyond 10 s is a typo, not a model of any headset */
           tv_arg_require("latency-ms", o->latency_ms, o->latency_ms >= 0.0f && o->latency_ms <= 10000.0f,
                          "in [0, 10000] ms");
}

bool tv_loop_fill(const tv_loop_opts* o, float aspect, pvs_method_desc* method, pred_predictor_desc* predictor,
                  pred_viewcell_desc* viewcell)
{
    if (!pvs_method_from_name(o->method, &method->kind)) {
        tv_log(TV_LOG_ERROR, "--method: unknown method '%s' (tr, gt, sas, frompoint, q3vis)", o->method);
        return false;
    }
    if (!pred_kind_from_name(o->predictor, &predictor->kind)) {
        tv_log(TV_LOG_ERROR, "--predictor: unknown predictor '%s' (cv, ca, kalman)", o->predictor);
        return false;
    }
    if (strcmp(o->policy, "adaptive") != 0 && strcmp(o->policy, "fixed") != 0) {
        tv_log(TV_LOG_ERROR, "--policy: expected adaptive or fixed, got '%s'", o->policy);
        return false;
    }
    /* tr's frustum is square (the viewcell's PVS FOV on both axes): a square image by default */
    method->tr.width = o->pvs_res[0] ? o->pvs_res[0] : 512;
    method->tr.height = o->pvs_res[1] ? o->pvs_res[1] : 512;
    method->tr.k = (uint32_t)o->k;
    method->tr.k_deep = (uint32_t)o->k_deep;
    method->tr.k_regions = (uint32_t)o->k_regions;
    method->tr.kbuffer_layout = (pvs_kbuffer_layout)tv_arg_kbuffer_layout(o->kb_layout);
    method->gt_samples = (uint32_t)o->samples;
    viewcell->policy = strcmp(o->policy, "fixed") == 0 ? PRED_POLICY_FIXED : PRED_POLICY_ADAPTIVE;
    viewcell->fixed_delta_m = o->delta;
    viewcell->fixed_fov_pvs_deg = o->fov_pvs;
    viewcell->quantile = o->quantile;
    viewcell->head_acc_mps2 = o->head_acc;
    viewcell->head_ang_acc_dps2 = o->head_ang_acc;
    viewcell->ipd_m = o->ipd;
    viewcell->display_fov_h_deg = o->fov;
    viewcell->display_fov_v_deg = rnd_fov_y_from_x(o->fov, aspect);
    return true;
}
