/* test_pvs_gpu_dynamic.c - the GPU PVS with see-through triangles, each
 * configuration with a known answer (issue 18, items 3, 5 and 7): moving
 * triangles never occlude and enter the PVS only through proxies
 * (pvs_compute_dynamic), a proxy box is output where any part of it may be
 * visible, and an SCN_ALPHA_BLEND pane hides nothing (docs/trim-regions.md,
 * "See-through triangles and proxies"). The viewcell sits at the origin
 * looking down -Z (pvs_gpu_checks.h). */
#include "pvs_gpu_checks.h"

#include <stdio.h>
#include <string.h>

/* The last `n` triangles of the scene move. */
static void make_dynamic(fixture* f, uint32_t n)
{
    f->scene.dynamic_triangle_count = n;
}

static pvs_proxy proxy(float x0, float y0, float z0, float x1, float y1, float z1, uint32_t first, uint32_t count)
{
    return (pvs_proxy){.box_min = {x0, y0, z0}, .box_max = {x1, y1, z1}, .first_id = first, .id_count = count};
}

static bool compute_dynamic(fixture* f, const pvs_viewcell* vc, const pvs_proxy* p, uint32_t n, pvs_result* r)
{
    char err[512];
    bool ok = pvs_compute_dynamic(f->pvs, vc, p, n, r, err, sizeof err);
    if (!ok)
        fprintf(stderr, "pvs_compute_dynamic: %s\n", err);
    else
        printf("  %u of %u triangles; proxies %u, output %u (%u without drawing)\n", r->count,
               f->scene.triangle_count, r->stats.proxies, r->stats.proxies_output, r->stats.proxies_always);
    return ok;
}

static void open_at_origin(fixture* f, pvs_viewcell* vc)
{
    scn_scene_update_bounds(&f->scene);
    fixture_open(f, 0);
    *vc = viewcell(0.0f, 0.0f, 0.0f, 0.1f);
}

/* A wall that moves during the window stands in front of a box: the wall
 * never occludes (it is not in the octree), so the box is in the PVS, and
 * the wall joins through its proxy. Also the case of an occluder covering
 * the box for part of the window only. */
static void test_box_behind_a_moving_wall(void)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    add_box(&f.scene, -10.0f, -3.0f, -20.0f, 10.0f, -2.5f, 0.0f, m); /* a floor: the octree's root holds the proxy */
    uint32_t box = add_box(&f.scene, -0.5f, -0.5f, -12.0f, 0.5f, 0.5f, -11.0f, m);
    uint32_t wall = add_box(&f.scene, -3.0f, -2.0f, -6.2f, 3.0f, 2.0f, -6.0f, m);
    make_dynamic(&f, 12);
    pvs_viewcell vc;
    open_at_origin(&f, &vc);
    pvs_result r;
    TV_CHECK(compute(&f, &vc, &r));
    TV_CHECK(count_in_range(&r, box, 12) > 0);
    TV_CHECK(count_in_range(&r, wall, 12) == 0); /* moving: only through a proxy */
    pvs_proxy p = proxy(-4.0f, -2.0f, -6.2f, 3.0f, 2.0f, -6.0f, wall, 12); /* slides 1 m to -x */
    TV_CHECK(compute_dynamic(&f, &vc, &p, 1, &r));
    TV_CHECK(count_in_range(&r, box, 12) > 0);
    TV_CHECK(count_in_range(&r, wall, 12) == 12);
    TV_CHECK(r.stats.proxies == 1 && r.stats.proxies_output == 1 && r.stats.proxies_always == 0);
    fixture_close(&f);
}

/* A building hides a mover at rest; the mover's proxy (its box over the
 * window) comes out past the building's edge: in the PVS. A second mover
 * stays behind a static wall for the whole window: not in the PVS. With
 * octree_cap 4 the boxes are sorted into leaves of several layers. */
static void check_movers_behind_buildings(uint32_t octree_cap)
{
    fixture f = {.octree_cap = octree_cap};
    uint32_t m = constructed_scene(&f);
    add_box(&f.scene, -3.0f, -2.0f, -6.2f, 3.0f, 2.0f, -6.0f, m); /* static: 6 m wide at 6 m */
    uint32_t beside = add_box(&f.scene, 9.0f, -0.5f, -12.0f, 10.0f, 0.5f, -11.0f, m);
    uint32_t out = add_box(&f.scene, -0.5f, -0.5f, -12.5f, 0.5f, 0.5f, -11.5f, m);
    uint32_t hid = add_box(&f.scene, -1.0f, -0.5f, -13.0f, 0.0f, 0.5f, -12.0f, m);
    make_dynamic(&f, 24);
    pvs_viewcell vc;
    open_at_origin(&f, &vc);
    /* the wall's umbra at z = -12 reaches |x| < 6 from v0 */
    pvs_proxy p[2] = {proxy(-0.5f, -0.5f, -12.5f, 8.0f, 0.5f, -11.5f, out, 12),
                      proxy(-2.0f, -0.5f, -13.0f, 1.0f, 0.5f, -12.0f, hid, 12)};
    pvs_result r;
    TV_CHECK(compute_dynamic(&f, &vc, p, 2, &r));
    TV_CHECK(octree_cap == 0 || r.stats.layers > 3);
    TV_CHECK(count_in_range(&r, beside, 12) > 0);
    TV_CHECK(count_in_range(&r, out, 12) == 12);
    TV_CHECK(count_in_range(&r, hid, 12) == 0);
    TV_CHECK(r.stats.proxies_output == 1);
    /* the same mover in front of the building: in, however its box is sorted */
    p[1] = proxy(-1.0f, -0.5f, -5.0f, 0.0f, 0.5f, -4.0f, hid, 12);
    TV_CHECK(compute_dynamic(&f, &vc, p, 2, &r));
    TV_CHECK(count_in_range(&r, hid, 12) == 12 && r.stats.proxies_output == 2);
    /* a box around the viewcell: output without drawing */
    p[1] = proxy(-1.0f, -1.0f, -1.0f, 1.0f, 1.0f, 1.0f, hid, 12);
    TV_CHECK(compute_dynamic(&f, &vc, p, 2, &r));
    TV_CHECK(count_in_range(&r, hid, 12) == 12 && r.stats.proxies_always == 1);
    /* bad input: a one-line reason, no result */
    char err[256] = "";
    p[1] = proxy(1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 1.0f, hid, 12);
    TV_CHECK(!pvs_compute_dynamic(f.pvs, &vc, p, 2, &r, err, sizeof err) && strstr(err, "proxy 1") != NULL);
    p[1] = proxy(0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, hid, 1000);
    TV_CHECK(!pvs_compute_dynamic(f.pvs, &vc, p, 2, &r, err, sizeof err) && strstr(err, "ids") != NULL);
    printf("  %s\n", err);
    fixture_close(&f);
}

static void test_movers_behind_buildings(void)
{
    check_movers_behind_buildings(0);
    check_movers_behind_buildings(4);
}

/* A pane in front of a box: see-through (SCN_ALPHA_BLEND), both are in the
 * PVS; opaque, it hides the box. */
static void check_pane(scn_alpha_mode mode)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    uint32_t glass = fx_material(&f.scene, 0.7f, 0.8f, 0.9f, mode, false, -1);
    uint32_t box = add_box(&f.scene, -0.5f, -0.5f, -12.0f, 0.5f, 0.5f, -11.0f, m);
    uint32_t pane = add_box(&f.scene, -3.0f, -2.0f, -6.02f, 3.0f, 2.0f, -6.0f, glass);
    pvs_viewcell vc;
    open_at_origin(&f, &vc);
    pvs_result r;
    TV_CHECK(compute(&f, &vc, &r));
    TV_CHECK(count_in_range(&r, pane, 12) > 0);
    TV_CHECK((count_in_range(&r, box, 12) > 0) == (mode == SCN_ALPHA_BLEND));
    fixture_close(&f);
}

static void test_see_through_pane(void)
{
    check_pane(SCN_ALPHA_BLEND);
    check_pane(SCN_ALPHA_OPAQUE);
}

int main(void)
{
    g_rnd = fx_context();
    TV_TEST_RUN(test_box_behind_a_moving_wall);
    TV_TEST_RUN(test_movers_behind_buildings);
    TV_TEST_RUN(test_see_through_pane);
    TV_CHECK(rnd_validation_message_count(g_rnd) == 0);
    rnd_destroy(g_rnd);
    return tv_test_finish();
}
