/* test_pvs_gpu.c - the GPU trim-region PVS end to end: occlusion with a
 * derived parallax threshold, false negatives against id-buffer renders
 * (none at all against a render from the apex v* at the PVS resolution;
 * bounded against eyes sampled in the double-cone viewcell, whose pixel
 * centres sample directions the PVS raster does not), polygon soups with
 * non-manifold edges, and k-buffer overflow.
 *
 * (The fixture and shared checks: pvs_gpu_fixture.h; the constructed
 * occluder configurations: test_pvs_gpu_cases.c.) */
#include "pvs_gpu_checks.h"

#include <cglm/cglm.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Does the segment p -> q miss the box [lo, hi]? (slab test) */
static bool segment_clear(const float p[3], const float q[3], const float lo[3], const float hi[3])
{
    float t0 = 0.0f, t1 = 1.0f;
    for (int i = 0; i < 3; i++) {
        float d = q[i] - p[i];
        if (fabsf(d) < 1e-9f) {
            if (p[i] < lo[i] || p[i] > hi[i])
                return true;
            continue;
        }
        float a = (lo[i] - p[i]) / d, b = (hi[i] - p[i]) / d;
        t0 = fmaxf(t0, fminf(a, b));
        t1 = fminf(t1, fmaxf(a, b));
    }
    return t0 > t1;
}

/* Whether some eye on the double cone of radius delta around (0, 1.5, 0)
 * sees a point of B's visible faces past W (the ground cannot block a
 * segment between points above it). */
static bool b_seen(float delta)
{
    const float wlo[3] = {-2, 0, -5.1f}, whi[3] = {2, 3, -5};
    float z = delta; /* tan 45 = 1 */
    for (int ia = -20; ia <= 20; ia++) {
        float a = z * (float)ia / 20.0f, r = delta * (1.0f - fabsf((float)ia) / 20.0f);
        for (int k = 0; k < 64; k++) {
            float th = (float)k * 2.0f * GLM_PIf / 64.0f;
            float eye[3] = {r * cosf(th), 1.5f + r * sinf(th), -a};
            for (int u = 0; u <= 10; u++) {
                for (int v = 0; v <= 10; v++) {
                    float s = (float)u / 10.0f, t = (float)v / 10.0f;
                    const float pts[3][3] = {{-0.5f + s, t, -7.0f},   /* front face */
                                             {-0.5f + s, 1.0f, -7.0f - t}, /* top */
                                             {0.5f, s, -7.0f - t}};   /* side (mirror-symmetric) */
                    for (int p = 0; p < 3; p++) {
                        if (segment_clear(eye, pts[p], wlo, whi))
                            return true;
                    }
                }
            }
        }
    }
    return false;
}

static float b_threshold(void)
{
    float lo = 0.0f, hi = 10.0f;
    for (int i = 0; i < 14; i++) {
        float mid = 0.5f * (lo + hi);
        if (b_seen(mid))
            hi = mid;
        else
            lo = mid;
    }
    return hi;
}

static void test_unit_wall_hides_box(void)
{
    fixture f = {0};
    load(&f, "builtin:unit", 0);
    uint32_t b0, bn, c0, cn, w0, wn;
    TV_CHECK(scn_unit_object("box_b", &b0, &bn) && scn_unit_object("box_c", &c0, &cn) &&
             scn_unit_object("wall", &w0, &wn));
    float threshold = b_threshold();
    printf("  parallax threshold for B: delta = %.3f m\n", threshold);
    TV_CHECK(threshold > 1.0f && threshold < 9.0f);

    pvs_result r;
    pvs_viewcell vc;
    uint32_t at_v0, worst;
    /* hidden well below the threshold (measured: B enters between 0.5 and
     * 0.75 m, the trim regions being conservative) */
    const float hidden[2] = {0.1f, 0.3f};
    for (int i = 0; i < 2; i++) {
        vc = viewcell(0.0f, 1.5f, 0.0f, hidden[i]);
        TV_CHECK(compute(&f, &vc, &r));
        TV_CHECK(count_in_range(&r, b0, bn) == 0);
        TV_CHECK(count_in_range(&r, c0, cn) > 0);
        TV_CHECK(count_in_range(&r, w0, wn) > 0);
        TV_CHECK(apex_fn(&f, &r, &vc) == 0);
        worst = cone_fn(&f, &r, &vc, &at_v0);
        TV_CHECK(at_v0 == 0);
        TV_CHECK(worst <= fn_bound(FN_SIMPLE));
    }

    vc.delta = 1.2f * threshold; /* B is truly visible from part of the viewcell */
    TV_CHECK(compute(&f, &vc, &r));
    TV_CHECK(count_in_range(&r, b0, bn) > 0);
    TV_CHECK(apex_fn(&f, &r, &vc) == 0);
    worst = cone_fn(&f, &r, &vc, &at_v0);
    TV_CHECK(at_v0 == 0 && worst <= fn_bound(FN_SIMPLE));
    fixture_close(&f);
}

/* ---- builtin:city: ground truth in a street ---- */

static void test_city_no_false_negatives(void)
{
    fixture f = {0};
    load(&f, "builtin:city?tris=20000", 0);
    const float deltas[2] = {0.05f, 0.2f};
    for (int i = 0; i < 2; i++) {
        pvs_result r;
        pvs_viewcell vc = viewcell(0.0f, 1.7f, 30.0f, deltas[i]);
        TV_CHECK(compute(&f, &vc, &r));
        TV_CHECK(r.count > 0 && r.count < f.scene.triangle_count / 2); /* buildings occlude */
        TV_CHECK(r.stats.layers >= 1 && r.stats.active_pixels > 0);
        TV_CHECK(r.stats.idle_resolves == 0); /* pvs_region_activates (before it: 8 and 36) */
        TV_CHECK(apex_fn(&f, &r, &vc) == 0);
        uint32_t at_v0, worst = cone_fn(&f, &r, &vc, &at_v0);
        printf("  FN pixels: %u at v0 (3 renders), worst cone sample %u (bound %u); idle resolves %llu\n", at_v0,
               worst, fn_bound(FN_CITY), (unsigned long long)r.stats.idle_resolves);
        TV_CHECK(at_v0 <= 3 * fn_bound(FN_CITY));
        TV_CHECK(worst <= fn_bound(FN_CITY));
    }
    fixture_close(&f);
}

/* ---- polygon soup: non-manifold fins and open quads still occlude ---- */

static void test_soup_nonmanifold(void)
{
    fixture f = {0};
    fx_scene_init(&f.scene, 64, 1);
    uint32_t m = fx_material(&f.scene, 0.8f, 0.8f, 0.8f, SCN_ALPHA_OPAQUE, false, -1);
    soup_box(&f.scene, (float[3]){-3, -2, -6.2f}, (float[3]){3, 2, -6}, m);
    /* fins on the top front edge and the left front edge: three triangles
     * per edge, i.e. non-manifold */
    const float fin_top[4][3] = {{-3, 2, -6}, {3, 2, -6}, {3, 2.5f, -5.5f}, {-3, 2.5f, -5.5f}};
    const float fin_left[4][3] = {{-3, 2, -6}, {-3, -2, -6}, {-3.5f, -2, -5.5f}, {-3.5f, 2, -5.5f}};
    fx_quad(&f.scene, fin_top, m);
    fx_quad(&f.scene, fin_left, m);
    /* a single-sided open quad floating in front, and the hidden box */
    fx_quad_z(&f.scene, 1.0f, -1.5f, 1.6f, -0.9f, -3.0f, m);
    uint32_t hidden = f.scene.triangle_count;
    soup_box(&f.scene, (float[3]){-0.5f, -0.5f, -12.0f}, (float[3]){0.5f, 0.5f, -11.0f}, m);
    pvs_result r;
    pvs_viewcell vc;
    compute_at_origin(&f, 0.05f, &vc, &r);
    TV_CHECK(count_in_range(&r, hidden, 12) == 0);
    TV_CHECK(count_in_range(&r, 0, 2) == 2); /* the wall's front face */
    check_fn(&f, &r, &vc, FN_SIMPLE);
    fixture_close(&f);
}

/* ---- alpha mask: the hole of a masked occluder lets its occludee in ---- */

static void test_alpha_masked_hole(void)
{
    fixture f = {0};
    fx_scene_init(&f.scene, 64, 2);
    /* 4x1 texels, alpha 255 0 0 255: the middle half of every quad is a
     * hole, symmetric in u so the back face's hole lines up with the front's */
    f.scene.textures = calloc(1, sizeof(scn_texture));
    f.scene.textures[0] = (scn_texture){.width = 4, .height = 1, .rgba8 = calloc(16, 1)};
    for (int i = 0; i < 4; i++) {
        memset(f.scene.textures[0].rgba8 + 4 * i, 200, 3);
        f.scene.textures[0].rgba8[4 * i + 3] = i == 0 || i == 3 ? 255 : 0;
    }
    f.scene.texture_count = 1;
    uint32_t masked = fx_material(&f.scene, 1, 1, 1, SCN_ALPHA_MASK, false, 0);
    uint32_t opaque = fx_material(&f.scene, 0.8f, 0.8f, 0.8f, SCN_ALPHA_OPAQUE, false, -1);
    /* a thin closed wall x in [-2, 2] whose front and back faces are masked
     * (hole x in [-1, 1]), opaque sides */
    const float x0 = -2, x1 = 2, y0 = -1, y1 = 1, zf = -3, zb = -3.1f;
    const float front[4][3] = {{x0, y0, zf}, {x1, y0, zf}, {x1, y1, zf}, {x0, y1, zf}};
    const float back[4][3] = {{x1, y0, zb}, {x0, y0, zb}, {x0, y1, zb}, {x1, y1, zb}};
    fx_quad(&f.scene, front, masked);
    fx_quad(&f.scene, back, masked);
    const float sides[4][4][3] = {
        {{x1, y0, zf}, {x1, y0, zb}, {x1, y1, zb}, {x1, y1, zf}},
        {{x0, y0, zb}, {x0, y0, zf}, {x0, y1, zf}, {x0, y1, zb}},
        {{x0, y1, zf}, {x1, y1, zf}, {x1, y1, zb}, {x0, y1, zb}},
        {{x0, y0, zb}, {x1, y0, zb}, {x1, y0, zf}, {x0, y0, zf}},
    };
    for (int i = 0; i < 4; i++)
        fx_quad(&f.scene, sides[i], opaque);
    uint32_t through = f.scene.triangle_count;
    soup_box(&f.scene, (float[3]){-0.3f, -0.3f, -9}, (float[3]){0.3f, 0.3f, -8}, opaque);
    uint32_t behind = f.scene.triangle_count; /* seen through the opaque part only from >= 0.3 m aside */
    soup_box(&f.scene, (float[3]){-4.5f, -0.3f, -9}, (float[3]){-3.5f, 0.3f, -8}, opaque);
    scn_scene_update_bounds(&f.scene);
    fixture_open(&f, 0);

    pvs_result r;
    pvs_viewcell vc = viewcell(0.0f, 0.0f, 0.0f, 0.05f);
    TV_CHECK(compute(&f, &vc, &r));
    TV_CHECK(count_in_range(&r, through, 12) > 0);
    TV_CHECK(count_in_range(&r, behind, 12) == 0);
    TV_CHECK(apex_fn(&f, &r, &vc) == 0);
    uint32_t at_v0, worst = cone_fn(&f, &r, &vc, &at_v0);
    printf("  FN pixels: %u at v0 (3 renders), worst cone sample %u\n", at_v0, worst);
    TV_CHECK(at_v0 == 0);
    TV_CHECK(worst <= fn_bound(FN_SIMPLE));
    fixture_close(&f);
}

/* ---- constructed occluder configurations (issue: known answers) ---- */

/* Bumps of +-4 mm at the grid points of the wall below. */
static float bump(int i, int j)
{
    return 0.004f * (float)((i * 7 + j * 13) % 3 - 1);
}

/* A 6 x 3 m wall 12 m away made of 5 cm cells with +-4 mm bumps (the
 * mouldings of Sponza): at 0.5 degrees per PVS pixel (10 cm there) its
 * triangles are sub-pixel, so a pixel centre lands on one triangle of the
 * four or more touching the pixel, and an eye's pixel centres on others.
 * Nothing occludes the wall, so any missing triangle is a hole in an eye's
 * render. The exact pass covers few of them; the rest must come from the
 * dilated pass, where a triangle touching the pixel ties in depth with the
 * face covering the centre (until 2026-11-23 only triangles entirely in
 * front of that face were taken: 5,344 of the 14,400 triangles, 4,756 FN
 * pixels over the three v0 renders, 1,623 at the worst cone sample). */
static void test_fine_tessellation(void)
{
    enum { NX = 120, NY = 60 };
    const float cell = 0.05f, x0 = -3.0f, y0 = -1.5f, z = -12.0f;
    fixture f = {0};
    fx_scene_init(&f.scene, NX * NY, 1);
    uint32_t m = fx_material(&f.scene, 0.8f, 0.8f, 0.8f, SCN_ALPHA_OPAQUE, false, -1);
    for (int j = 0; j < NY; j++) {
        for (int i = 0; i < NX; i++) {
            const float q[4][3] = {
                {x0 + cell * i, y0 + cell * j, z + bump(i, j)},
                {x0 + cell * (i + 1), y0 + cell * j, z + bump(i + 1, j)},
                {x0 + cell * (i + 1), y0 + cell * (j + 1), z + bump(i + 1, j + 1)},
                {x0 + cell * i, y0 + cell * (j + 1), z + bump(i, j + 1)},
            };
            fx_quad(&f.scene, q, m);
        }
    }
    check_configuration(&f, "a bumpy wall of sub-pixel triangles", 0.1f, FN_SIMPLE, NULL, 0, NULL, 0);
}

/* Needles: 40 thin rhombi 60 cm long and 5 mm wide, 12 m away in front of
 * a wall (13 x 0.1 PVS pixels), vertical and tilted, at phases across the
 * pixel grid, so most cover no pixel centre of v*. Each half is a sliver
 * whose corners are almost collinear: two sharp corners and one near 180
 * degrees. Nothing occludes them, so each touches pixels of v*'s image and
 * is visible: all 80 triangles belong in the PVS. Until 2026-11-24 the
 * dilated pass clamped corner offsets to 3 pixels, which leaves the edges at
 * two sharp corners almost undilated: such slivers produced no fragment at
 * all (Sponza's decimated mesh has many; they were most of its
 * false-negative pixels). */
static void test_needles(void)
{
    enum { N = 40 };
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    uint32_t first = f.scene.triangle_count;
    for (int i = 0; i < N; i++) {
        float x = -1.0f + 0.0493f * (float)i, y = -0.3f, tilt = (float)(i % 3 - 1) * 0.25f, h = 0.0025f;
        const float q[4][3] = {{x, y, -12.0f}, {x + 0.5f * tilt + h, y + 0.3f, -12.0f},
                               {x + tilt, y + 0.6f, -12.0f}, {x + 0.5f * tilt - h, y + 0.3f, -12.0f}};
        fx_quad(&f.scene, q, m);
    }
    fx_quad_z(&f.scene, -6.0f, -4.0f, 6.0f, 4.0f, -14.0f, m);
    scn_scene_update_bounds(&f.scene);
    fixture_open(&f, 0);
    pvs_result r;
    pvs_viewcell vc = viewcell(0.0f, 0.0f, 0.0f, 0.05f);
    TV_CHECK(compute(&f, &vc, &r));
    uint32_t in = count_in_range(&r, first, 2 * N);
    printf("  needles in the PVS: %u of %d\n", in, 2 * N);
    TV_CHECK(in == 2 * N);
    fixture_close(&f);
}

/* ---- k = 1: overflow is counted and loses nothing ---- */

static void test_tiny_k_overflow(void)
{
    fixture f = {0};
    load(&f, "builtin:city?tris=20000", 1);
    pvs_result r;
    pvs_viewcell vc = viewcell(0.0f, 1.7f, 30.0f, 0.1f);
    TV_CHECK(compute(&f, &vc, &r));
    TV_CHECK(r.stats.overflow_pixels > 0 && r.stats.overflow_fronts > 0);
    TV_CHECK(apex_fn(&f, &r, &vc) == 0);
    uint32_t at_v0, worst = cone_fn(&f, &r, &vc, &at_v0);
    printf("  FN pixels: %u at v0 (3 renders), worst cone sample %u\n", at_v0, worst);
    TV_CHECK(at_v0 <= 3 * fn_bound(FN_CITY));
    TV_CHECK(worst <= fn_bound(FN_CITY));
    fixture_close(&f);
}

/* Eight boxes behind a wall, sized with their depth so that their
 * silhouettes coincide in the image: the pixels along them get more trims
 * than k = 4 holds. All the lost trims lie behind the wall, so they cannot
 * have eroded it: the wall still seals those pixels and every box is
 * culled. Until 2026-11-24 a lost trim made every interval of the pixel
 * count as validated, and the boxes' fronts were output there. */
static void test_trims_lost_behind_a_wall(void)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    add_box(&f.scene, -3.0f, -2.0f, -6.2f, 3.0f, 2.0f, -6.0f, m);
    uint32_t first = f.scene.triangle_count;
    for (int i = 0; i < 8; i++) {
        float z = 10.0f + (float)i, h = 0.05f * z;
        add_box(&f.scene, -h, -h, -z - 0.1f, h, h, -z, m);
    }
    scn_scene_update_bounds(&f.scene);
    fixture_open(&f, 4);
    pvs_result r;
    pvs_viewcell vc = viewcell(0.0f, 0.0f, 0.0f, 0.1f);
    TV_CHECK(compute(&f, &vc, &r));
    TV_CHECK(r.stats.overflow_pixels > 0);
    uint32_t boxes = count_in_range(&r, first, 8 * 12);
    printf("  box triangles in the PVS: %u of 96\n", boxes);
    TV_CHECK(boxes == 0);
    TV_CHECK(apex_fn(&f, &r, &vc) == 0);
    fixture_close(&f);
}

/* Eight boxes whose silhouettes coincide in the image, in front of a wall,
 * and a ninth box behind the wall: the pixels along the silhouettes get more
 * fronts and trims than k = 4. Lists of k entries leave those pixels to the
 * overflow policy, which outputs every front there, the hidden box's too;
 * lists of k_deep = 32 resolve them as deep pixels, without umbrae
 * (docs/trim-regions.md, "Overflow policy"): the wall seals them and the
 * hidden box is culled. */
static void test_deep_pixels_resolve(void)
{
    uint32_t hidden[2], overflow[2];
    for (int deep = 0; deep < 2; deep++) {
        fixture f = {.k_deep = deep ? 32 : 0};
        uint32_t m = constructed_scene(&f);
        for (int i = 0; i < 8; i++) {
            float z = 6.0f + (float)i, h = 0.05f * z;
            add_box(&f.scene, -h, -h, -z - 0.1f, h, h, -z, m);
        }
        add_box(&f.scene, -3.0f, -2.0f, -16.2f, 3.0f, 2.0f, -16.0f, m);
        uint32_t first = f.scene.triangle_count;
        add_box(&f.scene, -0.9f, -0.9f, -18.1f, 0.9f, 0.9f, -18.0f, m);
        scn_scene_update_bounds(&f.scene);
        fixture_open(&f, 4);
        pvs_result r;
        pvs_viewcell vc = viewcell(0.0f, 0.0f, 0.0f, 0.1f);
        TV_CHECK(compute(&f, &vc, &r));
        hidden[deep] = count_in_range(&r, first, 12);
        overflow[deep] = r.stats.overflow_pixels;
        TV_CHECK(apex_fn(&f, &r, &vc) == 0);
        fixture_close(&f);
    }
    printf("  hidden box triangles in the PVS: %u at k_deep 0, %u at 32; overflowing pixels %u, %u\n", hidden[0], hidden[1],
           overflow[0], overflow[1]);
    TV_CHECK(overflow[0] > 0 && hidden[0] > 0); /* the case overflows at k = 4 */
    TV_CHECK(overflow[1] < overflow[0] && hidden[1] == 0);
}

/* ---- hybrid sort: per thread or per workgroup, the same PVS ---- */

/* The PVS of the interior's room with every sequence sorted per thread, those
 * of >= 8 entries (the paper's split) and of >= 2 entries by a workgroup.
 * Bitonic sort is not stable, so this fails if two entries that compare
 * equal could differ. k = 32 avoids overflow, whose outcome depends on
 * fragment arrival order. */
static void test_hybrid_sort(void)
{
    const uint32_t mins[3] = {UINT32_MAX, 8, 2};
    uint32_t *ids[3] = {NULL}, counts[3] = {0};
    uint64_t coop[3] = {0}, resolves = 0;
    pvs_viewcell vc = viewcell(-6.0f, 1.7f, 6.5f, 0.1f);
    vc.forward[0] = 1.0f;
    vc.forward[2] = 0.0f;
    for (int i = 0; i < 3; i++) {
        fixture f = {.coop_sort_min = mins[i]};
        load(&f, "builtin:interior", 32);
        pvs_result r;
        TV_CHECK(compute(&f, &vc, &r));
        TV_CHECK(r.stats.overflow_pixels == 0);
        coop[i] = r.stats.coop_pixels;
        resolves = r.stats.active_pixels;
        printf("  coop_sort_min %u: %llu of %llu resolves sorted by a workgroup, mean sequence %.2f\n", mins[i],
               (unsigned long long)coop[i], (unsigned long long)resolves, r.stats.mean_sequence);
        counts[i] = r.count;
        ids[i] = malloc(sizeof(uint32_t) * (r.count ? r.count : 1));
        memcpy(ids[i], r.ids, sizeof(uint32_t) * r.count);
        fixture_close(&f);
    }
    TV_CHECK(coop[0] == 0 && coop[1] > 0 && coop[2] > coop[1] && coop[2] < resolves);
    for (int i = 1; i < 3; i++)
        TV_CHECK(counts[i] == counts[0] && memcmp(ids[i], ids[0], sizeof(uint32_t) * counts[0]) == 0);
    for (int i = 0; i < 3; i++)
        free(ids[i]);
}

/* ---- a worker thread computes while the main thread renders ---- */

typedef struct worker {
    fixture* f;
    pvs_viewcell vc;
    const uint32_t* expected;
    uint32_t expected_count;
    bool ok;
} worker;

static void* worker_main(void* arg)
{
    worker* w = arg;
    w->ok = true;
    for (int i = 0; i < 3; i++) {
        char err[256];
        pvs_result r;
        w->ok = w->ok && pvs_compute(w->f->pvs, &w->vc, &r, err, sizeof err) && r.count == w->expected_count &&
                memcmp(r.ids, w->expected, sizeof(uint32_t) * r.count) == 0;
    }
    return NULL;
}

static void test_worker_thread(void)
{
    fixture f = {0};
    load(&f, "builtin:unit", 0);
    pvs_result r;
    pvs_viewcell vc = viewcell(0.0f, 1.5f, 0.0f, 0.3f);
    TV_CHECK(compute(&f, &vc, &r));
    uint32_t* expected = malloc(sizeof(uint32_t) * (r.count + 1));
    memcpy(expected, r.ids, sizeof(uint32_t) * r.count);
    worker w = {.f = &f, .vc = vc, .expected = expected, .expected_count = r.count};
    pthread_t thread;
    TV_CHECK(pthread_create(&thread, NULL, worker_main, &w) == 0);
    rnd_camera cam = pvs_apex_camera(f.pvs, &vc);
    for (int i = 0; i < 10; i++)
        TV_CHECK(rnd_draw(g_rnd, f.target, f.gpu, &cam, NULL, 0, NULL));
    pthread_join(thread, NULL);
    TV_CHECK(w.ok); /* same ids every time, while rnd_draw ran beside it */
    free(expected);
    fixture_close(&f);
}

static void test_invalid_input(void)
{
    fixture f = {0};
    load(&f, "builtin:unit", 0);
    char err[256] = "";
    pvs_result r;
    pvs_viewcell vc = viewcell(0.0f, 1.5f, 0.0f, 0.1f);
    vc.up[0] = 0, vc.up[1] = 0, vc.up[2] = 2; /* parallel to forward */
    TV_CHECK(!pvs_compute(f.pvs, &vc, &r, err, sizeof err) && strstr(err, "parallel"));
    vc = viewcell(0.0f, 1.5f, 0.0f, NAN);
    TV_CHECK(!pvs_compute(f.pvs, &vc, &r, err, sizeof err) && strstr(err, "non-finite"));
    TV_CHECK(pvs_create(g_rnd, &f.scene, f.gpu, &(pvs_desc){.k = 1000}, err, sizeof err) == NULL &&
             strstr(err, "k = 1000"));
    fixture_close(&f);
}

int main(void)
{
    g_rnd = fx_context();
    TV_TEST_RUN(test_unit_wall_hides_box);
    TV_TEST_RUN(test_soup_nonmanifold);
    TV_TEST_RUN(test_alpha_masked_hole);
    TV_TEST_RUN(test_fine_tessellation);
    TV_TEST_RUN(test_needles);
    TV_TEST_RUN(test_tiny_k_overflow);
    TV_TEST_RUN(test_trims_lost_behind_a_wall);
    TV_TEST_RUN(test_deep_pixels_resolve);
    TV_TEST_RUN(test_hybrid_sort);
    TV_TEST_RUN(test_city_no_false_negatives);
    TV_TEST_RUN(test_worker_thread);
    TV_TEST_RUN(test_invalid_input);
    TV_CHECK(rnd_validation_message_count(g_rnd) == 0);
    rnd_destroy(g_rnd);
    return tv_test_finish();
}
