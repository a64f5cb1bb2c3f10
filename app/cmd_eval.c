/* trimvr eval: PVS quality against sampled ground truth, measured the way the
 * Trim Regions paper does (section 6; docs/evaluation.md), for one viewcell
 * or for viewcells along a path. Writes DIR/eval.json and pictures in the
 * paper's Figure 1 colours. */
#include "app_scene.h"
#include "args.h"
#include "cli_viewcell.h"
#include "interrupt.h"
#include "commands.h"
#include "eval_common.h"
#include "eval_images.h"
#include "explain.h"
#include "gt_cache.h"
#include "log.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct eval_opts {
    const char *scene, *path, *out, *method, *gt_cache, *kb_layout;
    float pos[3], dir[3], up[3];
    float delta, fov, fov_pvs;
    int every, samples, k, k_deep, k_regions, max_cells, max_layers;
    unsigned res[2], pvs_res[2];
    bool explain;
} eval_opts;

static bool write_json(const eval_opts* o, const char* scene_name, const tv_eval_cell* cells, int n, bool interrupted,
                       const tv_explain* ex)
{
    char name[4200];
    snprintf(name, sizeof name, "%s/eval.json", o->out);
    FILE* f = fopen(name, "w");
    if (!f) {
        tv_log(TV_LOG_ERROR, "%s: cannot write", name);
        return false;
    }
    tv_eval_cell mean = tv_eval_mean(cells, n);
    fprintf(f, "{\n  \"scene\": \"%s\", \"method\": \"%s\", \"viewcell_count\": %d, \"interrupted\": %s,\n",
            scene_name, o->method, n, interrupted ? "true" : "false");
    fprintf(f, "  \"delta_m\": %.4f, \"fov_deg\": %.2f, \"fov_pvs_deg\": %.2f, \"samples\": %d,\n", o->delta, o->fov,
            o->fov_pvs, cells[0].m.samples);
    fprintf(f, "  \"sample_res\": [%u, %u], \"pvs_res\": [%u, %u],\n", o->res[0], o->res[1], o->pvs_res[0],
            o->pvs_res[1]);
    tv_eval_json_metrics(f, &mean, "  ");
    if (ex) {
        fprintf(f, ",\n");
        tv_explain_json(f, ex, "  ");
    }
    fprintf(f, ",\n  \"viewcells\": [\n");
    for (int i = 0; i < n; i++) {
        const pred_viewcell* vc = &cells[i].vc;
        fprintf(f, "    {\"v0\": [%.4f, %.4f, %.4f], \"forward\": [%.4f, %.4f, %.4f],\n", vc->v0[0], vc->v0[1],
                vc->v0[2], vc->forward[0], vc->forward[1], vc->forward[2]);
        tv_eval_json_metrics(f, &cells[i], "     ");
        fprintf(f, "}%s\n", i + 1 < n ? "," : "");
    }
    fprintf(f, "  ]\n}\n");
    if (fclose(f) != 0) {
        tv_log(TV_LOG_ERROR, "%s: write failed", name);
        return false;
    }
    return true;
}

/* The viewcells: one from --pos/--dir, or one every `every` display frames
 * (90 Hz) along --path. */
static int make_cells(const eval_opts* o, tv_eval_cell** out, char* scene_spec, size_t spec_size)
{
    if (!o->path) {
        *out = calloc(1, sizeof **out);
        if (!*out || !tv_viewcell_make(o->pos, o->dir, isnan(o->up[0]) ? NULL : o->up, o->delta, o->fov, o->fov_pvs,
                                        &(*out)->vc)) {
            tv_log(TV_LOG_ERROR, "--dir must be non-zero (components below 1e19) and --up not parallel to it");
            free(*out);
            *out = NULL;
            return -1;
        }
        return 1;
    }
    char err[512];
    int n = tv_eval_path_cells(o->path, o->every, o->max_cells, o->delta, o->fov, o->fov_pvs, out, scene_spec,
                               spec_size, err, sizeof err);
    if (n < 0)
        tv_log(TV_LOG_ERROR, "%s", err);
    return n;
}

static tv_args_result parse(eval_opts* o, int argc, char** argv)
{
    const tv_arg args[] = {
        {"scene", TV_ARG_STRING, &o->scene, "S", "scene (default: the path's '# scene:')"},
        {"pos", TV_ARG_VEC3, o->pos, "X,Y,Z", "one viewcell at this centre (or use --path)"},
        {"dir", TV_ARG_VEC3, o->dir, "X,Y,Z", "its view direction (default 0,0,-1)"},
        {"up", TV_ARG_VEC3, o->up, "X,Y,Z", "its up direction, made perpendicular to --dir (default +Y)"},
        {"path", TV_ARG_STRING, &o->path, "FILE", "viewcells at the head poses of this path"},
        {"every", TV_ARG_INT, &o->every, "N", "with --path: one viewcell every N display frames at 90 Hz (default 90)"},
        {"max-cells", TV_ARG_INT, &o->max_cells, "N", "with --path: at most N viewcells (default all)"},
        {"delta", TV_ARG_FLOAT, &o->delta, "M", "viewcell radius (default 0.1; tr: at most 31.7 m x tan(fov-pvs / 2))"},
        {"fov", TV_ARG_FLOAT, &o->fov, "DEG", "display FOV, horizontal (default 60)"},
        TV_ARG_FOV_PVS(&o->fov_pvs),
        TV_ARG_SAMPLES(&o->samples),
        TV_ARG_GT_CACHE(&o->gt_cache),
        {"res", TV_ARG_RES, o->res, "WxH", "sample-view resolution (default 640x360)"},
        TV_ARG_PVS_RES("pvs-res", o->pvs_res),
        TV_ARG_K(&o->k),
        TV_ARG_K_DEEP(&o->k_deep),
        TV_ARG_K_REGIONS(&o->k_regions),
        TV_ARG_KBUFFER_LAYOUT(&o->kb_layout),
        TV_ARG_MAX_LAYERS(&o->max_layers),
        TV_ARG_METHOD(&o->method),
        {"out", TV_ARG_STRING, &o->out, "DIR", "output folder (default out/eval)"},
        {"explain", TV_ARG_FLAG, &o->explain, NULL, "tr: attribute every false positive to the rule that output it"},
    };
    const char* summary =
        "Measures a PVS method against sampled ground truth (the paper's section 6): PVS and GT size, FP and\n"
        "FN rates, false-negative pixels per view (FNG), PSNR of PVS renders against full renders, timings.\n"
        "Writes DIR/eval.json, DIR/fig1_overview.png and DIR/fig1_eye.png (visible shaded, false positives\n"
        "blue, rest grey) and DIR/fn_worst.png (false-negative pixels red in the worst view). With --explain\n"
        "it prints and records which PVS rule output each false positive and draws them in the rule's colour\n"
        "(DIR/explain_overview.png, DIR/explain_eye.png; docs/evaluation.md). Ctrl-C stops after the current\n"
        "viewcell; eval.json then covers the finished ones.";
    return tv_args_parse("eval", summary, args, (int)(sizeof args / sizeof args[0]), argc, argv);
}

static bool validate(const eval_opts* o, pvs_method_desc* md)
{
    int layout = tv_arg_kbuffer_layout(o->kb_layout);
    *md = (pvs_method_desc){.tr = {.width = o->pvs_res[0], .height = o->pvs_res[1], .k = (uint32_t)o->k,
                                   .k_deep = (uint32_t)o->k_deep, .k_regions = (uint32_t)o->k_regions, .kbuffer_layout = (pvs_kbuffer_layout)layout,
                                   .max_layers = tv_arg_max_layers(o->max_layers),
                                   .explain = o->explain},
                            .width = o->res[0], .height = o->res[1], .gt_samples = (uint32_t)o->samples};
    if (layout < 0 || !tv_arg_k(o->k, o->k_deep, o->k_regions) ||
        !tv_arg_require("max-layers", o->max_layers, o->max_layers >= -1, ">= -1") ||
        !tv_arg_viewcell(o->delta, o->fov, o->fov_pvs) || !tv_arg_gt_cache(o->gt_cache))
        return false;
    if ((!o->path && isnan(o->pos[0])) || o->every < 1 || o->samples < 1 ||
        !pvs_method_from_name(o->method, &md->kind)) {
        tv_log(TV_LOG_ERROR, "need --pos or --path, a known --method, --every >= 1 and "
               "--samples >= 1 (see trimvr eval --help)");
        return false;
    }
    if (o->explain && md->kind != PVS_METHOD_TR) {
        tv_log(TV_LOG_ERROR, "--explain: only --method tr records the rules behind its output (not %s)", o->method);
        return false;
    }
    return true;
}

static void print_cell(int i, int n, const pvs_eval_result* m)
{
    fprintf(stderr,
            "viewcell %d/%d: PVS %u (%.2f%%), GT %u (%.0f%% complete), FP %.2f, FN %.4f, FNG %.1f px, "
            "PSNR min %.1f dB\n",
            i + 1, n, m->pvs_tris, 100.0 * m->pvs_fraction, m->gt_tris, 100.0 * m->gt_completeness, m->fp_rate,
            m->fn_rate, m->fng_pixels_mean, m->psnr_min_db);
}

/* Evaluates the cells in turn (a signal stops the run between two) and
 * writes eval.json and the pictures. Returns the exit status. */
static int run(const eval_opts* o, const pvs_method_desc* md, tv_app_scene* s, const char* spec,
               tv_eval_cell* cells, int n)
{
    char err[512] = "";
    int status = 0;
    uint32_t tris = s->scene.triangle_count;
    pvs_method* m = pvs_method_create(md, s->ctx, &s->scene, s->gpu, err, sizeof err);
    uint8_t* mask = calloc(tris ? tris : 1, 1);
    uint8_t* gt = calloc(tris ? tris : 1, 1);
    tv_eval_images worst = {0};
    tv_explain ex = {0};
    char scene_id[1024] = "";
    if (o->gt_cache)
        pvs_gt_scene_id(&s->scene, spec, rnd_device_name(s->ctx), scene_id, sizeof scene_id);
    pvs_eval_desc ed = {.samples = (uint32_t)o->samples, .width = o->res[0], .height = o->res[1],
                        .pose = tv_app_scene_pose, .pose_user = s, .gt_cache_dir = o->gt_cache,
                        .gt_cache_scene = scene_id};
    if (!m || !mask || !gt) {
        tv_log(TV_LOG_ERROR, "%s", m ? "out of memory" : err);
        status = 1;
    }
    int done = 0;
    for (; done < n && status == 0 && !tv_interrupted(); done++) {
        if (!tv_eval_cell_run(m, s->ctx, &s->scene, s->gpu, &ed, o->fov, &cells[done], mask, gt, err, sizeof err)) {
            tv_log(TV_LOG_ERROR, "viewcell %d: %s", done, err);
            status = 1;
        } else if (!tv_eval_images_keep_worst(&worst, &cells[done].vc, &cells[done].m, mask, gt, tris) ||
                   (o->explain && !tv_explain_add(&ex, &cells[done].vc, pvs_method_reasons(m), mask, gt, tris))) {
            tv_log(TV_LOG_ERROR, "out of memory");
            status = 1;
        } else {
            print_cell(done, n, &cells[done].m);
        }
    }
    int sig = tv_interrupted();
    if (status == 0 && done == 0) {
        tv_log(TV_LOG_ERROR, "interrupted by signal %d before the first viewcell finished", sig);
        status = tv_interrupt_status(sig);
    }
    err[0] = '\0';
    if (status == 0 && (!write_json(o, spec, cells, done, sig != 0, o->explain ? &ex : NULL) ||
                        !tv_eval_images_write(&worst, s->ctx, s->gpu, &s->scene, &ed, o->out, err, sizeof err) ||
                        (o->explain && !tv_explain_write_pictures(&ex, s->ctx, s->gpu, &s->scene, o->res[0],
                                                                  o->res[1], o->out, err, sizeof err)))) {
        if (err[0])
            tv_log(TV_LOG_ERROR, "%s", err);
        status = 1;
    }
    if (status == 0 && sig) {
        tv_log(TV_LOG_ERROR, "interrupted by signal %d after %d of %d viewcell(s): %s/eval.json covers them", sig,
               done, n, o->out);
        status = tv_interrupt_status(sig);
    } else if (status == 0) {
        if (o->explain)
            tv_explain_print(stdout, &ex, spec, o->delta);
        printf("trimvr eval: %d viewcell(s) of %s with %s -> %s/eval.json\n", n, spec, o->method, o->out);
    }
    tv_eval_images_free(&worst);
    tv_explain_free(&ex);
    free(mask);
    free(gt);
    pvs_method_destroy(m);
    return status;
}

int tv_cmd_eval(int argc, char** argv)
{
    eval_opts o = {.out = "out/eval", .method = "tr", .pos = {NAN, NAN, NAN}, .dir = {0, 0, -1},
                   .up = {NAN, NAN, NAN}, .delta = 0.1f,
                   .fov = 60.0f, .fov_pvs = 90.0f, .every = 90, .samples = TV_ARGS_DEFAULT_SAMPLES, .res = {640, 360},
                   .pvs_res = {512, 512}, .k = TV_ARGS_DEFAULT_K,
                   .max_layers = TV_ARGS_DEFAULT_MAX_LAYERS};
    tv_args_result r = parse(&o, argc, argv);
    if (r != TV_ARGS_OK)
        return r == TV_ARGS_HELP ? 0 : 2;
    pvs_method_desc md;
    if (!validate(&o, &md))
        return 2;
    char spec[512] = "";
    if (o.scene)
        snprintf(spec, sizeof spec, "%s", o.scene);
    tv_eval_cell* cells = NULL;
    int n = make_cells(&o, &cells, spec, sizeof spec);
    if (n < 0)
        return 1;
    if (!spec[0]) {
        tv_log(TV_LOG_ERROR, "no scene: pass --scene");
        free(cells);
        return 2;
    }
    tv_interrupt_install(); /* before the scene load and the method's preprocessing, which can take seconds */
    tv_app_scene s;
    if (!tv_app_scene_open_out(spec, o.out, &s)) {
        free(cells);
        return 1;
    }
    int status = run(&o, &md, &s, spec, cells, n);
    free(cells);
    if (!tv_app_scene_close(&s))
        status = 1;
    return status;
}
