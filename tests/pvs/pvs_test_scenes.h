/* pvs_test_scenes.h - hand-built scn_scene structs for the PVS unit tests
 * (tv_pvs_cpu depends on scene.h only, so the tests do not load scenes). */
#ifndef TRIMVR_PVS_TEST_SCENES_H
#define TRIMVR_PVS_TEST_SCENES_H

#include <stdint.h>

#include "scene.h"

/* A grid of nx x nz boxes (side 1, spacing 2) on y = 0, each face split into
 * s x s quads: 12 s^2 triangles per box, closed and counter-clockwise. */
void pvs_test_box_grid(scn_scene* out, uint32_t nx, uint32_t nz, uint32_t s);

/* `count` random triangles in [0, extent]^3: most small (size up to
 * `small`), some spanning up to half the extent; clustered near the origin
 * corner so that the octree gets uneven depths. Deterministic in `seed`. */
void pvs_test_soup(scn_scene* out, uint32_t count, float extent, float small, uint32_t seed);

/* Frees what the two builders allocated. */
void pvs_test_scene_free(scn_scene* scene);

/* xorshift32 in [0, 1). */
float pvs_test_rand(uint32_t* state);

#endif
