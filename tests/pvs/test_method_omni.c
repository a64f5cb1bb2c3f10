/* test_method_omni.c - the all-directions PVS (pred_viewcell.frusta > 1):
 * on builtin:unit (scene/procedural.h) from v0 = (0, 1.5, -6.5), between the
 * wall W (z in [-5.1, -5], behind v0) and box B (z in [-8, -7], ahead), with
 * box C (x in [4, 5], z in [-6, -5]) off to the side and behind: the frustum
 * about forward (-Z) alone sees B and the ground, never W or C. The union of
 * the six faces' tr PVSs must hold every triangle any eye of the viewcell
 * sees in any direction. */
#include "method.h"
#include "procedural.h"
#include "rng.h"
#include "test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 160u
#define H 90u

static rnd_context* g_rnd;
static scn_scene g_scene;
static rnd_gpu_scene* g_gpu;

static uint32_t pvs_mask(pvs_method* m, const pvs_request* req, uint8_t* mask, pvs_method_stats* st)
{
    char err[512] = "";
    uint32_t *ids = NULL, n = 0;
    bool ok = pvs_method_compute(m, req, &ids, &n, st, err, sizeof err);
    if (!ok)
        fprintf(stderr, "compute: %s\n", err);
    TV_CHECK(ok);
    memset(mask, 0, g_scene.triangle_count);
    for (uint32_t i = 0; i < n; i++) {
        TV_CHECK(i == 0 || ids[i] > ids[i - 1]);
        mask[ids[i]] = 1;
    }
    free(ids);
    return n;
}

static bool any_in(const uint8_t* mask, const char* object)
{
    uint32_t first, count;
    TV_CHECK(scn_unit_object(object, &first, &count));
    for (uint32_t t = first; t < first + count; t++)
        if (mask[t])
            return true;
    return false;
}

static void test_omni_union_holds_every_view(void)
{
    /* a half turn over the window: too much for one frustum */
    pred_pose heads[3];
    for (int i = 0; i < 3; i++) {
        heads[i] = (pred_pose){.p = {0, 1.5, -6.5}};
        pred_quat_from_ypr((i - 1) * 0.5 * PRED_PI, 0, 0, heads[i].q);
    }
    pvs_request req = {.eye_fov_h_deg = 60.0f};
    pred_viewcell_from_poses(&(pred_viewcell_desc){.policy = PRED_POLICY_ADAPTIVE, .display_fov_v_deg = 36.0f}, heads,
                             3, 1, 0.05, 2.0, &req.vc);
    TV_CHECK(req.vc.frusta == PRED_VC_OMNI_FRUSTA);
    char err[512] = "";
    pvs_method* m = pvs_method_create(&(pvs_method_desc){.kind = PVS_METHOD_TR, .tr = {.width = 128, .height = 128},
                                                          .far_m = 80.0f},
                                      g_rnd, &g_scene, g_gpu, err, sizeof err);
    TV_CHECK(m != NULL);
    if (!m)
        return;
    uint32_t tris = g_scene.triangle_count;
    uint8_t *omni = malloc(tris), *front = malloc(tris), *seen = malloc(tris);
    pvs_method_stats st;
    uint32_t n_omni = pvs_mask(m, &req, omni, &st);
    TV_CHECK(st.frusta == PRED_VC_OMNI_FRUSTA);
    pvs_request one = req;
    pred_viewcell_frustum(&req.vc, 0, &one.vc);
    uint32_t n_front = pvs_mask(m, &one, front, &st);
    TV_CHECK(st.frusta == 1);
    printf("  omni %u triangles (%u in the front frustum alone) of %u\n", n_omni, n_front, tris);
    TV_CHECK(any_in(front, "box_b") && !any_in(front, "wall") && !any_in(front, "box_c"));
    TV_CHECK(any_in(omni, "box_b") && any_in(omni, "wall") && any_in(omni, "box_c"));
    for (uint32_t t = 0; t < tris; t++)
        TV_CHECK(!front[t] || omni[t]);

    /* eyes anywhere in the ball the cell was sized for, looking anywhere */
    rnd_target* target = rnd_target_create(g_rnd, W, H, err, sizeof err);
    uint32_t* ids = malloc(sizeof(uint32_t) * W * H);
    TV_CHECK(target && ids);
    pred_rng rng;
    pred_rng_seed(&rng, 7, 8);
    double radius = req.vc.delta * cos(PRED_VC_OMNI_HALF_DEG * PRED_DEG) * 0.999;
    int missing = 0, views = 0;
    bool saw_wall = false;
    for (int v = 0; v < 40 && target && ids; v++) {
        double p[3], q[4], r2;
        do {
            r2 = 0;
            for (int k = 0; k < 3; k++) {
                p[k] = pred_rng_range(&rng, -1, 1);
                r2 += p[k] * p[k];
            }
        } while (r2 > 1.0);
        for (int k = 0; k < 3; k++)
            p[k] = req.vc.v0[k] + radius * p[k];
        /* the first 8 views yaw around the horizon in 45-degree steps; then random orientations */
        if (v < 8)
            pred_quat_from_ypr(v * 0.25 * PRED_PI, 0, 0, q);
        else {
            for (int k = 0; k < 4; k++)
                q[k] = pred_rng_range(&rng, -1, 1);
            pred_quat_normalize(q);
        }
        TV_CHECK(pred_viewcell_contains(&req.vc, p, q, 60.0f, 36.0f, NULL));
        rnd_camera cam = {.position = {(float)p[0], (float)p[1], (float)p[2]},
                          .orientation = {(float)q[0], (float)q[1], (float)q[2], (float)q[3]},
                          .fov_y_deg = 36.0f, .near_m = 0.05f, .far_m = 80.0f};
        TV_CHECK(rnd_draw(g_rnd, target, g_gpu, &cam, NULL, 0, NULL) && rnd_target_read_ids(g_rnd, target, ids));
        memset(seen, 0, tris);
        for (uint32_t i = 0; i < W * H; i++)
            if (ids[i] < tris)
                seen[ids[i]] = 1;
        for (uint32_t t = 0; t < tris; t++)
            missing += seen[t] && !omni[t];
        saw_wall |= any_in(seen, "wall");
        views++;
    }
    printf("  %d views: %d visible triangles missing from the union\n", views, missing);
    TV_CHECK(views == 40 && missing == 0 && saw_wall);
    free(ids);
    if (target)
        rnd_target_destroy(g_rnd, target);
    free(omni);
    free(front);
    free(seen);
    pvs_method_destroy(m);
}

int main(void)
{
    char err[512];
    g_rnd = rnd_create(NULL, err, sizeof err);
    if (!g_rnd || !scn_load("builtin:unit", &g_scene, err, sizeof err) ||
        !(g_gpu = rnd_scene_create(g_rnd, &g_scene, err, sizeof err))) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    TV_TEST_RUN(test_omni_union_holds_every_view);
    rnd_scene_destroy(g_rnd, g_gpu);
    scn_scene_free(&g_scene);
    TV_CHECK(rnd_validation_message_count(g_rnd) == 0);
    rnd_destroy(g_rnd);
    return tv_test_finish();
}
