/* trimvr pvs: compute one PVS for a viewcell given on the command line and
 * print its size and the method's statistics (per-phase timings, layers,
 * k-buffer use for tr). */
#include "app_scene.h"
#include "args.h"
#include "cli_viewcell.h"
#include "commands.h"
#include "method.h"
#include "log.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void print_tr_stats(const pvs_stats* s)
{
    printf("phases (ms)       P0 %.2f  P1 %.2f  P2 %.2f  P3 %.2f  P4 %.2f  (total %.2f)\n", s->ms[0], s->ms[1],
           s->ms[2], s->ms[3], s->ms[4], s->total_ms);
    printf("layers            %u (%u triangles in layers, %u trim regions)\n", s->layers, s->layer_triangles,
           s->silhouettes);
    printf("active pixels     %llu (summed over layers), mean trim sequence %.2f, %llu sorted by a workgroup\n",
           (unsigned long long)s->active_pixels, s->mean_sequence, (unsigned long long)s->coop_pixels);
    printf("k-buffers         %.1f MiB allocated (%u tile%s), %.1f MiB used (fullest layer), pool grown %u time%s, "
           "%llu entries lost\n",
           s->kbuffer_bytes / 1048576.0, s->tiles, s->tiles == 1 ? "" : "s", s->kbuffer_bytes_used / 1048576.0,
           s->kbuffer_regrows, s->kbuffer_regrows == 1 ? "" : "s", (unsigned long long)s->kbuffer_lost);
    printf("overflow          %llu pixels, %llu front fragments (handled conservatively)\n",
           (unsigned long long)s->overflow_pixels, (unsigned long long)s->overflow_fronts);
    if (s->loop_budget_pixels)
        printf("loop budget       %llu pixel resolves ran out of it (llvmpipe): unreliable\n",
               (unsigned long long)s->loop_budget_pixels);
    printf("per layer         tris: in the layer / fronts + backs drawn, regions: trim regions, active: pixels\n"
           "                  resolved, seq: mean trim sequence, ovf: overflowing pixels, KiB: k-buffer pages taken\n"
           "                  (flat layout: entries read)\n");
    printf("%5s %8s %8s %8s %8s %8s %6s %6s %8s %9s %9s %9s\n", "layer", "tris", "fronts", "backs", "regions",
           "active", "seq", "ovf", "KiB", "P1 ms", "P2 ms", "P3 ms");
    for (uint32_t l = 0; s->per_layer && l < s->layers; l++) {
        const pvs_layer_stats* p = &s->per_layer[l];
        printf("%5u %8u %8u %8u %8u %8llu %6.2f %6llu %8.1f %9.2f %9.2f %9.2f\n", l, p->triangles, p->fronts,
               p->backs, p->silhouettes, (unsigned long long)p->active_pixels,
               p->active_pixels ? (double)p->sequence_entries / (double)p->active_pixels : 0.0,
               (unsigned long long)p->overflow_pixels, p->kbuffer_bytes_used / 1024.0, p->ms[0], p->ms[1], p->ms[2]);
    }
}

/* --repeat: one line per computation (the first pays first touches and
 * shader compiles, the later ones are what a long-running app pays). */
static void print_run(int i, const pvs_method_stats* st, pvs_method_kind kind)
{
    if (kind == PVS_METHOD_TR)
        printf("run %-13d P1 %.2f  P2 %.2f  P3 %.2f  (total %.2f)\n", i, st->tr.ms[1], st->tr.ms[2], st->tr.ms[3],
               st->total_ms);
    else
        printf("run %-13d total %.2f\n", i, st->total_ms);
}

/* The same request again: a warning where the ids differ from the first's,
 * which they should not (docs/pvs-gpu-passes.md, "Repeatability"). */
static bool compute_again(pvs_method* m, const pvs_request* req, const uint32_t* ids, uint32_t count,
                          pvs_method_stats* st, char* err, size_t err_size)
{
    uint32_t* again = NULL;
    uint32_t n = 0;
    *st = (pvs_method_stats){0};
    if (!pvs_method_compute(m, req, &again, &n, st, err, err_size))
        return false;
    if (n != count || (n && memcmp(again, ids, sizeof(uint32_t) * n) != 0))
        tv_log(TV_LOG_WARN, "--repeat: a computation gave other ids than the first (%u triangles, first %u)", n,
               count);
    free(again);
    return true;
}

int tv_cmd_pvs(int argc, char** argv)
{
    const char *scene = NULL, *method = "tr", *ids_out = NULL, *layout = NULL;
    float pos[3] = {NAN, NAN, NAN}, dir[3] = {0, 0, -1}, up[3] = {NAN, NAN, NAN};
    float delta = 0.1f, fov = 60.0f, fov_pvs = 90.0f;
    unsigned res[2] = {0, 0};
    int k = TV_ARGS_DEFAULT_K, coop_min = 0, tile_pixels = 0, max_layers = TV_ARGS_DEFAULT_MAX_LAYERS, pages = 0;
    int repeat = 1, k_deep = 0, k_regions = 0;
    const tv_arg args[] = {
        {"scene", TV_ARG_STRING, &scene, "S", "scene (required)"},
        {"pos", TV_ARG_VEC3, pos, "X,Y,Z", "viewcell centre v0 (required)"},
        {"dir", TV_ARG_VEC3, dir, "X,Y,Z", "view direction (default 0,0,-1)"},
        {"up", TV_ARG_VEC3, up, "X,Y,Z",
         "up direction, made perpendicular to --dir (default +Y; a replay's pvs.csv has its own)"},
        {"delta", TV_ARG_FLOAT, &delta, "M", "viewcell radius (default 0.1; tr: at most 31.7 m x tan(fov-pvs / 2))"},
        {"fov", TV_ARG_FLOAT, &fov, "DEG", "display FOV (default 60)"},
        TV_ARG_FOV_PVS(&fov_pvs),
        {"res", TV_ARG_RES, res, "WxH", "PVS resolution (default 512x512)"},
        TV_ARG_K(&k),
        TV_ARG_K_DEEP(&k_deep),
        TV_ARG_K_REGIONS(&k_regions),
        TV_ARG_KBUFFER_LAYOUT(&layout),
        TV_ARG_MAX_LAYERS(&max_layers),
        {"coop-min", TV_ARG_INT, &coop_min, "N",
         "tr: sort trim sequences of >= N entries with a workgroup per pixel (default 8; 1000: never)"},
        {"tile-pixels", TV_ARG_INT, &tile_pixels, "N",
         "tr: compute the image in tiles of at most N pixels (default 1024x1024, flat layout 512x512)"},
        {"kbuffer-pages", TV_ARG_INT, &pages, "N",
         "tr, paged: first size of the k-buffer page pool, in pages of 4 entries (default: 2 per tile pixel)"},
        TV_ARG_METHOD(&method),
        {"ids", TV_ARG_STRING, &ids_out, "FILE", "also write the triangle ids, one per line"},
        {"repeat", TV_ARG_INT, &repeat, "N",
         "compute N times in one context, one timing line each, statistics of the last (the first pays "
         "first touches and shader compiles; default 1)"},
    };
    tv_args_result r = tv_args_parse("pvs", "Computes the PVS of one viewcell and prints a summary.", args,
                                     (int)(sizeof args / sizeof args[0]), argc, argv);
    if (r != TV_ARGS_OK)
        return r == TV_ARGS_HELP ? 0 : 2;
    /* tr's frustum is square (the viewcell's PVS FOV on both axes): a square image by default */
    int kb_layout = tv_arg_kbuffer_layout(layout);
    pvs_method_desc md = {.tr = {.width = res[0] ? res[0] : 512, .height = res[1] ? res[1] : 512, .k = (uint32_t)k,
                                 .k_deep = (uint32_t)k_deep, .k_regions = (uint32_t)k_regions, .kbuffer_layout = (pvs_kbuffer_layout)kb_layout,
                                 .coop_sort_min = (uint32_t)coop_min, .max_tile_pixels = (uint32_t)tile_pixels,
                                 .kbuffer_pages = (uint32_t)pages,
                                 .max_layers = tv_arg_max_layers(max_layers)},
                          .width = res[0], .height = res[1]};
    pred_viewcell vc;
    if (kb_layout < 0 || !tv_arg_k(k, k_deep, k_regions) ||
        !tv_arg_require("coop-min", coop_min, coop_min >= 0, ">= 0") ||
        !tv_arg_require("tile-pixels", tile_pixels, tile_pixels >= 0, ">= 0") ||
        !tv_arg_require("kbuffer-pages", pages, pages >= 0, ">= 0") ||
        !tv_arg_require("max-layers", max_layers, max_layers >= -1, ">= -1") ||
        !tv_arg_require("repeat", repeat, repeat >= 1, ">= 1") || !tv_arg_viewcell(delta, fov, fov_pvs))
        return 2;
    if (!scene || isnan(pos[0]) || !pvs_method_from_name(method, &md.kind) ||
        !tv_viewcell_make(pos, dir, isnan(up[0]) ? NULL : up, delta, fov, fov_pvs, &vc)) {
        tv_log(TV_LOG_ERROR, "need --scene, --pos, a known --method, a non-zero --dir (components below 1e19) and "
               "--up not parallel to it (see trimvr pvs --help)");
        return 2;
    }
    tv_app_scene s;
    if (!tv_app_scene_open(scene, &s))
        return 1;
    char err[512];
    int status = 0;
    pvs_method* m = pvs_method_create(&md, s.ctx, &s.scene, s.gpu, err, sizeof err);
    pvs_request req = {.vc = vc, .eye_fov_h_deg = fov};
    for (int i = 0; i < 3; i++)
        req.current.p[i] = pos[i];
    req.current.q[3] = 1.0;
    /* movers over the viewcell's window (tv_viewcell_make: [0, TV_VIEWCELL_WINDOW_S]) */
    pvs_proxy* proxies = calloc(s.scene.mover_count ? s.scene.mover_count : 1, sizeof *proxies);
    req.proxies = proxies;
    req.proxy_count = proxies ? pvs_method_proxies(&s.scene, vc.t_begin, vc.t_end, proxies) : 0;
    uint32_t* ids = NULL;
    uint32_t count = 0;
    pvs_method_stats st = {0};
    if (!proxies)
        snprintf(err, sizeof err, "out of memory");
    bool ok = m && proxies && pvs_method_compute(m, &req, &ids, &count, &st, err, sizeof err);
    for (int i = 1; ok && i < repeat; i++) {
        print_run(i, &st, md.kind);
        ok = compute_again(m, &req, ids, count, &st, err, sizeof err);
    }
    if (ok && repeat > 1)
        print_run(repeat, &st, md.kind);
    if (!ok) {
        tv_log(TV_LOG_ERROR, "%s", err);
        status = 1;
    } else {
        printf("scene             %s (%u triangles) on %s\n", scene, s.scene.triangle_count, rnd_device_name(s.ctx));
        printf("viewcell          v0 (%.3f, %.3f, %.3f), delta %.3f m, FOV %.1f / PVS %.1f deg, apex %.3f m behind\n",
               vc.v0[0], vc.v0[1], vc.v0[2], vc.delta, vc.fov_target_deg, vc.fov_pvs_deg, vc.z);
        printf("PVS (%s)          %u triangles, %.2f %% of the scene, %.1f ms\n", method, count,
               s.scene.triangle_count ? 100.0 * count / s.scene.triangle_count : 0.0, st.total_ms);
        if (md.kind == PVS_METHOD_TR)
            print_tr_stats(&st.tr);
        else
            printf("views rendered    %u\n", st.views);
        if (ids_out) {
            FILE* f = fopen(ids_out, "w");
            for (uint32_t i = 0; f && i < count; i++)
                fprintf(f, "%u\n", ids[i]);
            if (!f || fclose(f) != 0) {
                tv_log(TV_LOG_ERROR, "%s: cannot write", ids_out);
                status = 1;
            }
        }
    }
    free(ids);
    free(proxies);
    pvs_method_destroy(m);
    if (!tv_app_scene_close(&s))
        status = 1;
    return status;
}
