/* trimvr bench: every PVS method on the same scenes and viewcells at several
 * Δ, measured against sampled ground truth (issues 3 and 6): the quantities
 * of the paper's Figures 13-16 and Tables 2-3 in one table per scene. */
#define _POSIX_C_SOURCE 200809L
#include "app_scene.h"
#include "args.h"
#include "auto_place.h"
#include "bench_report.h"
#include "cli_viewcell.h"
#include "clock.h"
#include "commands.h"
#include "fs.h"
#include "stats.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define MAX_LIST 32
#define DEFAULT_SCENES "builtin:city,sponza,oa:oasago2,oa:oa_dm5,oa:czest2ctf,oa:ctf_inyard,oa:oacmpdm9,oa:pul1ctf"

typedef struct bench_opts {
    const char *scenes, *deltas, *methods, *pos, *out;
    float dir[3], fov, fov_pvs;
    int every, max_cells, samples, k;
    unsigned res[2], pvs_res[2];
} bench_opts;

/* Splits a `sep`-separated list (copied into buf) into at most MAX_LIST items. */
static int split(const char* list, char* buf, size_t size, char** items, char sep)
{
    snprintf(buf, size, "%s", list);
    int n = 0;
    for (char *save = NULL, *t = strtok_r(buf, (char[]){sep, 0}, &save); t && n < MAX_LIST;
         t = strtok_r(NULL, (char[]){sep, 0}, &save))
        items[n++] = t;
    return n;
}

typedef struct bench_run {
    const bench_opts* o;
    float deltas[MAX_LIST];
    int ndelta;
    pvs_method_kind methods[PVS_METHOD_COUNT];
    int nmethod;
    float pos[3 * MAX_LIST]; /* --pos centres */
    int npos;
    tv_bench_row* rows;
    int nrows, cap;
    double t0;
    char device[256];
    bool cells_printed; /* this scene's viewcells were listed */
    char placed_spec[256]; /* the scene whose viewcells were placed automatically */
    float placed_pos[3 * MAX_LIST], placed_dir[3 * MAX_LIST];
    int nplaced;
} bench_run;

/* The viewcells of one scene at radius delta: --pos if given, else the
 * scene's bundled walk (builtin:NAME and sponza: paths/NAME-walk.csv), else
 * placed automatically (app/auto_place.h: q3 vis floor points of an
 * OpenArena level, the walkable-floor rule elsewhere), once per scene. -1
 * with a message when it has none. */
static int scene_cells(bench_run* b, const char* spec, const tv_app_scene* s, float delta, tv_eval_cell** out)
{
    const bench_opts* o = b->o;
    char err[512], walk[4300];
    if (b->npos == 0 && tv_bundled_walk(spec, walk, sizeof walk)) {
        char scene_spec[8] = "-"; /* non-empty: the path's own scene line is not wanted */
        int n = tv_eval_path_cells(walk, o->every, o->max_cells, delta, o->fov, o->fov_pvs, out, scene_spec,
                                   sizeof scene_spec, err, sizeof err);
        if (n < 0)
            fprintf(stderr, "trimvr bench: error: %s: %s\n", spec, err);
        return n;
    }
    if (b->npos == 0 && strcmp(b->placed_spec, spec) != 0) {
        int want = o->max_cells > 0 && o->max_cells < MAX_LIST ? o->max_cells : MAX_LIST;
        const char* rule = "";
        b->nplaced = tv_auto_viewcells(spec, &s->scene, want, b->placed_pos, b->placed_dir, &rule, err, sizeof err);
        snprintf(b->placed_spec, sizeof b->placed_spec, "%s", spec);
        if (b->nplaced < 0)
            fprintf(stderr, "trimvr bench: error: %s: %s\n", spec, err);
        else
            fprintf(stderr, "bench %s: no bundled walk: %d viewcells placed by the %s rule (docs/bench.md)\n", spec,
                    b->nplaced, rule);
    }
    int n = b->npos > 0 ? b->npos : b->nplaced;
    const float* pos = b->npos > 0 ? b->pos : b->placed_pos;
    *out = n > 0 ? calloc((size_t)n, sizeof **out) : NULL;
    for (int i = 0; *out && i < n; i++) {
        const float* dir = b->npos > 0 ? o->dir : &b->placed_dir[3 * i];
        tv_viewcell_make(&pos[3 * i], dir, delta, o->fov, o->fov_pvs, &(*out)[i].vc);
        for (int k = 0; k < 3; k++)
            (*out)[i].motion[k] = 2.0 * delta * (*out)[i].vc.forward[k];
    }
    return *out ? n : -1;
}

/* Median wall clock of full-scene draws at the PVS resolution and FOV from
 * the viewcell centres: the render the "PVS time <= 10x a full
 * render at equal resolution" compares with. */
static double full_render_ms(const bench_opts* o, const tv_app_scene* s, const tv_eval_cell* cells, int n)
{
    char err[512];
    rnd_target* t = rnd_target_create(s->ctx, o->pvs_res[0], o->pvs_res[1], err, sizeof err);
    double ms[3 * MAX_LIST];
    int m = 0;
    float aspect = (float)o->pvs_res[0] / (float)o->pvs_res[1];
    for (int i = 0; t && i < n && i < MAX_LIST; i++) {
        pvs_request req = tv_eval_request(&cells[i], o->fov);
        rnd_camera cam = {.fov_y_deg = aspect >= 1.0f ? rnd_fov_y_from_x(o->fov_pvs, aspect) : o->fov_pvs,
                          .near_m = 0.05f, .far_m = 500.0f};
        for (int k = 0; k < 3; k++)
            cam.position[k] = cells[i].vc.v0[k];
        for (int k = 0; k < 4; k++)
            cam.orientation[k] = (float)req.current.q[k];
        for (int r = 0; r < 3; r++) {
            rnd_draw_stats st;
            if (rnd_draw(s->ctx, t, s->gpu, &cam, NULL, 0, &st))
                ms[m++] = st.cpu_ms;
        }
    }
    if (t)
        rnd_target_destroy(s->ctx, t);
    return m ? tv_percentile(ms, (size_t)m, 50.0) : NAN;
}

static const char* elapsed(const bench_run* b, char* buf, size_t size)
{
    int s = (int)((tv_now_ms() - b->t0) / 1000.0);
    snprintf(buf, size, "%dm%02ds", s / 60, s % 60);
    return buf;
}

/* One method at every delta on one scene: rows appended in ascending delta. */
static bool bench_method(bench_run* b, const char* spec, const tv_app_scene* s, pvs_method_kind kind,
                         uint8_t* mask, uint8_t* gt)
{
    const bench_opts* o = b->o;
    char err[512], json[4200], t[32];
    tv_eval_pvs_json_of(spec, json, sizeof json);
    pvs_method_desc md = {.kind = kind, .tr = {.width = o->pvs_res[0], .height = o->pvs_res[1], .k = (uint32_t)o->k},
                          .width = o->res[0], .height = o->res[1], .gt_samples = (uint32_t)o->samples,
                          .q3vis_file = kind == PVS_METHOD_Q3VIS ? json : NULL};
    pvs_method* m = pvs_method_create(&md, s->ctx, &s->scene, s->gpu, err, sizeof err);
    if (!m) {
        fprintf(stderr, "trimvr bench: error: %s: %s\n", spec, err);
        return false;
    }
    pvs_eval_desc ed = {.samples = (uint32_t)o->samples, .width = o->res[0], .height = o->res[1]};
    bool ok = true, warm = false;
    for (int d = 0; d < b->ndelta && ok; d++) {
        tv_eval_cell* cells = NULL;
        int n = scene_cells(b, spec, s, b->deltas[d], &cells);
        ok = n > 0;
        for (int i = 0; ok && !b->cells_printed && i < n; i++) /* once per scene, to repeat with --pos */
            fprintf(stderr, "bench %s: viewcell %d at %.2f,%.2f,%.2f looking %.2f,%.2f,%.2f\n", spec, i,
                    cells[i].vc.v0[0], cells[i].vc.v0[1], cells[i].vc.v0[2], cells[i].vc.forward[0],
                    cells[i].vc.forward[1], cells[i].vc.forward[2]);
        b->cells_printed = b->cells_printed || ok;
        if (ok && !warm) { /* the first PVS builds what is cached per scene (octree, pipelines) */
            pvs_request req = tv_eval_request(&cells[0], o->fov);
            uint32_t *ids = NULL, count;
            ok = pvs_method_compute(m, &req, &ids, &count, NULL, err, sizeof err);
            free(ids);
            warm = true;
        }
        for (int i = 0; ok && i < n; i++)
            ok = tv_eval_cell_run(m, s->ctx, &s->scene, s->gpu, &ed, o->fov, &cells[i], mask, gt, err, sizeof err);
        if (!ok && n > 0)
            fprintf(stderr, "trimvr bench: error: %s, %s, delta %.2f: %s\n", spec, pvs_method_name(kind),
                    b->deltas[d], err);
        if (ok && b->nrows == b->cap) {
            b->cap = b->cap ? 2 * b->cap : 64;
            tv_bench_row* grown = realloc(b->rows, (size_t)b->cap * sizeof *grown);
            ok = grown != NULL;
            if (ok)
                b->rows = grown;
        }
        if (ok) {
            tv_bench_row* r = &b->rows[b->nrows++];
            memset(r, 0, sizeof *r);
            snprintf(r->scene, sizeof r->scene, "%s", spec);
            r->method = kind;
            r->delta = b->deltas[d];
            r->cells = n;
            r->mean = tv_eval_mean(cells, n);
            r->views = cells[0].st.views;
            r->full_pvsres_ms = full_render_ms(o, s, cells, n);
            r->psnr_worst_cell_db = INFINITY;
            for (int i = 0; i < n; i++) {
                r->fng_fraction_worst_cell = fmax(r->fng_fraction_worst_cell, cells[i].m.fng_fraction_mean);
                r->psnr_worst_cell_db = fmin(r->psnr_worst_cell_db, cells[i].m.psnr_mean_db);
            }
            const pvs_eval_result* x = &r->mean.m;
            fprintf(stderr, "bench %s: %-9s delta %4.2f: %d cells, PVS %.2f%% (GT %.2f%%), FP %.3f, FN %.4f, "
                            "FNG %.1f px, PSNR %.1f dB, PVS %.0f ms, GT %.0f ms [%s]\n",
                    spec, pvs_method_name(kind), r->delta, n, 100.0 * x->pvs_fraction, 100.0 * x->gt_fraction,
                    x->fp_rate, x->fn_rate, x->fng_pixels_mean, x->psnr_mean_db, r->mean.pvs_ms, x->gt_ms,
                    elapsed(b, t, sizeof t));
        }
        free(cells);
    }
    pvs_method_destroy(m);
    return ok;
}

/* Every method on one scene; a scene file that is absent is skipped. */
static bool bench_scene(bench_run* b, const char* spec)
{
    char file[4200];
    tv_resolve_scene_spec(spec, file, sizeof file);
    if (strncmp(file, "builtin:", 8) != 0 && access(file, R_OK) != 0) {
        fprintf(stderr, "bench: skip %s: %s not found\n", spec, file);
        return true;
    }
    tv_app_scene s;
    b->cells_printed = false;
    if (!tv_app_scene_open("bench", spec, &s))
        return false;
    snprintf(b->device, sizeof b->device, "%s", rnd_device_name(s.ctx));
    uint32_t tris = s.scene.triangle_count;
    uint8_t* mask = calloc(tris + 1, 1);
    uint8_t* gt = calloc(tris + 1, 1);
    bool ok = mask && gt;
    for (int i = 0; ok && i < b->nmethod; i++)
        if (b->methods[i] != PVS_METHOD_Q3VIS || strncmp(spec, "oa:", 3) == 0)
            ok = bench_method(b, spec, &s, b->methods[i], mask, gt);
    free(mask);
    free(gt);
    return tv_app_scene_close("bench", &s) && ok;
}

static bool parse_lists(const bench_opts* o, bench_run* b)
{
    char buf[512], *items[MAX_LIST];
    b->ndelta = split(o->deltas, buf, sizeof buf, items, ',');
    for (int i = 0; i < b->ndelta; i++) {
        char* end;
        b->deltas[i] = strtof(items[i], &end);
        if (*end || !(b->deltas[i] >= 0.0f) || (i > 0 && b->deltas[i] <= b->deltas[i - 1])) {
            fprintf(stderr, "trimvr bench: error: --deltas: expected ascending metres >= 0, got '%s'\n", items[i]);
            return false;
        }
    }
    int n = split(o->methods, buf, sizeof buf, items, ',');
    for (int i = 0; i < n; i++) {
        if (b->nmethod == PVS_METHOD_COUNT || !pvs_method_from_name(items[i], &b->methods[b->nmethod++])) {
            fprintf(stderr, "trimvr bench: error: --methods: unknown or repeated method '%s' (tr, gt, sas, "
                            "frompoint, q3vis)\n", items[i]);
            return false;
        }
    }
    b->npos = o->pos ? split(o->pos, buf, sizeof buf, items, ';') : 0;
    for (int i = 0; i < b->npos; i++) {
        char tail;
        if (sscanf(items[i], "%f,%f,%f%c", &b->pos[3 * i], &b->pos[3 * i + 1], &b->pos[3 * i + 2], &tail) != 3) {
            fprintf(stderr, "trimvr bench: error: --pos: expected X,Y,Z;X,Y,Z..., got '%s'\n", items[i]);
            return false;
        }
    }
    return b->ndelta > 0 && b->nmethod > 0;
}

int tv_cmd_bench(int argc, char** argv)
{
    bench_opts o = {.scenes = DEFAULT_SCENES, .deltas = "0.05,0.1,0.2,0.3", .methods = "tr,sas,frompoint,gt,q3vis",
                    .out = "out/bench", .dir = {0, 0, -1}, .fov = 60.0f, .fov_pvs = 90.0f, .every = 450,
                    .max_cells = 3, .samples = 50, .res = {320, 180}};
    const tv_arg args[] = {
        {"scenes", TV_ARG_STRING, &o.scenes, "S,S..", "scenes (default builtin:city, sponza and the six oa: levels)"},
        {"deltas", TV_ARG_STRING, &o.deltas, "M,M..", "viewcell radii, ascending (default 0.05,0.1,0.2,0.3)"},
        {"methods", TV_ARG_STRING, &o.methods, "M,M..", "methods (default tr,sas,frompoint,gt,q3vis; q3vis on oa: only)"},
        {"path-every", TV_ARG_INT, &o.every, "N", "walk paths: one viewcell every N frames at 90 Hz (default 450)"},
        {"max-cells", TV_ARG_INT, &o.max_cells, "N", "at most N viewcells per scene (default 3)"},
        {"pos", TV_ARG_STRING, &o.pos, "X,Y,Z;..", "viewcells at these centres instead (every scene)"},
        {"dir", TV_ARG_VEC3, o.dir, "X,Y,Z", "with --pos: view direction (default 0,0,-1)"},
        {"samples", TV_ARG_INT, &o.samples, "N", "ground-truth views per viewcell, also gt's (default 50)"},
        {"res", TV_ARG_RES, o.res, "WxH", "ground-truth and id-buffer resolution (default 320x180)"},
        {"pvs-res", TV_ARG_RES, o.pvs_res, "WxH", "tr resolution and full-render timing (default 512x512)"},
        {"k", TV_ARG_INT, &o.k, "N", "tr: k-buffer slots per pixel and kind (default 16)"},
        {"fov", TV_ARG_FLOAT, &o.fov, "DEG", "display FOV, horizontal (default 60)"},
        {"fov-pvs", TV_ARG_FLOAT, &o.fov_pvs, "DEG", "PVS FOV, square frustum (default 90)"},
        {"out", TV_ARG_STRING, &o.out, "DIR", "output folder (default out/bench)"},
    };
    const char* summary =
        "Runs every PVS method on the same viewcells of each scene at each delta and measures it against sampled\n"
        "ground truth: PVS and GT size, FP/FN rates, false-negative pixels, PSNR, and PVS time beside the\n"
        "ground-truth time and a full-scene render at the PVS resolution, in the same run. Viewcells: the\n"
        "scene's bundled walk (paths/NAME-walk.csv), else placed automatically (floor points of OpenArena\n"
        "levels, the walkable-floor rule of docs/scenes.md elsewhere), or --pos. Writes\n"
        "DIR/bench.md, bench.csv, bench.json and fig14-16 PNGs; progress on stderr. See docs/bench.md.";
    tv_args_result r = tv_args_parse("bench", summary, args, (int)(sizeof args / sizeof args[0]), argc, argv);
    if (r != TV_ARGS_OK)
        return r == TV_ARGS_HELP ? 0 : 2;
    if (!o.pvs_res[0])
        o.pvs_res[0] = o.pvs_res[1] = 512;
    bench_run b = {.o = &o, .t0 = tv_now_ms()};
    if (!parse_lists(&o, &b))
        return 2;
    float dir_len = sqrtf(o.dir[0] * o.dir[0] + o.dir[1] * o.dir[1] + o.dir[2] * o.dir[2]);
    if (o.every < 1 || o.samples < 1 || o.k < 0 || o.max_cells < 1 || !(o.fov > 0.0f && o.fov <= o.fov_pvs) ||
        !(o.fov_pvs < 179.0f) || !(dir_len > 0.0f)) {
        fprintf(stderr, "trimvr bench: error: need --path-every, --samples, --max-cells >= 1, --k >= 0 and "
                        "0 < --fov <= --fov-pvs < 179 and a non-zero --dir (see trimvr bench --help)\n");
        return 2;
    }
    if (!tv_mkdirs(o.out)) {
        fprintf(stderr, "trimvr bench: error: %s: cannot create the output folder\n", o.out);
        return 1;
    }
    char buf[1024], *scenes[MAX_LIST];
    int nscene = split(o.scenes, buf, sizeof buf, scenes, ',');
    bool ok = true;
    for (int i = 0; i < nscene && ok; i++)
        ok = bench_scene(&b, scenes[i]);
    char cmd[4096] = "trimvr bench", date[64];
    for (int i = 0; i < argc; i++)
        snprintf(cmd + strlen(cmd), sizeof cmd - strlen(cmd), " %s", argv[i]);
    time_t now = time(NULL);
    strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", gmtime(&now));
    tv_bench_info info = {.command_line = cmd, .date = date, .device = b.device,
                          .res = {o.res[0], o.res[1]}, .pvs_res = {o.pvs_res[0], o.pvs_res[1]},
                          .samples = o.samples, .fov = o.fov, .fov_pvs = o.fov_pvs,
                          .wall_s = (tv_now_ms() - b.t0) / 1000.0};
    char err[4300];
    if (ok && b.nrows == 0) {
        fprintf(stderr, "trimvr bench: error: no scene could be benchmarked\n");
        ok = false;
    }
    if (ok && !tv_bench_write(o.out, &info, b.rows, b.nrows, err, sizeof err)) {
        fprintf(stderr, "trimvr bench: error: %s\n", err);
        ok = false;
    }
    if (ok) {
        tv_bench_plots(o.out, b.rows, b.nrows);
        printf("trimvr bench: %d rows in %.0f s -> %s/bench.md, bench.csv, bench.json\n", b.nrows, info.wall_s, o.out);
    }
    free(b.rows);
    return ok ? 0 : 1;
}
