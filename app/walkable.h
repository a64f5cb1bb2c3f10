/* walkable.h - where a person can stand in any scene: automatic viewcells and
 * walking routes for scenes without a bundled path or Quake 3 vis data.
 *
 * The rule (docs/scenes.md, "Automatic viewcells"):
 *  1. A column grid of cell `cell_m` covers the scene's x-z extent. At each
 *     column centre, every triangle whose normal is within max_slope_deg of
 *     +Y or -Y and whose x-z projection holds the centre is a floor
 *     candidate at its height there (either winding: trimvr draws both
 *     sides, and real models, Sponza's among them, have floors facing down).
 *  2. A floor at height h gives a standing eye at h + eye_height_m, kept when
 *     (a) the vertical ray up from just above the floor meets no triangle
 *     below the eye + clearance_m (headroom), (b) no triangle comes within
 *     clearance_m of the eye (free space around the head), and (c) the eye
 *     is not inside a solid: when the first triangle above faces up (seen
 *     from its back) and is single-sided, of the 8 horizontal rays from the
 *     eye (45 degrees apart, 50 m) that meet a single-sided triangle, no
 *     more than half meet its back.
 *  3. Two kept points of neighbouring columns (8-neighbourhood) are joined
 *     when their floors differ by at most step_m and the straight walk
 *     between them keeps the head clearance, keeps clearance_m / 1.5 at knee
 *     height (0.5 m: no walking through railings or low walls) and stays over
 *     floor. Joined points form regions; regions of at least region_fraction
 *     of the largest one's points are walkable, the rest (ledges, small roof
 *     tops) are not, and neither is a roof: a region with nothing above any
 *     of its points whose mean height is over 1 m above the lowest big one.
 *  4. Viewcells: farthest-point sampling over the walkable points in 3D,
 *     starting from the point nearest their centroid; each looks horizontally
 *     along the longest free line of sight of 16 directions.
 * Deterministic (no randomness; ties go to the lower index). Vulkan-free. */
#ifndef TRIMVR_APP_WALKABLE_H
#define TRIMVR_APP_WALKABLE_H

#include "scene.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef struct tv_walk_desc {
    float eye_height_m;     /* 0: 1.6 */
    float clearance_m;      /* 0: 0.3 */
    float max_slope_deg;    /* 0: 30 */
    float step_m;           /* 0: 0.5, the largest floor height change between neighbouring columns */
    float cell_m;           /* 0: sqrt(x-z extent / 65536), at least 0.5 m */
    float region_fraction;  /* 0: 0.25 */
    /* optional last test of a standing eye before rule 3 (such as "inside a
     * vis cluster of the level"); NULL: none. Only called by create. */
    bool (*accept)(const float eye[3], void* user);
    void* user;
} tv_walk_desc;

typedef struct tv_walkable tv_walkable;

/* Builds the grid, the points and the regions of `scene` (which must outlive
 * the result). desc may be NULL for the defaults. NULL with a one-line
 * message on out of memory or an empty scene; a scene with no walkable point
 * is not an error (tv_walkable_count() is 0). */
tv_walkable* tv_walkable_create(const scn_scene* scene, const tv_walk_desc* desc, char* err, size_t err_size);

void tv_walkable_destroy(tv_walkable* w);

/* The settings in effect (defaults resolved). */
tv_walk_desc tv_walkable_desc(const tv_walkable* w);

/* Number of walkable points (kept regions only). */
uint32_t tv_walkable_count(const tv_walkable* w);

/* Walkable point i < tv_walkable_count(): its eye position and region. */
void tv_walkable_point(const tv_walkable* w, uint32_t i, float eye[3], uint32_t* region);

/* Rule 4: up to max eye positions (pos[3 * i]) and unit horizontal view
 * directions (dir[3 * i]), restricted to one region (UINT32_MAX: all
 * walkable points). Returns the count; indices[i] (may be NULL) receives the
 * point index of each. */
int tv_walkable_viewcells(const tv_walkable* w, uint32_t region, int max, float* pos, float* dir,
                          uint32_t* indices);

/* The region with the most points (UINT32_MAX when there are none). */
uint32_t tv_walkable_largest_region(const tv_walkable* w);

/* True when a person walks the straight line from floor point a to floor
 * point b (x, floor y, z) under rule 3's conditions. */
bool tv_walkable_segment(const tv_walkable* w, const float a[3], const float b[3]);

/* Breadth-first route over joined points from point `from` to point `to`
 * (same region): writes up to max point indices, from first, into route.
 * Returns the count, 0 when unreachable or longer than max. */
int tv_walkable_route(const tv_walkable* w, uint32_t from, uint32_t to, uint32_t* route, int max);

/* Head clearance at p (capped at the clearance radius). */
float tv_walkable_clearance(const tv_walkable* w, const float p[3]);

#endif
