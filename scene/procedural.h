/* procedural.h - the built-in scenes ("builtin:<name>[?key=value&...]").
 *
 * Deterministic: the same spec gives bit-identical arrays on every run (own
 * PCG32, no rand(), no time). Layout contracts below are relied on by other
 * modules' tests and walking paths; docs/scenes.md has the full description.
 *
 * builtin:city[?seed=S&tris=T]  streets and buildings, at least T triangles
 *   and within a few percent of T (default 150000, 10000..16000000). Ground is y = 0.
 *   Block pitch SCN_CITY_BLOCK_PITCH (40 m: 30 m blocks, 10 m streets);
 *   street centrelines x = i*40 and z = j*40 for integer i, j within the
 *   extent (|x|,|z| <= 80 m up to 300k triangles, 120 m up to 1.2M, 160 m
 *   beyond). Every street is free of geometry for 0 < y <= 6 m within 4 m of
 *   its centreline (the ground itself is at y = 0), for the whole extent.
 *
 * Both take movers=N (0..10000, default 0): N moving objects appended after
 * the static scene, which stays bit-identical (procgen_movers.c,
 * docs/scenes.md "Movers").
 *
 * builtin:interior[?seed=S]  rooms off a corridor. Floor y = 0, ceilings
 *   y = 3. Corridor: x in [-24, 24], z in [-1.5, 1.5], walls 0.2 m thick at
 *   z in [1.5, 1.7] and [-1.7, -1.5], end walls x in [24, 24.2] and
 *   [-24.2, -24]. Rooms: x in [cx-4, cx+4] for cx in {-18, -6, 6, 18},
 *   z in [1.7, 10.5] (and mirrored), walls 0.2 m thick outside that; the room
 *   centre of the contract is (cx, y, +-6.5). Each room opens on the corridor
 *   by a doorway x in [cx-0.6, cx+0.6], y in [0, 2.2] through the corridor
 *   wall. The box |x - cx| < 1.0, z from the corridor wall to the room centre,
 *   y in [0, 2.2], holds no geometry, so the line from any point of the
 *   doorway to the room centre at 1.0-2.0 m is clear. Each room has two
 *   columns (0.4 m square, at (cx+2.2, +-4.5) and (cx-2.5, +-8.5)), a thin
 *   zero-thickness partition (material "partition", double-sided) at
 *   x = cx-3.2, z in [7, 10] (mirrored), y in [0, 2], and seeded furniture
 *   boxes in 1.0 <= |x - cx| <= 3.8.
 *
 * builtin:house[?seed=S]  a detailed two-storey house (procgen_house*.c),
 *   built as CAD/BIM exports are: every part a closed box, parts touching,
 *   coplanar or interpenetrating. Outer walls x in [-6, 6], z in [-4.5, 4.5],
 *   0.3 m thick; floors y = 0 and y = 3 (slab 2.75-3), roof slab 6-6.25; a
 *   yard quad y = -0.15 over x in [-12, 12], z in [-10, 10]. Hall between
 *   walls x = +-1.5 (0.12 m thick), stairs on its east side (x in [0.4, 1.44],
 *   bottom at z = 2.2, up towards -z). Doors 1.0 x 2.1 m; the front door
 *   x in [-1.35, -0.15] in the north wall. The bundled walk's lanes hold no
 *   geometry within 0.3 m of the eye (1.7 m): x = -0.75 from the yard
 *   (z = 8.5) to z = -2.25, z = -2.25 to x = -3.25, x = -3.25 to z = 2.25
 *   (through the living-kitchen door), z = 2.25 back to x = -0.75,
 *   x = -0.75 to z = -3.25 and z = -3.25 to x = 3.25 (the doors on it are
 *   always open). Furniture
 *   positions are fixed; the seed varies book rows and the other doors.
 *
 * builtin:unit  four objects with analytic visibility (no seed):
 *   "ground": the quad y = 0, x in [-10, 10], z in [-15, 5], facing +y;
 *   "wall"  W: box x in [-2, 2],     y in [0, 3], z in [-5.1, -5];
 *   "box_b" B: box x in [-0.5, 0.5], y in [0, 1], z in [-8, -7] (behind W);
 *   "box_c" C: box x in [4, 5],      y in [0, 1], z in [-6, -5] (beside W).
 *   Boxes have no bottom face (it would lie on the ground): 10 triangles
 *   each. From (0, 1.5, 0) looking down -Z, C is visible and B is hidden.
 */
#ifndef TRIMVR_SCENE_PROCEDURAL_H
#define TRIMVR_SCENE_PROCEDURAL_H

#include "scene.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SCN_CITY_BLOCK_PITCH 40.0f
#define SCN_CITY_STREET_CLEAR_HALF_WIDTH 4.0f
#define SCN_CITY_STREET_CLEAR_HEIGHT 6.0f
#define SCN_CITY_DEFAULT_TRIS 150000u

/* Multi-line description of the builtin: spec syntax and scenes. */
const char* scn_builtin_help(void);

/* Loads a "builtin:..." spec (scn_load calls it). Unknown names, unknown
 * keys, malformed or out-of-range values fail with a one-line message. */
bool scn_load_builtin(const char* spec, scn_scene* out, char* err, size_t err_size);

/* Triangle id range [*first, *first + *count) of a builtin:unit object
 * ("ground", "wall", "box_b", "box_c"); false for other names. */
bool scn_unit_object(const char* name, uint32_t* first, uint32_t* count);

#ifdef __cplusplus
}
#endif

#endif
