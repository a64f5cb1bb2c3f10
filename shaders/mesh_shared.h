/* mesh_shared.h - the mesh pass's constants, included by C (render/) and by
 * GLSL (mesh_common.glsl). Only #define lines and comments: GLSL's
 * preprocessor must accept every line, so sizes and limits cannot drift
 * between the host and the shaders. Structs the two sides each declare are
 * checked with _Static_assert next to their C declaration (render_vk.h). */
#ifndef TRIMVR_SHADERS_MESH_SHARED_H
#define TRIMVR_SHADERS_MESH_SHARED_H

/* Descriptor sets of the mesh pipeline (render/): the scene's buffers and
 * textures (shared, read-only), and the per-target subset id list. */
#define TV_SET_SCENE 0
#define TV_SET_DRAW  1

/* Bindings of set TV_SET_SCENE, except TV_BIND_DRAW_IDS (set TV_SET_DRAW). */
#define TV_BIND_POSITIONS 0   /* float[3] per welded vertex           */
#define TV_BIND_ATTRIBS   1   /* normal.xyz, uv.xy per vertex          */
#define TV_BIND_INDICES   2   /* uint[3] per triangle                  */
#define TV_BIND_TRI_MAT   3   /* material index per triangle           */
#define TV_BIND_MATERIALS 4   /* tv_material_gpu per material          */
#define TV_BIND_DRAW_IDS  5   /* triangle ids drawn (subset renders)   */
#define TV_BIND_TEXTURES  6   /* one sampler2DArray, a layer per texture */

/* Lighting of the mesh pass, linear RGB: one directional light (unit vector
 * towards the light) plus a hemispheric ambient blended by normal.y. */
#define TV_SUN_DIR     0.30151134, 0.90453403, 0.30151134
#define TV_SUN_COLOR   0.75, 0.75, 0.75
#define TV_SKY_COLOR   0.30, 0.32, 0.35
#define TV_GROUND_COLOR 0.12, 0.11, 0.10

/* Textures are layers of one sRGB 2D array image (lavapipe has no dynamic
 * indexing of sampler arrays and only 32 samplers per stage): at most
 * TV_MAX_TEXTURES layers, every layer resampled to the largest texture's
 * size capped at TV_MAX_TEXTURE_SIZE. */
#define TV_MAX_TEXTURES 256
#define TV_MAX_TEXTURE_SIZE 1024

/* Triangle id written where no triangle covers the pixel. */
#define TV_NO_TRIANGLE 0xFFFFFFFFu

/* Material flags (tv_material_gpu.flags). */
#define TV_MAT_TEXTURED   1u
#define TV_MAT_ALPHA_MASK 2u
#define TV_MAT_DOUBLE_SIDED 4u
#define TV_MAT_ALPHA_BLEND 8u /* see-through: the PVS passes never let it occlude */

#endif
