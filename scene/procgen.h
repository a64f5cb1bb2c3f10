/* procgen.h - shared machinery of the built-in scenes (internal to scene/).
 *
 * A small deterministic PRNG (PCG32: never rand(), so a seed gives the same
 * scene on every platform) and emitters for axis-aligned quads and boxes with
 * world-space box-mapped UVs (one texture repeat per SCN_GEN_UV_METRES) and
 * flat normals. Every emitter also works on a count-only builder, which the
 * city uses to size its facade detail for a triangle budget.
 */
#ifndef TRIMVR_SCENE_PROCGEN_H
#define TRIMVR_SCENE_PROCGEN_H

#include "scene_build.h"

#define SCN_GEN_UV_METRES 3.0f

/* The scenes draw from predict/'s PCG32 (seeding and sequence are the
 * generator's own, so a seed gives the same city everywhere). */
#include "rng.h"

/* Uniform float in [lo, hi) from the top 24 bits: exact in float. */
float scn_rng_range(tv_rng* rng, float lo, float hi);

/* Procedural 256x256 RGBA8 textures. */
typedef enum scn_gen_texture {
    SCN_GEN_TEX_BRICKS,
    SCN_GEN_TEX_FACADE,
    SCN_GEN_TEX_CONCRETE,
    SCN_GEN_TEX_TILES,
    SCN_GEN_TEX_WOOD,
    SCN_GEN_TEX_COUNT
} scn_gen_texture;

/* Adds every procedural texture to the builder (indices == scn_gen_texture). */
void scn_gen_add_textures(scn_builder* b);

/* Adds an opaque material with a texture (-1: none) and an RGB factor. */
uint32_t scn_gen_material(scn_builder* b, const char* name, int32_t texture, float r, float g, float bl,
                          bool double_sided);

/* Emits the parallelogram origin + s*u + t*v (s, t in [0, 1]) as a grid of
 * cells_u x cells_v cells (2 triangles each); it faces u x v
 * (counter-clockwise seen from that side). */
void scn_gen_quad(scn_builder* b, const float origin[3], const float u[3], const float v[3], uint32_t cells_u,
                  uint32_t cells_v, uint32_t material);

/* Cell count along an edge of `length` metres so no cell exceeds max_cell. */
uint32_t scn_gen_cells(float length, float max_cell);

/* Box faces, for the `faces` mask of scn_gen_box. */
enum {
    SCN_FACE_NEG_X = 1, SCN_FACE_POS_X = 2, SCN_FACE_NEG_Y = 4,
    SCN_FACE_POS_Y = 8, SCN_FACE_NEG_Z = 16, SCN_FACE_POS_Z = 32,
    SCN_FACE_ALL = 63, SCN_FACE_NO_BOTTOM = 63 & ~4
};

/* Emits the outward faces of the axis-aligned box [lo, hi] selected by
 * `faces`, each split into cells of at most max_cell metres (0: one cell). */
void scn_gen_box(scn_builder* b, const float lo[3], const float hi[3], unsigned faces, float max_cell,
                 uint32_t material);

/* Built-in scene generators; `tris` is the city's triangle target. */
void scn_gen_city(scn_builder* b, uint64_t seed, uint32_t tris, uint32_t movers);
void scn_gen_interior(scn_builder* b, uint64_t seed, uint32_t movers);
void scn_gen_unit(scn_builder* b);
void scn_gen_house(scn_builder* b, uint64_t seed);

/* `count` movers of the city (blocks per half-extent as generated) or the
 * interior, appended after the static scene (procgen_movers.c). */
void scn_gen_city_movers(scn_builder* b, uint64_t seed, int blocks, uint32_t count);
void scn_gen_interior_movers(scn_builder* b, uint64_t seed, uint32_t count);

#endif
