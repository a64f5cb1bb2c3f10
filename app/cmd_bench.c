/* trimvr bench: every PVS method on the same scenes and viewcells at several
 * Δ, measured against sampled ground truth (issues 3 and 6): the quantities
 * of the paper's Figures 13-16 and Tables 2-3 in one table per scene. */
#define _POSIX_C_SOURCE 200809L
#include "app_scene.h"
#include "args.h"
#include "bench_part.h"
#include "auto_place.h"
#include "bench_report.h"
#include "bench_shard.h"
#include "cli_viewcell.h"
#include "clock.h"
#include "commands.h"
#include "fs.h"
#include "gt_cache.h"
#include "interrupt.h"
#include "stats.h"
#include "log.h"
#include "version.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define MAX_LIST 32
#define DEFAULT_CELLS 24
#define DEFAULT_CELLS_TEXT "24"
#define DEFAULT_SCENES "builtin:city,builtin:house,sponza,oa:oasago2,oa:oa_dm5,oa:czest2ctf,oa:ctf_inyard,oa:oacmpdm9,oa:pul1ctf"

typedef struct bench_opts {
    const char *scenes, *deltas, *methods, *pos, *out, *shard, *gt_cache, *kb_layout;
    float dir[3], fov, fov_pvs;
    int every, max_cells, cells_per_job, samples, k, k_deep, k_regions, max_layers;
    unsigned res[2], pvs_res[2];
    bool jobs;
} bench_opts;

/* Splits the `sep`-separated list of option --name (copied into buf) into its
 * items. A list with no item, more than MAX_LIST or longer than buf is an
 * error naming the option (-1), not a shorter list: a cut-off item would read
 * as another number. */
static int split(const char* name, const char* list, char* buf, size_t size, char** items, char sep)
{
    int n = (size_t)snprintf(buf, size, "%s", list) < size ? 0 : -1;
    for (char *save = NULL, *t = n < 0 ? NULL : strtok_r(buf, (char[]){sep, 0}, &save); t;
         t = strtok_r(NULL, (char[]){sep, 0}, &save)) {
        if (n == MAX_LIST) {
            n = -1;
            break;
        }
        items[n++] = t;
    }
    if (n >= 1)
        return n;
    tv_log(TV_LOG_ERROR, "--%s: expected 1 to %d items in at most %zu characters, got '%s'", name, MAX_LIST, size - 1,
           list);
    return -1;
}

typedef struct bench_run {
    const bench_opts* o;
    float deltas[MAX_LIST];
    int ndelta;
    pvs_method_kind methods[PVS_METHOD_COUNT];
    int nmethod;
    float pos[3 * MAX_LIST]; /* --pos centres */
    int npos;
    char scene_buf[1024], *scenes[MAX_LIST];
    int nscene;
    tv_bench_unit* units;
    int nunits, first, end; /* this run's slice of units: [first, end) */
    tv_bench_cell* cells;   /* results in row order */
    int ncells, cap;
    double t0;
    char device[256];
    char scene_id[1024]; /* the current scene's identity in the GT cache */
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
            tv_log(TV_LOG_ERROR, "%s: %s", spec, err);
        return n;
    }
    if (b->npos == 0 && strcmp(b->placed_spec, spec) != 0) {
        int want = o->max_cells > 0 && o->max_cells < MAX_LIST ? o->max_cells : MAX_LIST;
        const char* rule = "";
        b->nplaced = tv_auto_viewcells(spec, &s->scene, want, b->placed_pos, b->placed_dir, &rule, err, sizeof err);
        snprintf(b->placed_spec, sizeof b->placed_spec, "%s", spec);
        if (b->nplaced < 0)
            tv_log(TV_LOG_ERROR, "%s: %s", spec, err);
        else
            fprintf(stderr, "bench %s: no bundled walk: %d viewcells placed by the %s rule (docs/bench.md)\n", spec,
                    b->nplaced, rule);
    }
    int n = b->npos > 0 ? b->npos : b->nplaced;
    const float* pos = b->npos > 0 ? b->pos : b->placed_pos;
    *out = n > 0 ? calloc((size_t)n, sizeof **out) : NULL;
    for (int i = 0; *out && i < n; i++) {
        const float* dir = b->npos > 0 ? o->dir : &b->placed_dir[3 * i];
        tv_viewcell_make(&pos[3 * i], dir, NULL, delta, o->fov, o->fov_pvs, &(*out)[i].vc);
        for (int k = 0; k < 3; k++)
            (*out)[i].motion[k] = 2.0 * delta * (*out)[i].vc.forward[k];
    }
    return *out ? n : -1;
}

/* Wall clock of three full-scene draws at the PVS resolution and FOV from
 * the viewcell centre (NaN where a draw fails): rows take the median, the
 * render the "PVS time <= 10x a full render at equal resolution"
 * compares with. */
static void full_render_ms(const bench_opts* o, const tv_app_scene* s, rnd_target* t, const tv_eval_cell* cell,
                           double ms[3])
{
    float aspect = (float)o->pvs_res[0] / (float)o->pvs_res[1];
    pvs_request req = tv_eval_request(cell, o->fov);
    rnd_camera cam = {.fov_y_deg = aspect >= 1.0f ? rnd_fov_y_from_x(o->fov_pvs, aspect) : o->fov_pvs,
                      .near_m = 0.05f, .far_m = 500.0f};
    for (int k = 0; k < 3; k++)
        cam.position[k] = cell->vc.v0[k];
    for (int k = 0; k < 4; k++)
        cam.orientation[k] = (float)req.current.q[k];
    for (int r = 0; r < 3; r++) {
        rnd_draw_stats st;
        ms[r] = t && rnd_draw(s->ctx, t, s->gpu, &cam, NULL, 0, &st) ? st.cpu_ms : NAN;
    }
}

static const char* elapsed(const bench_run* b, char* buf, size_t size)
{
    int s = (int)((tv_now_ms() - b->t0) / 1000.0);
    snprintf(buf, size, "%dm%02ds", s / 60, s % 60);
    return buf;
}

/* The row of (scene, method, delta) when some of its viewcells lie in this
 * run's slice (those are [*lo, *hi): the slice is contiguous), else -1. */
static int row_in_slice(const bench_run* b, int scene, int method, int delta, int* lo, int* hi)
{
    int row = -1;
    for (int u = b->first; u < b->end; u++) {
        const tv_bench_unit* x = &b->units[u];
        if (x->scene != scene || x->method != method || x->delta != delta)
            continue;
        *lo = row < 0 ? x->first_cell : *lo;
        *hi = x->end_cell;
        row = x->row;
    }
    return row;
}

static bool append_cell(bench_run* b, const tv_bench_cell* c)
{
    if (b->ncells == b->cap) {
        int cap = b->cap ? 2 * b->cap : 64;
        tv_bench_cell* grown = realloc(b->cells, (size_t)cap * sizeof *grown);
        if (!grown)
            return false;
        b->cells = grown;
        b->cap = cap;
    }
    b->cells[b->ncells++] = *c;
    return true;
}

/* The progress line of the last n viewcell results (one row's). */
static void print_row(const bench_run* b, int n)
{
    tv_bench_row* r;
    char t[32];
    if (n < 1 || tv_bench_rows(&b->cells[b->ncells - n], n, &r) != 1)
        return;
    const pvs_eval_result* x = &r->mean.m;
    fprintf(stderr, "bench %s: %-9s delta %4.2f: %d cells, PVS %.2f%% (GT %.2f%%), FP %.3f, FN %.4f, "
                    "FNG %.1f px, PSNR %.1f dB, SSIM %.4f, PVS %.0f ms, GT %.0f ms [%s]\n",
            r->scene, pvs_method_name(r->method), r->delta, n, 100.0 * x->pvs_fraction, 100.0 * x->gt_fraction,
            x->fp_rate, x->fn_rate, x->fng_pixels_mean, x->psnr_mean_db, x->ssim_mean, r->mean.pvs_ms, x->gt_ms,
            elapsed(b, t, sizeof t));
    free(r);
}

/* One method at every delta of the slice on one scene: viewcell results
 * appended in ascending delta. */
static bool bench_method(bench_run* b, int scene, const tv_app_scene* s, int method, uint8_t* mask, uint8_t* gt)
{
    const bench_opts* o = b->o;
    const char* spec = b->scenes[scene];
    pvs_method_kind kind = b->methods[method];
    char err[512], json[4200];
    tv_eval_pvs_json_of(spec, json, sizeof json);
    pvs_method_desc md = {.kind = kind, .tr = {.width = o->pvs_res[0], .height = o->pvs_res[1], .k = (uint32_t)o->k,
                                                   .k_deep = (uint32_t)o->k_deep, .k_regions = (uint32_t)o->k_regions, .kbuffer_layout = (pvs_kbuffer_layout)tv_arg_kbuffer_layout(o->kb_layout),
                                                   .max_layers = tv_arg_max_layers(o->max_layers)},
                          .width = o->res[0], .height = o->res[1], .gt_samples = (uint32_t)o->samples,
                          .q3vis_file = kind == PVS_METHOD_Q3VIS ? json : NULL};
    pvs_method* m = pvs_method_create(&md, s->ctx, &s->scene, s->gpu, err, sizeof err);
    if (!m) {
        tv_log(TV_LOG_ERROR, "%s: %s", spec, err);
        return false;
    }
    rnd_target* target = rnd_target_create(s->ctx, o->pvs_res[0], o->pvs_res[1], err, sizeof err);
    pvs_eval_desc ed = {.samples = (uint32_t)o->samples, .width = o->res[0], .height = o->res[1],
                        .gt_cache_dir = o->gt_cache, .gt_cache_scene = b->scene_id};
    bool ok = true, warm = false;
    for (int d = 0; d < b->ndelta && ok && !tv_interrupted(); d++) {
        int lo = 0, hi = 0, row = row_in_slice(b, scene, method, d, &lo, &hi), done = 0, kept = b->ncells;
        if (row < 0)
            continue;
        tv_eval_cell* cells = NULL;
        int n = scene_cells(b, spec, s, b->deltas[d], &cells);
        ok = n > 0;
        for (int i = 0; ok && !b->cells_printed && i < n; i++) /* once per scene, to repeat with --pos */
            fprintf(stderr, "bench %s: viewcell %d at %.9g,%.9g,%.9g looking %.9g,%.9g,%.9g\n", spec, i,
                    cells[i].vc.v0[0], cells[i].vc.v0[1], cells[i].vc.v0[2], cells[i].vc.forward[0],
                    cells[i].vc.forward[1], cells[i].vc.forward[2]);
        b->cells_printed = b->cells_printed || ok;
        hi = hi < n ? hi : n;
        if (ok && !warm && lo < hi) { /* the first PVS builds what is cached per scene (octree, pipelines) */
            pvs_request req = tv_eval_request(&cells[lo], o->fov);
            uint32_t *ids = NULL, count;
            ok = pvs_method_compute(m, &req, &ids, &count, NULL, err, sizeof err);
            free(ids);
            warm = true;
        }
        for (int i = lo; ok && i < hi && !tv_interrupted(); i++, done++) {
            tv_bench_cell c = {.row = row, .index = i, .method = kind, .delta = b->deltas[d]};
            snprintf(c.scene, sizeof c.scene, "%s", spec);
            ok = tv_eval_cell_run(m, s->ctx, &s->scene, s->gpu, &ed, o->fov, &cells[i], mask, gt, err, sizeof err);
            if (ok) {
                c.c = cells[i];
                full_render_ms(o, s, target, &cells[i], c.full_ms);
                if (!append_cell(b, &c))
                    snprintf(err, sizeof err, "out of memory");
                ok = b->ncells > 0 && b->cells[b->ncells - 1].row == row && b->cells[b->ncells - 1].index == i;
            }
        }
        if (!ok && n > 0)
            tv_log(TV_LOG_ERROR, "%s, %s, delta %.2f: %s", spec, pvs_method_name(kind),
                    b->deltas[d], err);
        if (ok && lo + done == hi)
            print_row(b, done);
        else /* a row stopped by an error or a signal is left out of the report, not shown short */
            b->ncells = kept;
        free(cells);
    }
    if (target)
        rnd_target_destroy(s->ctx, target);
    pvs_method_destroy(m);
    return ok;
}

/* Every method of the slice on one scene; a scene file that is absent is
 * skipped. */
static bool bench_scene(bench_run* b, int scene)
{
    const char* spec = b->scenes[scene];
    bool wanted = false;
    for (int u = b->first; u < b->end; u++)
        wanted = wanted || b->units[u].scene == scene;
    if (!wanted)
        return true;
    char file[4200];
    tv_resolve_scene_spec(spec, file, sizeof file);
    if (strncmp(file, "builtin:", 8) != 0 && access(file, R_OK) != 0) {
        tv_log(TV_LOG_WARN, "skip %s: %s not found", spec, file);
        return true;
    }
    tv_app_scene s;
    b->cells_printed = false;
    if (!tv_app_scene_open(spec, &s))
        return false;
    snprintf(b->device, sizeof b->device, "%s", rnd_device_name(s.ctx));
    if (b->o->gt_cache)
        pvs_gt_scene_id(&s.scene, spec, b->device, b->scene_id, sizeof b->scene_id);
    uint32_t tris = s.scene.triangle_count;
    uint8_t* mask = calloc(tris + 1, 1);
    uint8_t* gt = calloc(tris + 1, 1);
    bool ok = mask && gt;
    for (int i = 0; ok && i < b->nmethod && !tv_interrupted(); i++)
        ok = bench_method(b, scene, &s, i, mask, gt);
    free(mask);
    free(gt);
    return tv_app_scene_close(&s) && ok;
}

static bool parse_lists(const bench_opts* o, bench_run* b)
{
    char buf[512], *items[MAX_LIST];
    if ((b->ndelta = split("deltas", o->deltas, buf, sizeof buf, items, ',')) < 0)
        return false;
    for (int i = 0; i < b->ndelta; i++) {
        char* end;
        b->deltas[i] = strtof(items[i], &end);
        if (*end || !(b->deltas[i] >= 0.0f && isfinite(b->deltas[i])) || (i > 0 && b->deltas[i] <= b->deltas[i - 1])) {
            tv_log(TV_LOG_ERROR, "--deltas: expected ascending metres >= 0, got '%s'", items[i]);
            return false;
        }
    }
    int n = split("methods", o->methods, buf, sizeof buf, items, ',');
    if (n < 0)
        return false;
    for (int i = 0; i < n; i++) {
        if (b->nmethod == PVS_METHOD_COUNT || !pvs_method_from_name(items[i], &b->methods[b->nmethod++])) {
            tv_log(TV_LOG_ERROR, "--methods: unknown or repeated method '%s' (tr, gt, sas, "
                            "frompoint, q3vis)", items[i]);
            return false;
        }
    }
    if ((b->npos = o->pos ? split("pos", o->pos, buf, sizeof buf, items, ';') : 0) < 0)
        return false;
    for (int i = 0; i < b->npos; i++) {
        char tail;
        float* p = &b->pos[3 * i];
        if (sscanf(items[i], "%f,%f,%f%c", &p[0], &p[1], &p[2], &tail) != 3 ||
            !(isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]))) {
            tv_log(TV_LOG_ERROR, "--pos: expected finite X,Y,Z;X,Y,Z..., got '%s'", items[i]);
            return false;
        }
    }
    return true;
}

/* Every option that changes a result, in one canonical string: parts of
 * one sweep must agree on it. */
static void settings_of(const bench_opts* o, char* buf, size_t size)
{
    snprintf(buf, size,
             "scenes=%s;deltas=%s;methods=%s;path-every=%d;max-cells=%d;cells-per-job=%d;pos=%s;dir=%.9g,%.9g,%.9g;"
             "samples=%d;res=%ux%u;pvs-res=%ux%u;k=%d;k-deep=%d;k-regions=%d;kbuffer-layout=%s;max-layers=%d;fov=%.9g;fov-pvs=%.9g",
             o->scenes, o->deltas, o->methods, o->every, o->max_cells, o->cells_per_job, o->pos ? o->pos : "", o->dir[0], o->dir[1],
             o->dir[2], o->samples, o->res[0], o->res[1], o->pvs_res[0], o->pvs_res[1], o->k, o->k_deep, o->k_regions,
             o->kb_layout ? o->kb_layout : "default", o->max_layers, o->fov,
             o->fov_pvs);
}

/* A shard's results as DIR/part-<I>.json. */
static bool write_part(const bench_run* b, const char* command, const char* date, int shard, int shards)
{
    const bench_opts* o = b->o;
    tv_bench_part p = {.shard = shard, .shards = shards, .wall_s = (tv_now_ms() - b->t0) / 1000.0,
                       .res = {o->res[0], o->res[1]}, .pvs_res = {o->pvs_res[0], o->pvs_res[1]},
                       .samples = o->samples, .fov = o->fov, .fov_pvs = o->fov_pvs, .cells = b->cells,
                       .count = b->ncells};
    snprintf(p.version, sizeof p.version, "%s", TRIMVR_VERSION);
    settings_of(o, p.settings, sizeof p.settings);
    snprintf(p.command, sizeof p.command, "%s", command);
    snprintf(p.device, sizeof p.device, "%s", b->device);
    snprintf(p.date, sizeof p.date, "%s", date);
    char file[4200], err[4400];
    snprintf(file, sizeof file, "%s/part-%d.json", o->out, shard);
    if (!tv_bench_part_write(file, &p, err, sizeof err)) {
        tv_log(TV_LOG_ERROR, "%s", err);
        return false;
    }
    printf("trimvr bench: shard %d/%d: units %d..%d, %d viewcell results in %.0f s -> %s\n", shard, shards, b->first,
           b->end - 1, b->ncells, p.wall_s, file);
    return true;
}

/* A sweep's results as bench.md, bench.csv, bench.json and plots; `stopped`
 * (NULL for a whole sweep) says why it ended early, in the report itself. */
static bool write_report(const bench_run* b, const char* command, const char* date, const char* stopped)
{
    const bench_opts* o = b->o;
    tv_bench_row* rows = NULL;
    int nrows = tv_bench_rows(b->cells, b->ncells, &rows);
    tv_bench_info info = {.command_line = command, .date = date, .device = b->device, .version = TRIMVR_VERSION,
                          .res = {o->res[0], o->res[1]}, .pvs_res = {o->pvs_res[0], o->pvs_res[1]},
                          .samples = o->samples, .fov = o->fov, .fov_pvs = o->fov_pvs, .stopped = stopped,
                          .wall_s = (tv_now_ms() - b->t0) / 1000.0};
    char err[4300];
    bool ok = nrows > 0;
    if (!ok)
        tv_log(TV_LOG_ERROR, "%s", nrows < 0 ? "out of memory" : "no scene could be benchmarked");
    if (ok && !(ok = tv_bench_write(o->out, &info, rows, nrows, err, sizeof err)))
        tv_log(TV_LOG_ERROR, "%s", err);
    if (ok) {
        tv_bench_plots(o->out, rows, nrows);
        printf("trimvr bench: %d rows in %.0f s -> %s/bench.md, bench.csv, bench.json\n", nrows, info.wall_s, o->out);
    }
    free(rows);
    return ok;
}

int tv_cmd_bench(int argc, char** argv)
{
    if (argc > 0 && strcmp(argv[0], "merge") == 0) {
        tv_log_set_program("bench merge");
        return tv_cmd_bench_merge(argc - 1, argv + 1);
    }
    bench_opts o = {.scenes = DEFAULT_SCENES, .deltas = "0.05,0.1,0.2,0.3", .methods = "tr,sas,frompoint,gt,q3vis",
                    .out = "out/bench", .dir = {0, 0, -1}, .fov = 60.0f, .fov_pvs = 90.0f, .every = 0,
                    .max_cells = DEFAULT_CELLS, .samples = 50, .res = {320, 180}, .k = TV_ARGS_DEFAULT_K,
                    .max_layers = TV_ARGS_DEFAULT_MAX_LAYERS};
    const tv_arg args[] = {
        {"scenes", TV_ARG_STRING, &o.scenes, "S,S..", "scenes (default builtin:city, builtin:house, sponza and the six oa: levels)"},
        {"deltas", TV_ARG_STRING, &o.deltas, "M,M..", "viewcell radii, ascending (default 0.05,0.1,0.2,0.3)"},
        {"methods", TV_ARG_STRING, &o.methods, "M,M..", "methods (default tr,sas,frompoint,gt,q3vis; q3vis on oa: only)"},
        {"path-every", TV_ARG_INT, &o.every, "N",
         "walk paths: one viewcell every N frames at 90 Hz (default 0: --max-cells spread evenly)"},
        {"max-cells", TV_ARG_INT, &o.max_cells, "N",
         "at most N viewcells per scene (default " DEFAULT_CELLS_TEXT "; 3 for a quick look)"},
        {"pos", TV_ARG_STRING, &o.pos, "X,Y,Z;..", "viewcells at these centres instead (every scene)"},
        {"dir", TV_ARG_VEC3, o.dir, "X,Y,Z", "with --pos: view direction (default 0,0,-1)"},
        {"samples", TV_ARG_INT, &o.samples, "N", "ground-truth views per viewcell, also gt's (default 50)"},
        {"res", TV_ARG_RES, o.res, "WxH", "ground-truth and id-buffer resolution (default 320x180)"},
        TV_ARG_GT_CACHE(&o.gt_cache),
        {"pvs-res", TV_ARG_RES, o.pvs_res, "WxH", "tr resolution and full-render timing (default 512x512)"},
        TV_ARG_K(&o.k),
        TV_ARG_K_DEEP(&o.k_deep),
        TV_ARG_K_REGIONS(&o.k_regions),
        TV_ARG_KBUFFER_LAYOUT(&o.kb_layout),
        TV_ARG_MAX_LAYERS(&o.max_layers),
        {"fov", TV_ARG_FLOAT, &o.fov, "DEG", "display FOV, horizontal (default 60)"},
        {"fov-pvs", TV_ARG_FLOAT, &o.fov_pvs, "DEG", "PVS FOV, square frustum (default 90)"},
        {"out", TV_ARG_STRING, &o.out, "DIR", "output folder (default out/bench); with --shard: its part file's"},
        {"jobs", TV_ARG_FLAG, &o.jobs, NULL, "print one command per scene x method x delta (each a --shard) and exit"},
        {"cells-per-job", TV_ARG_INT, &o.cells_per_job, "K",
         "with --jobs/--shard: split each scene x method x delta into jobs of K viewcells (default 0: whole)"},
        {"shard", TV_ARG_STRING, &o.shard, "I/N", "run slice I of N of the grid and write DIR/part-I.json"},
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
    if (!parse_lists(&o, &b) || tv_arg_kbuffer_layout(o.kb_layout) < 0 || !tv_arg_k(o.k, o.k_deep, o.k_regions) ||
        !tv_arg_require("max-layers", o.max_layers, o.max_layers >= -1, ">= -1") || !tv_arg_gt_cache(o.gt_cache))
        return 2;
    float dir_len = sqrtf(o.dir[0] * o.dir[0] + o.dir[1] * o.dir[1] + o.dir[2] * o.dir[2]);
    if (o.every < 0 || o.samples < 1 || o.max_cells < 1 || o.cells_per_job < 0 || !(o.fov > 0.0f && o.fov <= o.fov_pvs) ||
        !(o.fov_pvs < TV_VIEWCELL_MAX_FOV_PVS) || !(dir_len > 0.0f)) {
        tv_log(TV_LOG_ERROR, "need --path-every, --cells-per-job >= 0, --samples, --max-cells >= 1, "
                        "0 < --fov <= --fov-pvs < 179 and a non-zero --dir (see trimvr bench --help)");
        return 2;
    }
    int shard = 0, shards = 1;
    if (o.shard && (o.jobs || !tv_bench_shard_parse(o.shard, &shard, &shards))) {
        tv_log(TV_LOG_ERROR, "--shard: expected I/N with 0 <= I < N, without --jobs, got '%s'",
                o.shard);
        return 2;
    }
    if ((b.nscene = split("scenes", o.scenes, b.scene_buf, sizeof b.scene_buf, b.scenes, ',')) < 0)
        return 2;
    int cells = b.npos > 0 ? b.npos : o.max_cells; /* the most viewcells a scene can have */
    b.nunits = tv_bench_units(b.scenes, b.nscene, b.methods, b.nmethod, b.ndelta, cells, o.cells_per_job, NULL);
    if (b.nunits < 0) {
        tv_log(TV_LOG_ERROR, "--max-cells %d, --cells-per-job %d: more than %d units (scene x method x delta x "
               "viewcells / cells per job)", o.max_cells, o.cells_per_job, TV_BENCH_MAX_UNITS);
        return 2;
    }
    if (!(b.units = malloc(((size_t)b.nunits + 1) * sizeof *b.units))) {
        tv_log(TV_LOG_ERROR, "out of memory for %d units", b.nunits);
        return 1;
    }
    tv_bench_units(b.scenes, b.nscene, b.methods, b.nmethod, b.ndelta, cells, o.cells_per_job, b.units);
    if (o.jobs) { /* main passes argv + 2: argv[-2] is the program as the user invoked it */
        tv_bench_print_jobs(stdout, argv[-2], argc, argv, b.nunits);
        free(b.units);
        return 0;
    }
    tv_bench_slice(b.nunits, shard, shards, &b.first, &b.end);
    bool ok = tv_mkdirs(o.out);
    if (!ok)
        tv_log(TV_LOG_ERROR, "%s: cannot create the output folder", o.out);
    tv_interrupt_install(); /* a signal stops the sweep between viewcells */
    for (int i = 0; i < b.nscene && ok && !tv_interrupted(); i++)
        ok = bench_scene(&b, i);
    char cmd[4096] = "trimvr bench", date[64]; /* without --shard: the sweep's command, the same in every part */
    for (int i = 0; i < argc; i++) {
        bool shard_arg = strncmp(argv[i], "--shard", 7) == 0 && (argv[i][7] == 0 || argv[i][7] == '=');
        if (shard_arg)
            i += argv[i][7] == 0;
        else
            snprintf(cmd + strlen(cmd), sizeof cmd - strlen(cmd), " %s", argv[i]);
    }
    time_t now = time(NULL);
    strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", gmtime(&now));
    int sig = tv_interrupted();
    if (ok && !sig)
        ok = o.shard ? write_part(&b, cmd, date, shard, shards) : write_report(&b, cmd, date, NULL);
    else if (!o.shard && b.ncells > 0) { /* keep the complete rows; a part file is whole or absent (merge trusts it) */
        char why[64] = "stopped by an error";
        if (sig)
            snprintf(why, sizeof why, "interrupted by signal %d", sig);
        write_report(&b, cmd, date, why);
    }
    free(b.cells);
    free(b.units);
    if (sig)
        tv_log(TV_LOG_ERROR, "interrupted by signal %d: %s", sig,
               o.shard ? "no part file written (run the shard again)"
                       : "the report holds the rows completed so far, if any");
    return sig ? tv_interrupt_status(sig) : ok ? 0 : 1;
}
