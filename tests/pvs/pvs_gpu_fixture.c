#include "pvs_gpu_fixture.h"

#include <cglm/cglm.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

rnd_context* g_rnd;

void fixture_open(fixture* f, uint32_t k)
{
    char err[512];
    f->gpu = rnd_scene_create(g_rnd, &f->scene, err, sizeof err);
    f->target = f->gpu ? rnd_target_create(g_rnd, W, H, err, sizeof err) : NULL;
    f->apex_target = f->target ? rnd_target_create(g_rnd, PW, PH, err, sizeof err) : NULL;
    f->pvs = f->apex_target ? pvs_create(g_rnd, &f->scene, f->gpu, &(pvs_desc){.width = PW, .height = PH, .k = k, .octree_cap = f->octree_cap,
                                                              .max_layers = f->max_layers, .k_deep = f->k_deep,
                                                              .coop_sort_min = f->coop_sort_min, .explain = f->explain},
                                         err, sizeof err)
                            : NULL;
    if (!f->pvs) {
        fprintf(stderr, "fixture: %s\n", err);
        exit(1);
    }
    f->depth = malloc(sizeof(float) * PW * PH);
    f->pvs_depth = malloc(sizeof(float) * PW * PH);
}

void fixture_close(fixture* f)
{
    pvs_destroy(f->pvs);
    rnd_target_destroy(g_rnd, f->target);
    rnd_target_destroy(g_rnd, f->apex_target);
    rnd_scene_destroy(g_rnd, f->gpu);
    scn_scene_free(&f->scene);
    free(f->depth);
    free(f->pvs_depth);
}

void load(fixture* f, const char* spec, uint32_t k)
{
    char err[512];
    if (!scn_load(spec, &f->scene, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        exit(1);
    }
    fixture_open(f, k);
}

bool compute(fixture* f, const pvs_viewcell* vc, pvs_result* r)
{
    char err[512];
    bool ok = pvs_compute(f->pvs, vc, r, err, sizeof err);
    if (!ok)
        fprintf(stderr, "pvs_compute: %s\n", err);
    const pvs_stats* s = &r->stats;
    printf("  delta %.3f: %u of %u triangles; %u layers, %u silhouettes, %llu active px, mean seq %.2f, "
           "overflow %llu px / %llu fronts; P0-P4 %.2f %.2f %.2f %.2f %.2f ms\n",
           vc->delta, r->count, f->scene.triangle_count, s->layers, s->silhouettes,
           (unsigned long long)s->active_pixels, s->mean_sequence, (unsigned long long)s->overflow_pixels,
           (unsigned long long)s->overflow_fronts, s->ms[0], s->ms[1], s->ms[2], s->ms[3], s->ms[4]);
    return ok;
}

int compare_u32(const void* a, const void* b)
{
    uint32_t x = *(const uint32_t*)a, y = *(const uint32_t*)b;
    return (x > y) - (x < y);
}

bool in_pvs(const pvs_result* r, uint32_t id)
{
    return bsearch(&id, r->ids, r->count, sizeof(uint32_t), compare_u32) != NULL;
}

uint32_t count_in_range(const pvs_result* r, uint32_t first, uint32_t count)
{
    uint32_t n = 0;
    for (uint32_t t = first; t < first + count; t++)
        n += in_pvs(r, t);
    return n;
}

/* False-negative pixels of `cam` on target t: where a render of the PVS
 * differs in depth from the full render (a missing triangle that ties in
 * depth with one present changes nothing on screen, so it does not count). */
uint32_t diff_pixels(fixture* f, rnd_target* t, const rnd_camera* cam, const pvs_result* r)
{
    uint32_t n = rnd_target_width(t) * rnd_target_height(t);
    if (!rnd_draw(g_rnd, t, f->gpu, cam, NULL, 0, NULL) || !rnd_target_read_depth(g_rnd, t, f->depth) ||
        !rnd_draw(g_rnd, t, f->gpu, cam, r->ids, r->count, NULL) || !rnd_target_read_depth(g_rnd, t, f->pvs_depth))
        return n;
    uint32_t fn = 0;
    for (uint32_t i = 0; i < n; i++)
        fn += f->depth[i] != f->pvs_depth[i];
    return fn;
}

/* FN pixels of a render from `eye` (the viewcell's forward turned by
 * yaw_deg about up; target FOV). */
uint32_t fn_pixels(fixture* f, const pvs_result* r, const pvs_viewcell* vc, const float eye[3], float yaw_deg)
{
    vec3 fwd = {vc->forward[0], vc->forward[1], vc->forward[2]}, up = {vc->up[0], vc->up[1], vc->up[2]};
    glm_vec3_rotate(fwd, glm_rad(yaw_deg), up);
    versor q;
    glm_quat_for(fwd, up, q);
    float aspect = (float)W / (float)H;
    rnd_camera cam = {.fov_y_deg = rnd_fov_y_from_x(vc->fov_target_deg, aspect), .near_m = 0.05f, .far_m = vc->far_m};
    memcpy(cam.position, eye, sizeof cam.position);
    memcpy(cam.orientation, q, sizeof q);
    return diff_pixels(f, f->target, &cam, r);
}

/* FN pixels of a render from the apex v* with the PVS's own frustum and
 * resolution: the PVS raster samples these very pixel centres, so there
 * must be none. */
uint32_t apex_fn(fixture* f, const pvs_result* r, const pvs_viewcell* vc)
{
    rnd_camera cam = pvs_apex_camera(f->pvs, vc);
    return diff_pixels(f, f->apex_target, &cam, r);
}

/* Eye samples of the double cone: v0, then rings at a = 0, +-z/2, +-0.98z
 * along the axis on the cone's surface (radius Δ (1 - |a|/z)). Returns the
 * worst FN pixel count among them; *at_v0 gets v0's (also with the head
 * turned by +-12 degrees, inside the 15-degree rotation margin). */
uint32_t cone_fn(fixture* f, const pvs_result* r, const pvs_viewcell* vc, uint32_t* at_v0)
{
    *at_v0 = fn_pixels(f, r, vc, vc->v0, 0.0f);
    *at_v0 += fn_pixels(f, r, vc, vc->v0, 12.0f) + fn_pixels(f, r, vc, vc->v0, -12.0f);
    vec3 fwd = {vc->forward[0], vc->forward[1], vc->forward[2]}, up = {vc->up[0], vc->up[1], vc->up[2]}, right;
    glm_vec3_normalize(fwd);
    glm_vec3_crossn(fwd, up, right);
    glm_vec3_cross(right, fwd, up);
    float z = vc->delta / tanf(glm_rad(vc->fov_pvs_deg) * 0.5f);
    const float axis[5] = {0.0f, 0.5f, -0.5f, 0.98f, -0.98f};
    uint32_t worst = 0;
    for (int i = 0; i < 5; i++) {
        float a = axis[i] * z, radius = vc->delta * (1.0f - fabsf(axis[i]));
        for (int k = 0; k < 8; k++) {
            float th = (float)k * GLM_PIf / 4.0f, eye[3];
            for (int c = 0; c < 3; c++)
                eye[c] = vc->v0[c] + a * fwd[c] + radius * (cosf(th) * right[c] + sinf(th) * up[c]);
            uint32_t fn = fn_pixels(f, r, vc, eye, 0.0f);
            worst = fn > worst ? fn : worst;
        }
    }
    return worst;
}

/* Bound on FN pixels per eye render, as a fraction of its pixels. */
uint32_t fn_bound(double fraction)
{
    return (uint32_t)(fraction * W * H);
}


pvs_viewcell viewcell(float x, float y, float z, float delta)
{
    return (pvs_viewcell){.v0 = {x, y, z}, .forward = {0, 0, -1}, .up = {0, 1, 0}, .delta = delta,
                          .fov_target_deg = 60.0f, .fov_pvs_deg = 90.0f, .far_m = 100.0f};
}

/* ---- builtin:unit: the wall W hides box B from (0, 1.5, 0) ---- */

/* The first `faces` faces of a box, -y last, as separate quads (a soup:
 * adjacency comes from welding). */
static void box_faces(scn_scene* s, const float lo[3], const float hi[3], uint32_t m, int faces)
{
    float x0 = lo[0], y0 = lo[1], z0 = lo[2], x1 = hi[0], y1 = hi[1], z1 = hi[2];
    const float q[6][4][3] = {
        {{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}}, /* +z */
        {{x1, y0, z0}, {x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}}, /* -z */
        {{x1, y0, z1}, {x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}}, /* +x */
        {{x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0}}, /* -x */
        {{x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0}, {x0, y1, z0}}, /* +y */
        {{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}}, /* -y */
    };
    for (int i = 0; i < faces; i++)
        fx_quad(s, q[i], m);
}

void soup_box(scn_scene* s, const float lo[3], const float hi[3], uint32_t m)
{
    box_faces(s, lo, hi, m, 6);
}

/* A box as a soup, returning its first triangle id (12 triangles). */
uint32_t add_box(scn_scene* s, float x0, float y0, float z0, float x1, float y1, float z1, uint32_t m)
{
    uint32_t first = s->triangle_count;
    soup_box(s, (float[3]){x0, y0, z0}, (float[3]){x1, y1, z1}, m);
    return first;
}

uint32_t add_standing_box(scn_scene* s, float x0, float y0, float z0, float x1, float y1, float z1, uint32_t m)
{
    uint32_t first = s->triangle_count;
    box_faces(s, (float[3]){x0, y0, z0}, (float[3]){x1, y1, z1}, m, 5);
    return first;
}

/* An empty scene with room for a few boxes; returns its grey material. */
/* Single-sided material (glTF's default): the renderer culls its backs. */
uint32_t constructed_scene(fixture* f)
{
    fx_scene_init(&f->scene, 64, 2);
    return fx_material(&f->scene, 0.8f, 0.8f, 0.8f, SCN_ALPHA_OPAQUE, false, -1);
}

/* A second, double-sided material: its backs are drawn, so they are seen
 * and occlude like fronts. */
uint32_t double_sided(fixture* f)
{
    return fx_material(&f->scene, 0.6f, 0.7f, 0.8f, SCN_ALPHA_OPAQUE, true, -1);
}
