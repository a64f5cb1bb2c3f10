/* scene.h - the in-memory scene every other module consumes.
 *
 * A scene is one flat triangle list in world space: glTF node transforms are
 * applied at load time and every primitive is appended, so a triangle's index
 * in `indices` is its global triangle id. Triangle ids are what the renderer
 * writes into its id attachment and what a PVS contains.
 *
 * Conventions: metres, right-handed, +Y up (glTF). Counter-clockwise triangles
 * are front-facing. All arrays are owned by the scene and released by
 * scn_scene_free().
 */
#ifndef TRIMVR_SCENE_H
#define TRIMVR_SCENE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "mover.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum scn_alpha_mode {
    SCN_ALPHA_OPAQUE = 0,
    SCN_ALPHA_MASK = 1, /* fragments with alpha < alpha_cutoff are discarded in every pass */
    SCN_ALPHA_BLEND = 2 /* see-through: never an occluder in the PVS (docs/trim-regions.md, "See-through
                           triangles") nor in the ground truth; the renderer blends it
                           over the rest, sorted back to front (docs/rendering.md) */
} scn_alpha_mode;

typedef struct scn_material {
    char name[64];
    float base_color[4];  /* linear RGBA factor */
    int32_t texture;      /* index into scn_scene.textures, -1 when untextured */
    scn_alpha_mode alpha_mode;
    float alpha_cutoff;   /* glTF default 0.5 */
    bool double_sided;
} scn_material;

typedef struct scn_texture {
    uint32_t width, height;
    uint8_t* rgba8; /* width*height*4 bytes, sRGB-encoded colour, linear alpha */
} scn_texture;

typedef struct scn_scene {
    char name[128]; /* "builtin:city", or the file's base name */

    uint32_t vertex_count;
    float* positions; /* 3 floats per vertex */
    float* normals;   /* 3 floats per vertex, unit length (generated when missing) */
    float* uvs;       /* 2 floats per vertex (zero when missing) */

    uint32_t triangle_count;
    uint32_t* indices;      /* 3 per triangle, into the vertex arrays */
    uint32_t* tri_material; /* material index per triangle */
    uint32_t dynamic_triangle_count; /* the last N triangles move (scn_mover); not in the PVS octree */

    uint32_t material_count;
    scn_material* materials;
    uint32_t texture_count;
    scn_texture* textures;

    float bounds_min[3], bounds_max[3];

    /* Triangles dropped at load time because they could never cover a pixel
     * (repeated index or zero world-space area); not part of triangle_count. */
    uint32_t degenerate_dropped;

    uint32_t mover_count;
    scn_mover* movers; /* mover.h: each owns a contiguous range of those triangles and their vertices */
} scn_scene;

/* Loads `spec` into `out` (zeroed first). `spec` is a file path (.gltf or
 * .glb) or a built-in name such as "builtin:city" with optional parameters
 * (see scn_builtin_help()). On failure returns false, leaves `out` empty and
 * writes a one-line message naming the file and the problem into err. */
bool scn_load(const char* spec, scn_scene* out, char* err, size_t err_size);

/* Releases every array of the scene and zeroes it. Safe on a zeroed scene. */
void scn_scene_free(scn_scene* scene);

/* Recomputes bounds_min/bounds_max from the positions. */
void scn_scene_update_bounds(scn_scene* scene);

/* Writes a one-line summary (name, triangle/vertex/material/texture counts,
 * bounds) into buf, truncated to buf_size. */
void scn_scene_summary(const scn_scene* scene, char* buf, size_t buf_size);

#ifdef __cplusplus
}
#endif

#endif
