/* bench_methods.c - one viewcell, every PVS method: wall-clock time and PVS
 * size (the "Baselines" table of docs/evaluation.md).
 *
 *   bench_methods SCENE PATH.csv T_S [LEVEL.pvs.json]
 *
 * The viewcell is sized by the FIXED policy (delta 0.1 m, PVS FOV 90 deg,
 * display 60 deg) for the use window [T, T + 0.05 s] of the path; the
 * request's current pose is the path at T - 0.05 s (latency 50 ms) and its
 * motion the displacement over the window. Each method runs once to warm up,
 * then three times; the median is printed, with the PVS's false negatives
 * against the gt method's set (|GT \ PVS|). Resolution 640 x 360. Exits 77
 * when SCENE is a file that does not exist (../shared absent). */
#include "method.h"
#include "path.h"
#include "stats.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RUNS 3

/* Runs one method RUNS + 1 times; its last id list marks `mask` (one byte
 * per triangle, cleared first); with `gt`, prints |GT \ PVS|. */
static bool bench(pvs_method_kind kind, const char* json, rnd_context* rnd, const scn_scene* scene,
                  const rnd_gpu_scene* gpu, const pvs_request* req, const uint8_t* gt, uint8_t* mask)
{
    char err[512];
    pvs_method_desc d = {.kind = kind, .width = 640, .height = 360, .q3vis_file = json};
    pvs_method* m = pvs_method_create(&d, rnd, scene, gpu, err, sizeof err);
    if (!m) {
        fprintf(stderr, "%s: %s\n", pvs_method_name(kind), err);
        return false;
    }
    double ms[RUNS];
    uint32_t count = 0, views = 0;
    for (int r = -1; r < RUNS; r++) {
        uint32_t* ids;
        pvs_method_stats st;
        if (!pvs_method_compute(m, req, &ids, &count, &st, err, sizeof err)) {
            fprintf(stderr, "%s: %s\n", pvs_method_name(kind), err);
            pvs_method_destroy(m);
            return false;
        }
        memset(mask, 0, scene->triangle_count);
        for (uint32_t i = 0; i < count; i++)
            mask[ids[i]] = 1;
        free(ids);
        if (r >= 0)
            ms[r] = st.total_ms;
        views = st.views;
    }
    uint32_t fn = 0;
    for (uint32_t t = 0; gt && t < scene->triangle_count; t++)
        fn += gt[t] && !mask[t];
    printf("%-10s %9.1f ms %8u triangles (%5.2f%%) %4u views, %6u of the gt set missing\n", pvs_method_name(kind),
           tv_percentile(ms, RUNS, 50.0), count, 100.0 * count / (scene->triangle_count ? scene->triangle_count : 1),
           views, fn);
    pvs_method_destroy(m);
    return true;
}

int main(int argc, char** argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: bench_methods SCENE PATH.csv T_S [LEVEL.pvs.json]\n");
        return 2;
    }
    FILE* probe = strncmp(argv[1], "builtin:", 8) == 0 ? NULL : fopen(argv[1], "rb");
    if (strncmp(argv[1], "builtin:", 8) != 0 && !probe) {
        printf("skip: %s absent\n", argv[1]);
        return 77;
    }
    if (probe)
        fclose(probe);
    char err[512];
    pred_path path;
    scn_scene scene;
    if (!pred_path_load(argv[2], &path, err, sizeof err) || !scn_load(argv[1], &scene, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    double t = atof(argv[3]);
    enum { N = 9 };
    pred_pose heads[N];
    for (int i = 0; i < N; i++)
        pred_path_sample(&path, t + 0.05 * i / (N - 1), &heads[i]);
    pvs_request req = {.eye_fov_h_deg = 60.0f};
    pred_viewcell_from_poses(&(pred_viewcell_desc){.policy = PRED_POLICY_FIXED}, heads, N, N / 2, 0.0, 0.0, &req.vc);
    pred_path_sample(&path, t - 0.05, &req.current);
    for (int k = 0; k < 3; k++)
        req.motion[k] = heads[N - 1].p[k] - heads[0].p[k];

    rnd_context* rnd = rnd_create(NULL, err, sizeof err);
    rnd_gpu_scene* gpu = rnd ? rnd_scene_create(rnd, &scene, err, sizeof err) : NULL;
    if (!gpu) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    printf("%s: %u triangles; viewcell v0 (%.2f, %.2f, %.2f), delta %.2f m, fov %.0f/%.0f deg, motion %.3f m; %s\n",
           scene.name, scene.triangle_count, req.vc.v0[0], req.vc.v0[1], req.vc.v0[2], req.vc.delta,
           req.vc.fov_target_deg, req.vc.fov_pvs_deg,
           sqrt(req.motion[0] * req.motion[0] + req.motion[1] * req.motion[1] + req.motion[2] * req.motion[2]),
           rnd_device_name(rnd));
    uint8_t* gt = malloc(scene.triangle_count + 1);
    uint8_t* mask = malloc(scene.triangle_count + 1);
    bool ok = gt && mask && bench(PVS_METHOD_GT, NULL, rnd, &scene, gpu, &req, NULL, gt);
    for (int k = 0; k < PVS_METHOD_COUNT && gt && mask; k++)
        if (k != PVS_METHOD_GT && (k != PVS_METHOD_Q3VIS || argc > 4))
            ok = bench((pvs_method_kind)k, argc > 4 ? argv[4] : NULL, rnd, &scene, gpu, &req, gt, mask) && ok;
    free(gt);
    free(mask);
    rnd_scene_destroy(rnd, gpu);
    ok = ok && rnd_validation_message_count(rnd) == 0;
    rnd_destroy(rnd);
    scn_scene_free(&scene);
    pred_path_free(&path);
    return ok ? 0 : 1;
}
