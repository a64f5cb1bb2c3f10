/* pvs_gpu_checks.h - checks the GPU PVS tests share (pvs_gpu_fixture.h).
 * They are static inline so that TV_CHECK counts their failures in the
 * including test's own counters (test.h keeps them per file). */
#ifndef TRIMVR_TESTS_PVS_GPU_CHECKS_H
#define TRIMVR_TESTS_PVS_GPU_CHECKS_H

#include "layers.h"
#include "pvs_gpu_fixture.h"
#include "test.h"

/* Opens the fixture's scene and computes the PVS of the viewcell at the
 * origin looking down -Z. */
static inline void compute_at_origin(fixture* f, float delta, pvs_viewcell* vc, pvs_result* r)
{
    scn_scene_update_bounds(&f->scene);
    fixture_open(f, 0);
    *vc = viewcell(0.0f, 0.0f, 0.0f, delta);
    TV_CHECK(compute(f, vc, r));
}

/* No false-negative pixel from the apex or v0, and at most fn_fraction of
 * a view at any sample of the double cone. */
static inline void check_fn(fixture* f, const pvs_result* r, const pvs_viewcell* vc, double fn_fraction)
{
    TV_CHECK(apex_fn(f, r, vc) == 0);
    uint32_t at_v0, worst = cone_fn(f, r, vc, &at_v0);
    printf("  FN pixels: %u at v0 (3 renders), worst cone sample %u\n", at_v0, worst);
    TV_CHECK(at_v0 == 0 && worst <= fn_bound(fn_fraction));
}

/* Computes the PVS of a small viewcell at the origin looking down -Z and
 * checks the known answer: every box in `hidden` culled, every one in
 * `visible` kept, and no false-negative pixel from the apex or anywhere on
 * the double cone. */
static inline void check_configuration(fixture* f, const char* what, float delta, double fn_fraction, const uint32_t* hidden,
                                int n_hidden, const uint32_t* visible, int n_visible)
{
    printf("  %s\n", what);
    pvs_result r;
    pvs_viewcell vc;
    compute_at_origin(f, delta, &vc, &r);
    TV_CHECK(f->octree_cap == 0 || r.stats.layers > 3);
    TV_CHECK(f->max_layers == 0 || r.stats.layers <= f->max_layers); /* 0: the device decides */
    for (int i = 0; i < n_hidden; i++)
        TV_CHECK(count_in_range(&r, hidden[i], 12) == 0);
    for (int i = 0; i < n_visible; i++)
        TV_CHECK(count_in_range(&r, visible[i], 12) > 0);
    check_fn(f, &r, &vc, fn_fraction);
    fixture_close(f);
}

#endif
