/* gltf_loader.h - glTF 2.0 (.gltf + .bin, .glb) into an scn_scene.
 *
 * The one tinygltf file; images decode through image_io (OpenImageIO).
 * Support matrix (docs/scenes.md has the full table):
 *   - the default scene (scene 0 when unset; every root node when the file has
 *     no scenes), node hierarchy flattened: matrix or TRS, normals by the
 *     inverse transpose, winding flipped under a negative determinant;
 *   - TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN (converted), indexed or not,
 *     u8/u16/u32 indices; POINTS/LINES skipped with a debug log;
 *   - POSITION, NORMAL, TEXCOORD_0 in every component type glTF allows
 *     (normalized integers decoded); missing NORMAL generated (area-weighted,
 *     smooth over welded positions, see scene_build.c);
 *   - baseColorFactor, baseColorTexture, alphaMode, alphaCutoff, doubleSided.
 *     Sparse accessors and skins/morph targets are not supported.
 * Degenerate triangles (repeated index or zero area) are dropped and counted
 * in one info log line: they can never cover a pixel and triangle ids stay
 * dense.
 */
#ifndef TRIMVR_SCENE_GLTF_LOADER_H
#define TRIMVR_SCENE_GLTF_LOADER_H

#include "scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Loads `path` into `out` (zeroed first). On failure returns false, leaves
 * `out` empty and writes "<path>: <problem>" (one line) into err. Failures:
 * missing file, truncated or corrupt JSON/.glb, an accessor reaching past its
 * buffer view or buffer, an index >= the vertex count, a sparse accessor, a
 * missing or undecodable texture image, a NaN/Inf position, a singular node
 * matrix, a node cycle. */
bool scn_load_gltf(const char* path, scn_scene* out, char* err, size_t err_size);

#ifdef __cplusplus
}
#endif

#endif
