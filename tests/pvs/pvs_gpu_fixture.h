/* pvs_gpu_fixture.h - what the GPU PVS tests (test_pvs_gpu.c,
 * test_pvs_gpu_cases.c) share: a scene uploaded with its PVS context and
 * targets, and false-negative counts of eyes against it.
 *
 * Eyes render at 160x90 with the 60-degree target FOV (0.375 degrees per
 * pixel) against a 320x180 PVS whose 90 degrees span the smaller, vertical
 * axis (0.5 degrees per pixel vertically, 0.38 horizontally), so an eye
 * pixel spans about as many directions as one PVS pixel. */
#ifndef TRIMVR_TESTS_PVS_GPU_FIXTURE_H
#define TRIMVR_TESTS_PVS_GPU_FIXTURE_H

#include "procedural.h"
#include "pvs.h"
#include "render_fixture.h"

#include <stdbool.h>
#include <stdint.h>

#define W 160u /* eye renders */
#define H 90u
#define PW 320u /* PVS */
#define PH 180u

/* FN pixel bounds per eye render, as fractions of its pixels (fn_bound).
 * Scenes of large, well-separated objects: no eye pixel may miss. */
#define FN_SIMPLE 0.0
/* builtin:city at these resolutions: sub-pixel slivers (poles seen edge-on,
 * distant ground strips) decide some eye pixels differently from every PVS
 * pixel centre (docs/pvs-edge-cases.md, "What the tests check"). */
#define FN_CITY 0.01
/* Sub-pixel slivers in a constructed scene (test_small_opening_at_view_edge). */
#define FN_SLIVER 0.001

extern rnd_context* g_rnd; /* set by the test's main */

typedef struct fixture {
    scn_scene scene;
    rnd_gpu_scene* gpu;
    rnd_target* target;
    rnd_target* apex_target;
    pvs_context* pvs;
    float *depth, *pvs_depth;
    uint32_t octree_cap;    /* 0: the default */
    uint32_t max_layers;    /* 0: the default */
    uint32_t coop_sort_min; /* 0: the default */
    bool explain;           /* pvs_desc.explain */
    uint32_t k_deep;        /* pvs_desc.k_deep */
} fixture;

void fixture_open(fixture* f, uint32_t k);
void fixture_close(fixture* f);
void load(fixture* f, const char* spec, uint32_t k);
bool compute(fixture* f, const pvs_viewcell* vc, pvs_result* r);
int compare_u32(const void* a, const void* b);
bool in_pvs(const pvs_result* r, uint32_t id);
uint32_t count_in_range(const pvs_result* r, uint32_t first, uint32_t count);
uint32_t diff_pixels(fixture* f, rnd_target* t, const rnd_camera* cam, const pvs_result* r);
uint32_t fn_pixels(fixture* f, const pvs_result* r, const pvs_viewcell* vc, const float eye[3], float yaw_deg);
uint32_t apex_fn(fixture* f, const pvs_result* r, const pvs_viewcell* vc);
uint32_t cone_fn(fixture* f, const pvs_result* r, const pvs_viewcell* vc, uint32_t* at_v0);
uint32_t fn_bound(double fraction);
pvs_viewcell viewcell(float x, float y, float z, float delta);
void soup_box(scn_scene* s, const float lo[3], const float hi[3], uint32_t m);
uint32_t add_box(scn_scene* s, float x0, float y0, float z0, float x1, float y1, float z1, uint32_t m);
/* A box without its bottom face (it stands on a floor: the feet of its
 * sides are border edges), returning its first triangle id (10 triangles). */
uint32_t add_standing_box(scn_scene* s, float x0, float y0, float z0, float x1, float y1, float z1, uint32_t m);
uint32_t constructed_scene(fixture* f);
uint32_t double_sided(fixture* f);

#endif
