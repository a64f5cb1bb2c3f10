/* test_pvs_gpu_bench.c - timings of the GPU PVS next to a full-scene draw
 * at the same resolution (docs/pvs-gpu-passes.md; earlier figures in
 * docs/journal/2026-11-23-pvs-timings.md). Arguments: scene spec, then v0
 * x y z and the forward vector (defaults: builtin:city from a street).
 * Checks that a render of the PVS from the apex equals the full render's
 * depth at every pixel and that no validation message appeared; prints
 * medians over the runs. Then the cost of moving objects: PROXIES car-sized
 * proxy boxes (pvs_compute_dynamic) spread over the scene's ground, run
 * alternately with the static PVS, which their result must contain
 * (proxies never occlude). */
#include "pvs.h"
#include "render_fixture.h"
#include "test.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 512u
#define H 512u
#define RUNS 5
#define PROXIES 40

static double median(double* v, int n)
{
    for (int i = 1; i < n; i++) {
        for (int j = i; j > 0 && v[j] < v[j - 1]; j--) {
            double t = v[j];
            v[j] = v[j - 1];
            v[j - 1] = t;
        }
    }
    return v[n / 2];
}

int main(int argc, char** argv)
{
    const char* spec = argc > 1 ? argv[1] : "builtin:city";
    pvs_viewcell vc = {.v0 = {0.0f, 1.7f, 30.0f}, .forward = {0, 0, -1}, .up = {0, 1, 0}, .delta = 0.1f,
                       .fov_target_deg = 60.0f, .fov_pvs_deg = 90.0f, .far_m = 200.0f};
    if (argc > 7) {
        for (int i = 0; i < 3; i++) {
            vc.v0[i] = strtof(argv[2 + i], NULL);
            vc.forward[i] = strtof(argv[5 + i], NULL);
        }
    }
    char err[512];
    scn_scene scene;
    if (!scn_load(spec, &scene, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return strstr(err, "No such file") ? 77 : 1;
    }
    rnd_context* rnd = fx_context();
    rnd_gpu_scene* gpu = rnd_scene_create(rnd, &scene, err, sizeof err);
    rnd_target* target = gpu ? rnd_target_create(rnd, W, H, err, sizeof err) : NULL;
    pvs_context* pvs = target ? pvs_create(rnd, &scene, gpu, &(pvs_desc){.width = W, .height = H}, err, sizeof err)
                              : NULL;
    if (!pvs) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    double phase[5][RUNS], total[RUNS], full[RUNS];
    pvs_result r = {0};
    for (int run = 0; run < RUNS; run++) {
        TV_CHECK(pvs_compute(pvs, &vc, &r, err, sizeof err));
        for (int p = 0; p < 5; p++)
            phase[p][run] = r.stats.ms[p];
        total[run] = r.stats.total_ms;
        rnd_draw_stats ds;
        rnd_camera cam = pvs_apex_camera(pvs, &vc);
        TV_CHECK(rnd_draw(rnd, target, gpu, &cam, NULL, 0, &ds));
        full[run] = ds.cpu_ms;
    }
    const pvs_stats* s = &r.stats;
    printf("%s, %ux%u, delta %.2f m: PVS %u of %u triangles (%.1f%%)\n", scene.name, W, H, vc.delta, r.count,
           scene.triangle_count, 100.0 * r.count / scene.triangle_count);
    printf("  layers %u, layer triangles %u, silhouettes %u, active pixels %llu, mean sequence %.2f\n", s->layers,
           s->layer_triangles, s->silhouettes, (unsigned long long)s->active_pixels, s->mean_sequence);
    printf("  k-buffers %.1f MiB allocated, %.2f MiB used (peak layer), overflow %llu pixels / %llu fronts\n",
           (double)s->kbuffer_bytes / 1048576.0, (double)s->kbuffer_bytes_used / 1048576.0,
           (unsigned long long)s->overflow_pixels, (unsigned long long)s->overflow_fronts);
    printf("  median ms: P0 %.2f  P1 %.2f  P2 %.2f  P3 %.2f  P4 %.2f  total %.2f | full draw %.2f | ratio %.2f\n",
           median(phase[0], RUNS), median(phase[1], RUNS), median(phase[2], RUNS), median(phase[3], RUNS),
           median(phase[4], RUNS), median(total, RUNS), median(full, RUNS), median(total, RUNS) / median(full, RUNS));

    /* proxies: without ids, so that the results compare with the static one */
    pvs_proxy proxies[PROXIES];
    uint32_t seed = 7u;
    for (int i = 0; i < PROXIES; i++) {
        float at[3];
        for (int a = 0; a < 3; a += 2) {
            seed = seed * 1664525u + 1013904223u;
            at[a] = scene.bounds_min[a] + (scene.bounds_max[a] - scene.bounds_min[a]) * (float)(seed >> 8) / 16777216.0f;
        }
        proxies[i] = (pvs_proxy){.box_min = {at[0] - 2.25f, scene.bounds_min[1], at[2] - 1.0f},
                                 .box_max = {at[0] + 2.25f, scene.bounds_min[1] + 1.6f, at[2] + 1.0f}};
    }
    double stat[RUNS], dyn[RUNS];
    uint32_t lost = 0, extra = 0, output = 0;
    for (int run = 0; run < RUNS; run++) {
        TV_CHECK(pvs_compute(pvs, &vc, &r, err, sizeof err));
        stat[run] = r.stats.total_ms;
        uint32_t* ids = malloc(sizeof(uint32_t) * (r.count ? r.count : 1));
        uint32_t n = r.count;
        memcpy(ids, r.ids, sizeof(uint32_t) * n);
        TV_CHECK(pvs_compute_dynamic(pvs, &vc, proxies, PROXIES, &r, err, sizeof err));
        dyn[run] = r.stats.total_ms;
        output = r.stats.proxies_output;
        uint32_t j = 0;
        lost = 0;
        for (uint32_t i = 0; i < n; i++) { /* both sorted */
            while (j < r.count && r.ids[j] < ids[i])
                j++;
            lost += j == r.count || r.ids[j] != ids[i];
        }
        extra = r.count - (n - lost);
        free(ids);
    }
    printf("  %d proxies: %u output; PVS %u ids lost, %u added; median ms static %.2f, with proxies %.2f, ratio %.2f\n",
           PROXIES, output, lost, extra, median(stat, RUNS), median(dyn, RUNS), median(dyn, RUNS) / median(stat, RUNS));
    TV_CHECK(lost == 0);

    /* the static PVS again, and the full render from the apex at the PVS's frustum */
    float* full_depth = malloc(sizeof(float) * W * H);
    float* pvs_depth = malloc(sizeof(float) * W * H);
    rnd_camera cam = pvs_apex_camera(pvs, &vc);
    TV_CHECK(pvs_compute(pvs, &vc, &r, err, sizeof err) && rnd_draw(rnd, target, gpu, &cam, NULL, 0, NULL));
    TV_CHECK(full_depth && pvs_depth && rnd_target_read_depth(rnd, target, full_depth) &&
             rnd_draw(rnd, target, gpu, &cam, r.ids, r.count, NULL) && rnd_target_read_depth(rnd, target, pvs_depth));
    uint32_t missing = 0;
    for (uint32_t i = 0; full_depth && pvs_depth && i < W * H; i++)
        missing += full_depth[i] != pvs_depth[i];
    printf("  apex render: %u pixels differ in depth from a render of the PVS\n", missing);
    TV_CHECK(missing == 0);
    TV_CHECK(r.count > 0 && r.count <= scene.triangle_count);
    TV_CHECK(rnd_validation_message_count(rnd) == 0);
    free(full_depth);
    free(pvs_depth);
    pvs_destroy(pvs);
    rnd_target_destroy(rnd, target);
    rnd_scene_destroy(rnd, gpu);
    rnd_destroy(rnd);
    scn_scene_free(&scene);
    return tv_test_finish();
}
