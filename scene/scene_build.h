/* scene_build.h - growing an scn_scene (internal to scene/).
 *
 * Both the glTF adapter and the procedural generators append into a builder;
 * it owns the growth policy, world-space flattening of glTF primitives,
 * degenerate-triangle removal and normal generation, so the C++ adapter stays
 * a thin reader of accessors.
 */
#ifndef TRIMVR_SCENE_BUILD_H
#define TRIMVR_SCENE_BUILD_H

#include "scene.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct scn_builder {
    scn_scene* scene;
    uint32_t vertex_capacity, triangle_capacity, material_capacity, texture_capacity;
    bool count_only;  /* only count vertices/triangles: sizing passes of the generators */
    bool failed;      /* out of memory or over 2^32 vertices; every append is then a no-op */
    bool* needs_normal; /* per vertex, NULL until a mesh without normals is appended */
    uint64_t vertex_total, triangle_total; /* counts, valid in count_only mode too */
    uint32_t dropped_degenerate;
    uint32_t mover_capacity;
    uint32_t mover_vertex, mover_triangle; /* scene counts at scn_builder_mover_begin */
} scn_builder;

/* Starts building into `out` (zeroed first). With count_only no vertex or
 * triangle memory is allocated and only vertex_total/triangle_total advance
 * (materials are still stored: release with scn_builder_abort). */
void scn_builder_init(scn_builder* b, scn_scene* out, bool count_only);

/* Appends `count` vertices and returns the id of the first; the caller fills
 * positions/normals/uvs of ids [first, first+count). Returns UINT32_MAX when
 * the builder failed or counts only (then nothing may be written). */
uint32_t scn_builder_vertices(scn_builder* b, uint32_t count);

/* Appends one triangle (vertex ids already appended). */
void scn_builder_triangle(scn_builder* b, uint32_t i0, uint32_t i1, uint32_t i2, uint32_t material);

/* Appends a copy of *m; returns its index. */
uint32_t scn_builder_material(scn_builder* b, const scn_material* m);

/* Appends a texture, taking ownership of rgba8 (freed with free()). */
uint32_t scn_builder_texture(scn_builder* b, uint32_t width, uint32_t height, uint8_t* rgba8);

/* One glTF primitive already decoded to float arrays. */
typedef struct scn_mesh_input {
    const float* positions;  /* 3 per vertex, object space */
    const float* normals;    /* 3 per vertex or NULL (generated) */
    const float* uvs;        /* 2 per vertex or NULL (zero) */
    uint32_t vertex_count;
    const uint32_t* indices; /* 3 per triangle, each < vertex_count (checked by the caller) */
    uint32_t triangle_count;
    float world[16];         /* column-major object-to-world matrix */
    uint32_t material;
} scn_mesh_input;

/* Transforms the primitive into world space (normals by the inverse
 * transpose, winding flipped when det < 0) and appends it; drops triangles
 * with repeated indices or zero world-space area (counted in
 * dropped_degenerate). Returns false with "<file>: <problem>" in err when a
 * position is NaN/Inf or the matrix is singular. */
bool scn_builder_append_mesh(scn_builder* b, const scn_mesh_input* mesh, const char* file,
                             char* err, size_t err_size);

/* Starts a mover: the vertices and triangles appended until
 * scn_builder_mover_end are its geometry, in its local frame. Movers come
 * after every static triangle. */
void scn_builder_mover_begin(scn_builder* b);

/* Ends the mover begun last and returns it with identity parent and base
 * (T = 0, R = identity, S = 1) and no tracks, for the caller to fill now
 * (the pointer is valid until the next mover); tracks' arrays are the
 * mover's (malloc). NULL when the builder failed or only counts. */
scn_mover* scn_builder_mover_end(scn_builder* b, const char* name);

/* Generates the missing normals, takes the movers' rest geometry
 * (scn_mover_init), poses them at t = 0, computes bounds (over every mover's
 * whole loop) and hands the arrays to the scene. Returns false (scene freed) when the builder failed. */
bool scn_builder_finish(scn_builder* b, const char* what, char* err, size_t err_size);

/* Frees everything built so far. */
void scn_builder_abort(scn_builder* b);

/* Column-major glTF node matrix from translation, rotation quaternion
 * (x, y, z, w) and scale: T * R * S. */
void scn_mat4_trs(float out[16], const double t[3], const double r[4], const double s[3]);

/* out = a * b (column-major); out may alias neither input. */
void scn_mat4_mul(float out[16], const float a[16], const float b[16]);

#ifdef __cplusplus
}
#endif

#endif
