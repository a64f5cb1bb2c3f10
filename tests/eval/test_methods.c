/* test_methods.c - every PVS method behind method.h on builtin:unit, whose
 * visibility is analytic (scene/procedural.h, tests/eval/test_ground_truth.c):
 * box B (x in [-0.5, 0.5], z in [-8, -7]) hides behind wall W (x in [-2, 2],
 * z in [-5.1, -5]) for eyes at height 1.5 m until x_eye > 4.638; box C
 * (x in [4, 5], z in [-6, -5]) is in view from x = 4.4 and out of a
 * 60-degree view from x = 0 (atan(4 / 5) = 38.7 > 30 degrees). With
 * ../shared, q3vis runs on an OpenArena level against the gt method. */
#include "ground_truth.h"
#include "method.h"
#include "procedural.h"
#include "q3vis.h"
#include "rng.h"
#include "test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 320u
#define H 180u

static rnd_context* g_rnd;

typedef struct loaded {
    scn_scene scene;
    rnd_gpu_scene* gpu;
} loaded;

static bool load(const char* spec, loaded* l)
{
    char err[512];
    if (!scn_load(spec, &l->scene, err, sizeof err) || !(l->gpu = rnd_scene_create(g_rnd, &l->scene, err, sizeof err))) {
        fprintf(stderr, "%s\n", err);
        return false;
    }
    return true;
}

static loaded g_unit;  /* builtin:unit */
static uint8_t* g_mask; /* one byte per triangle of g_unit */

static void unload(loaded* l)
{
    rnd_scene_destroy(g_rnd, l->gpu);
    scn_scene_free(&l->scene);
}

static pvs_request unit_request(float x0, float delta)
{
    pvs_request r = {.vc = {.v0 = {x0, 1.5f, 0.0f}, .forward = {0, 0, -1}, .up = {0, 1, 0}, .delta = delta,
                            .fov_target_deg = 60.0f, .fov_pvs_deg = 90.0f}};
    r.vc.z = delta / tanf(0.25f * 3.14159265f);
    for (int i = 0; i < 3; i++) {
        r.vc.apex[i] = r.vc.v0[i] - r.vc.z * r.vc.forward[i];
        r.current.p[i] = r.vc.v0[i];
    }
    r.current.q[3] = 1.0; /* identity: looking down -Z, the viewcell axis */
    return r;
}

static pvs_method* create(const loaded* l, pvs_method_desc d)
{
    char err[512] = "";
    if (!d.width) {
        d.width = W;
        d.height = H;
    }
    pvs_method* m = pvs_method_create(&d, g_rnd, &l->scene, l->gpu, err, sizeof err);
    if (!m)
        fprintf(stderr, "create %s: %s\n", pvs_method_name(d.kind), err);
    TV_CHECK(m != NULL);
    return m;
}

/* Runs a method into a byte mask; checks that the list is sorted and unique. */
static bool compute(pvs_method* m, const loaded* l, const pvs_request* req, uint8_t* mask, pvs_method_stats* st)
{
    char err[512] = "";
    uint32_t* ids = NULL;
    uint32_t n = 0;
    bool ok = pvs_method_compute(m, req, &ids, &n, st, err, sizeof err);
    if (!ok)
        fprintf(stderr, "compute %s: %s\n", pvs_method_name(pvs_method_kind_of(m)), err);
    TV_CHECK(ok);
    memset(mask, 0, l->scene.triangle_count);
    for (uint32_t i = 0; i < n; i++) {
        TV_CHECK(ids[i] < l->scene.triangle_count && (i == 0 || ids[i] > ids[i - 1]));
        if (ids[i] < l->scene.triangle_count)
            mask[ids[i]] = 1;
    }
    free(ids);
    return ok;
}

static uint32_t count_of(const loaded* l, const uint8_t* mask)
{
    uint32_t n = 0;
    for (uint32_t t = 0; t < l->scene.triangle_count; t++)
        n += mask[t];
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

/* Marks the ids of a full render from cam (W x H) in mask (cleared first). */
static void render_ids(const loaded* l, const rnd_camera* cam, uint8_t* mask)
{
    char err[256];
    rnd_target* t = rnd_target_create(g_rnd, W, H, err, sizeof err);
    uint32_t* ids = malloc(sizeof(uint32_t) * W * H);
    TV_CHECK(t && rnd_draw(g_rnd, t, l->gpu, cam, NULL, 0, NULL) && rnd_target_read_ids(g_rnd, t, ids));
    memset(mask, 0, l->scene.triangle_count);
    for (uint32_t i = 0; i < W * H; i++)
        if (ids[i] < l->scene.triangle_count)
            mask[ids[i]] = 1;
    free(ids);
    rnd_target_destroy(g_rnd, t);
}

/* A camera at the viewcell centre with the request's current orientation and
 * vertical FOV fov_y_deg. */
static rnd_camera centre_camera(const pvs_request* req, float fov_y_deg)
{
    rnd_camera cam = {.position = {req->vc.v0[0], req->vc.v0[1], req->vc.v0[2]},
                      .orientation = {(float)req->current.q[0], (float)req->current.q[1], (float)req->current.q[2],
                                      (float)req->current.q[3]},
                      .fov_y_deg = fov_y_deg, .near_m = 0.05f, .far_m = 500.0f};
    return cam;
}

static void test_names(void)
{
    for (int k = 0; k < PVS_METHOD_COUNT; k++) {
        pvs_method_kind back = PVS_METHOD_COUNT;
        TV_CHECK(pvs_method_from_name(pvs_method_name((pvs_method_kind)k), &back) && back == (pvs_method_kind)k);
    }
    pvs_method_kind kind;
    TV_CHECK(strcmp(pvs_method_name(PVS_METHOD_FROMPOINT), "frompoint") == 0);
    TV_CHECK(!pvs_method_from_name("TR", &kind) && !pvs_method_from_name("", &kind) && !pvs_method_from_name(NULL, &kind));
}

static void test_gt(void)
{
    loaded* unit = &g_unit;
    uint8_t* mask = g_mask;
    pvs_method* m = create(unit, (pvs_method_desc){.kind = PVS_METHOD_GT, .gt_samples = 48});
    pvs_request req = unit_request(4.4f, 0.1f); /* eyes reach x = 4.5 < 4.638 */
    pvs_method_stats st;
    TV_CHECK(compute(m, unit, &req, mask, &st));
    TV_CHECK(any_in(mask, "wall") && any_in(mask, "box_c") && any_in(mask, "ground"));
    TV_CHECK(!any_in(mask, "box_b"));
    TV_CHECK(st.views == 48 && st.total_ms > 0.0);
    printf("  gt: %u triangles from %u views in %.1f ms\n", count_of(unit, mask), st.views, st.total_ms);
    /* the same cameras as pvs_evaluate's ground truth for the same settings: the same set
     * (only its gt_mask matters here, not the PVS renders it also makes) */
    uint8_t* eval_gt = malloc(unit->scene.triangle_count);
    pvs_eval_desc ed = {.samples = 48, .width = W, .height = H};
    pvs_eval_result r;
    char err[256] = "";
    TV_CHECK(pvs_evaluate(g_rnd, unit->gpu, &unit->scene, &req.vc, mask, NULL, 0, &ed, eval_gt, &r, err, sizeof err));
    TV_CHECK(memcmp(mask, eval_gt, unit->scene.triangle_count) == 0 && r.samples == 48);
    free(eval_gt);
    pvs_method_destroy(m);
}

static void test_sas(void)
{
    loaded* unit = &g_unit;
    uint8_t* mask = g_mask;
    uint8_t* one = malloc(unit->scene.triangle_count);
    pvs_method* m = create(unit, (pvs_method_desc){.kind = PVS_METHOD_SAS});
    pvs_request req = unit_request(4.4f, 0.1f);
    pvs_method_stats st;
    TV_CHECK(compute(m, unit, &req, mask, &st));
    TV_CHECK(st.views == 3); /* ceil(0.1 / 0.05) + 1 */
    /* no motion: every sample is v0, so the union is that one view (PVS FOV
     * on the smaller, vertical axis) */
    rnd_camera cam = centre_camera(&req, 90.0f);
    render_ids(unit, &cam, one);
    TV_CHECK(memcmp(mask, one, unit->scene.triangle_count) == 0);
    TV_CHECK(!any_in(mask, "box_b"));
    /* moving 1.2 m along +x over the window: the last sample, at x = 5.0, looks past the wall */
    req.motion[0] = 1.2;
    TV_CHECK(compute(m, unit, &req, mask, &st));
    TV_CHECK(any_in(mask, "box_b"));
    for (uint32_t t = 0; t < unit->scene.triangle_count; t++)
        TV_CHECK(mask[t] >= one[t]); /* the middle sample is still v0 */
    pvs_method_destroy(m);
    free(one);
}

static void test_frompoint(void)
{
    loaded* unit = &g_unit;
    uint8_t* mask = g_mask;
    uint8_t* full = malloc(unit->scene.triangle_count);
    pvs_method* m = create(unit, (pvs_method_desc){.kind = PVS_METHOD_FROMPOINT});
    pvs_request req = unit_request(0.0f, 0.1f);
    pvs_method_stats st;
    TV_CHECK(compute(m, unit, &req, mask, &st));
    TV_CHECK(st.views == 1);
    /* conservative at the pose: everything a full render there shows */
    rnd_camera cam = centre_camera(&req, rnd_fov_y_from_x(60.0f, (float)W / H));
    render_ids(unit, &cam, full);
    uint32_t missing = 0;
    for (uint32_t t = 0; t < unit->scene.triangle_count; t++)
        missing += full[t] && !mask[t];
    TV_CHECK(missing == 0);
    TV_CHECK(any_in(mask, "wall") && !any_in(mask, "box_b") && !any_in(mask, "box_c"));
    printf("  frompoint: %u triangles, %u in the full render\n", count_of(unit, mask), count_of(unit, full));

    /* from x = 4.4 box C is ahead (B, hidden by W's corner with a few pixels
     * to spare, may pass the coarse HiZ levels: conservative, not exact) */
    req = unit_request(4.4f, 0.1f);
    TV_CHECK(compute(m, unit, &req, mask, &st));
    TV_CHECK(any_in(mask, "box_c"));

    /* a request without a current pose is refused, naming the method */
    req.current.q[3] = 0.0;
    uint32_t* ids = NULL;
    uint32_t n = 0;
    char err[256] = "";
    TV_CHECK(!pvs_method_compute(m, &req, &ids, &n, NULL, err, sizeof err) && ids == NULL);
    TV_CHECK(strncmp(err, "frompoint: ", 11) == 0);
    pvs_method_destroy(m);
    free(full);
}

/* The same conservativeness on the 150k-triangle city, where the HiZ levels
 * are exercised by thousands of small, partly hidden triangles. */
static void test_frompoint_city(void)
{
    loaded city = {0};
    TV_CHECK(load("builtin:city", &city));
    if (!city.gpu)
        return;
    uint8_t* mask = malloc(city.scene.triangle_count);
    uint8_t* full = malloc(city.scene.triangle_count);
    pvs_method* m = create(&city, (pvs_method_desc){.kind = PVS_METHOD_FROMPOINT});
    pvs_request req = unit_request(0.0f, 0.1f);
    float eye[3] = {18.3f, 1.7f, 0.0f}; /* on the city-walk path's street, looking down it (-X) */
    for (int k = 0; k < 3; k++)
        req.current.p[k] = req.vc.v0[k] = eye[k];
    pred_quat_from_ypr(0.5 * PRED_PI, 0.0, 0.0, req.current.q);
    pvs_method_stats st;
    TV_CHECK(compute(m, &city, &req, mask, &st));
    rnd_camera cam = centre_camera(&req, rnd_fov_y_from_x(60.0f, (float)W / H));
    render_ids(&city, &cam, full);
    uint32_t missing = 0, visible = count_of(&city, full), kept = count_of(&city, mask);
    for (uint32_t t = 0; t < city.scene.triangle_count; t++)
        missing += full[t] && !mask[t];
    printf("  frompoint city: %u of %u triangles kept, %u in the full render, %u missing, %.1f ms\n", kept,
           city.scene.triangle_count, visible, missing, st.total_ms);
    TV_CHECK(visible > 100 && missing == 0 && kept < city.scene.triangle_count / 10);
    pvs_method_destroy(m);
    free(mask);
    free(full);
    unload(&city);
}

/* The wrapper hands pvs_compute the same viewcell (far plane included) and
 * returns the same ids. */
static void test_tr(void)
{
    loaded* unit = &g_unit;
    uint8_t* mask = g_mask;
    pvs_method* m = create(unit, (pvs_method_desc){.kind = PVS_METHOD_TR, .far_m = 80.0f});
    pvs_request req = unit_request(4.4f, 0.1f);
    pvs_method_stats st;
    TV_CHECK(compute(m, unit, &req, mask, &st));
    TV_CHECK(st.tr.layers > 0 && st.tr.total_ms > 0.0);
    char err[512] = "";
    pvs_context* ctx = pvs_create(g_rnd, &unit->scene, unit->gpu, &(pvs_desc){.width = W, .height = H}, err, sizeof err);
    TV_CHECK(ctx != NULL);
    pvs_viewcell vc = {.v0 = {4.4f, 1.5f, 0.0f}, .forward = {0, 0, -1}, .up = {0, 1, 0}, .delta = 0.1f,
                       .fov_target_deg = 60.0f, .fov_pvs_deg = 90.0f, .far_m = 80.0f};
    pvs_result r;
    TV_CHECK(ctx && pvs_compute(ctx, &vc, &r, err, sizeof err));
    if (ctx) {
        TV_CHECK(r.count == count_of(unit, mask));
        for (uint32_t i = 0; i < r.count; i++)
            TV_CHECK(mask[r.ids[i]]);
    }
    TV_CHECK(any_in(mask, "wall") && any_in(mask, "box_c"));
    printf("  tr: %u triangles in %.1f ms (%u layers)\n", count_of(unit, mask), st.total_ms, st.tr.layers);
    pvs_destroy(ctx);
    pvs_method_destroy(m);
}

/* The all-directions PVS (pred_viewcell.frusta > 1) from v0 = (0, 1.5, -6.5),
 * between W (behind v0) and B (ahead), with C off to the side and behind:
 * the frustum about forward (-Z) alone sees B and the ground, never W or C.
 * The union of the six faces' tr PVSs must hold every triangle any eye of
 * the cell sees in any direction. */
static void test_tr_all_directions(void)
{
    loaded* unit = &g_unit;
    pred_pose heads[3]; /* a half turn over the window: too much for one frustum */
    for (int i = 0; i < 3; i++) {
        heads[i] = (pred_pose){.p = {0, 1.5, -6.5}};
        pred_quat_from_ypr((i - 1) * 0.5 * PRED_PI, 0, 0, heads[i].q);
    }
    float fov_y = rnd_fov_y_from_x(60.0f, (float)W / (float)H);
    pvs_request req = {.eye_fov_h_deg = 60.0f};
    pred_viewcell_from_poses(&(pred_viewcell_desc){.policy = PRED_POLICY_ADAPTIVE, .display_fov_v_deg = fov_y}, heads,
                             3, 1, 0.05, 2.0, &req.vc);
    TV_CHECK(req.vc.frusta == PRED_VC_OMNI_FRUSTA);
    pvs_method* m = create(unit, (pvs_method_desc){.kind = PVS_METHOD_TR, .tr = {.width = 128, .height = 128},
                                                   .far_m = 80.0f});
    uint32_t tris = unit->scene.triangle_count;
    uint8_t *omni = malloc(tris), *front = malloc(tris);
    pvs_method_stats st;
    TV_CHECK(compute(m, unit, &req, omni, &st) && st.frusta == PRED_VC_OMNI_FRUSTA);
    pvs_request one = req;
    pred_viewcell_frustum(&req.vc, 0, &one.vc);
    TV_CHECK(compute(m, unit, &one, front, &st) && st.frusta == 1);
    printf("  tr all directions: %u triangles (%u in the front frustum alone) of %u\n", count_of(unit, omni),
           count_of(unit, front), tris);
    TV_CHECK(any_in(front, "box_b") && !any_in(front, "wall") && !any_in(front, "box_c"));
    TV_CHECK(any_in(omni, "box_b") && any_in(omni, "wall") && any_in(omni, "box_c"));
    for (uint32_t t = 0; t < tris; t++)
        TV_CHECK(!front[t] || omni[t]);
    /* eyes anywhere in the ball the cell was sized for: the first 8 yaw around
     * the horizon in 45-degree steps, then random orientations */
    tv_rng rng;
    tv_rng_seed(&rng, 7, 8);
    double radius = req.vc.delta * cos(PRED_VC_OMNI_HALF_DEG * PRED_DEG) * 0.999;
    int missing = 0;
    bool saw_wall = false, saw_c = false;
    for (int v = 0; v < 40; v++) {
        double p[3], q[4], r2;
        do {
            r2 = 0;
            for (int k = 0; k < 3; k++) {
                p[k] = tv_rng_range(&rng, -1, 1);
                r2 += p[k] * p[k];
            }
        } while (r2 > 1.0);
        for (int k = 0; k < 3; k++)
            p[k] = req.vc.v0[k] + radius * p[k];
        if (v < 8)
            pred_quat_from_ypr(v * 0.25 * PRED_PI, 0, 0, q);
        for (int k = 0; v >= 8 && k < 4; k++)
            q[k] = tv_rng_range(&rng, -1, 1);
        pred_quat_normalize(q);
        TV_CHECK(pred_viewcell_contains(&req.vc, p, q, 60.0f, fov_y, NULL));
        rnd_camera cam = {.position = {(float)p[0], (float)p[1], (float)p[2]},
                          .orientation = {(float)q[0], (float)q[1], (float)q[2], (float)q[3]},
                          .fov_y_deg = fov_y, .near_m = 0.05f, .far_m = 80.0f};
        render_ids(unit, &cam, g_mask);
        for (uint32_t t = 0; t < tris; t++)
            missing += g_mask[t] && !omni[t];
        saw_wall |= any_in(g_mask, "wall");
        saw_c |= any_in(g_mask, "box_c");
    }
    printf("  40 views in every direction: %d visible triangles missing from the union\n", missing);
    TV_CHECK(missing == 0 && saw_wall && saw_c);
    free(omni);
    free(front);
    pvs_method_destroy(m);
}

static void test_bad_input(void)
{
    loaded* unit = &g_unit;
    char err[512] = "";
    pvs_method_desc d = {.kind = PVS_METHOD_Q3VIS, .q3vis_file = "/nonexistent/level.pvs.json"};
    TV_CHECK(pvs_method_create(&d, g_rnd, &unit->scene, unit->gpu, err, sizeof err) == NULL);
    TV_CHECK(strstr(err, "/nonexistent/level.pvs.json: cannot open") != NULL);
    d.q3vis_file = NULL;
    TV_CHECK(pvs_method_create(&d, g_rnd, &unit->scene, unit->gpu, err, sizeof err) == NULL);
    TV_CHECK(strstr(err, "q3vis") != NULL);

    pvs_method* m = create(unit, (pvs_method_desc){.kind = PVS_METHOD_SAS});
    pvs_request req = unit_request(0.0f, 0.1f);
    req.vc.fov_pvs_deg = 0.0f;
    uint32_t* ids = NULL;
    uint32_t n = 0;
    TV_CHECK(!pvs_method_compute(m, &req, &ids, &n, NULL, err, sizeof err) && strstr(err, "sas: ") == err);
    req = unit_request(0.0f, 0.1f);
    req.vc.v0[1] = NAN;
    TV_CHECK(!pvs_method_compute(m, &req, &ids, &n, NULL, err, sizeof err) && strstr(err, "non-finite"));
    pvs_method_destroy(m);
}

/* An OpenArena level: the level compiler's cluster PVS for a viewcell in the
 * middle of a cluster leaf holds (nearly) every triangle dense sampling sees
 * there: q3vis is conservative by construction, up to leaf-box rounding. */
static void test_q3vis_level(void)
{
    const char* shared = getenv("TRIMVR_SHARED");
    char glb[1024], json[1024];
    snprintf(glb, sizeof glb, "%s/scenes/openarena/oa_dm5/oa_dm5.gltf", shared ? shared : "");
    snprintf(json, sizeof json, "%s/scenes/openarena/oa_dm5/oa_dm5.pvs.json", shared ? shared : "");
    loaded l = {0};
    pvs_q3vis vis = {0};
    char err[512];
    FILE* present = fopen(json, "rb");
    if (!shared || !present) {
        TV_TEST_SKIP("the shared oa_dm5 level is absent");
        return;
    }
    fclose(present);
    TV_CHECK(pvs_q3vis_load(json, &vis, err, sizeof err));
    if (!vis.leaves) {
        fprintf(stderr, "%s\n", err);
        return;
    }
    /* the largest leaf of a cluster that sees at least 20 others: room for
     * the whole viewcell, inside the playable level (the largest leaves of
     * all lie outside it, seeing only a couple of clusters) */
    const pvs_q3vis_leaf* best = NULL;
    float best_vol = 0.0f;
    for (uint32_t i = 0; i < vis.leaf_count; i++) {
        const pvs_q3vis_leaf* lf = &vis.leaves[i];
        float vol = (lf->max[0] - lf->min[0]) * (lf->max[1] - lf->min[1]) * (lf->max[2] - lf->min[2]);
        uint32_t sees = 0;
        for (uint32_t c = 0; lf->cluster >= 0 && c < vis.n_clusters; c++)
            sees += pvs_q3vis_sees(&vis, (uint32_t)lf->cluster, c);
        if (sees >= 20 && vol > best_vol) {
            best = lf;
            best_vol = vol;
        }
    }
    TV_CHECK(best != NULL && load(glb, &l));
    if (!best || !l.gpu) {
        pvs_q3vis_free(&vis);
        return;
    }
    pvs_request req = unit_request(0.0f, 0.1f);
    for (int k = 0; k < 3; k++)
        req.vc.v0[k] = 0.5f * (best->min[k] + best->max[k]);
    uint8_t* gt = malloc(l.scene.triangle_count);
    uint8_t* q3 = malloc(l.scene.triangle_count);
    pvs_method* mg = create(&l, (pvs_method_desc){.kind = PVS_METHOD_GT, .gt_samples = 32});
    pvs_method* mq = create(&l, (pvs_method_desc){.kind = PVS_METHOD_Q3VIS, .q3vis_file = json});
    pvs_method_stats st, st_q3;
    TV_CHECK(mg && mq && compute(mg, &l, &req, gt, &st) && compute(mq, &l, &req, q3, &st_q3));
    uint32_t missed = 0, gtc = count_of(&l, gt), q3c = count_of(&l, q3);
    for (uint32_t t = 0; t < l.scene.triangle_count; t++)
        missed += gt[t] && !q3[t];
    printf("  q3vis oa_dm5: %u of %u triangles in %.2f ms; gt %u (%.0f ms), of which q3vis misses %u\n", q3c,
           l.scene.triangle_count, st_q3.total_ms, gtc, st.total_ms, missed);
    TV_CHECK(gtc > 0 && q3c > gtc && q3c < l.scene.triangle_count);
    TV_CHECK(missed <= gtc / 100);

    /* a viewcell far outside the level lies in no cluster: refused with the reason */
    req.vc.v0[1] = 1e4f;
    uint32_t* ids = NULL;
    uint32_t n = 0;
    TV_CHECK(!pvs_method_compute(mq, &req, &ids, &n, NULL, err, sizeof err) && strstr(err, "lies in no cluster"));
    pvs_method_destroy(mg);
    pvs_method_destroy(mq);
    free(gt);
    free(q3);
    unload(&l);
    pvs_q3vis_free(&vis);
}

int main(void)
{
    char err[256];
    g_rnd = rnd_create(NULL, err, sizeof err);
    if (!g_rnd) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    if (!load("builtin:unit", &g_unit))
        return 1;
    g_mask = malloc(g_unit.scene.triangle_count);
    TV_TEST_RUN(test_names);
    TV_TEST_RUN(test_gt);
    TV_TEST_RUN(test_sas);
    TV_TEST_RUN(test_frompoint);
    TV_TEST_RUN(test_frompoint_city);
    TV_TEST_RUN(test_tr);
    TV_TEST_RUN(test_tr_all_directions);
    TV_TEST_RUN(test_bad_input);
    TV_TEST_RUN(test_q3vis_level);
    unload(&g_unit);
    free(g_mask);
    TV_CHECK(rnd_validation_message_count(g_rnd) == 0);
    rnd_destroy(g_rnd);
    return tv_test_finish();
}
