/* render_fixture.h - shared set-up of the render tests: a validated context
 * and hand-built scenes of coloured quads (no scene loader needed). */
#ifndef TRIMVR_TEST_RENDER_FIXTURE_H
#define TRIMVR_TEST_RENDER_FIXTURE_H

#include "render.h"

/* Creates a context with validation forced on; exits 1 with the reason when
 * it cannot (a Vulkan test must never run unvalidated). */
rnd_context* fx_context(void);

/* A scene with room for max_quads quads and max_materials materials. */
void fx_scene_init(scn_scene* s, uint32_t max_quads, uint32_t max_materials);

/* Appends a material; returns its index. */
uint32_t fx_material(scn_scene* s, float r, float g, float b, scn_alpha_mode mode, bool double_sided,
                     int32_t texture);

/* Appends the quad c0 c1 c2 c3 (counter-clockwise seen from the front) as the
 * triangles (c0 c1 c2) and (c0 c2 c3); returns the first triangle's id. UVs
 * run (0,0) (1,0) (1,1) (0,1) over the corners; the normal is the face's. */
uint32_t fx_quad(scn_scene* s, const float c[4][3], uint32_t material);

/* Axis-aligned quad facing +Z at depth z covering [x0,x1] x [y0,y1]. */
uint32_t fx_quad_z(scn_scene* s, float x0, float y0, float x1, float y1, float z, uint32_t material);

/* Camera at the origin looking down -Z, 60 degree vertical FOV, clip 0.1..100. */
rnd_camera fx_camera(void);

/* sRGB encoding of a linear value in [0, 1] as an 8-bit value. */
int fx_srgb8(float linear);

#endif
