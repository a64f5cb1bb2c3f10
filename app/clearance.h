/* clearance.h - distance from points to a scene's nearest triangle.
 *
 * Used to check that a head-motion path, typically a recorded trace placed in
 * a scene, keeps the head out of walls (`trimvr path check`). Triangles are
 * binned by bounding box into a uniform grid whose cells are at least the
 * search radius, so a query visits the 27 cells around the point. Distances
 * are exact up to the radius and capped at it: "nothing within the radius".
 * Vulkan-free (scene only). */
#ifndef TRIMVR_CLEARANCE_H
#define TRIMVR_CLEARANCE_H

#include "scene.h"

#include <stdbool.h>
#include <stddef.h>

typedef struct tv_clearance tv_clearance;

typedef struct tv_clearance_desc {
    float radius_m;    /* search radius; 0: 1.0 m */
    uint32_t max_cells; /* grid size cap (cells grow beyond the radius to fit); 0: 4M */
} tv_clearance_desc;

/* Builds the grid of `scene`'s triangles (the scene must outlive it; it keeps
 * pointers into it). desc may be NULL for the defaults. Returns NULL with a
 * message in err when out of memory or the scene has no triangles. */
tv_clearance* tv_clearance_create(const scn_scene* scene, const tv_clearance_desc* desc, char* err,
                                  size_t err_size);

void tv_clearance_destroy(tv_clearance* c);

/* The search radius in effect. */
float tv_clearance_radius(const tv_clearance* c);

/* Distance from p to the nearest point of any triangle, or the radius when no
 * triangle comes closer. *tri (may be NULL) receives that triangle's id, or
 * UINT32_MAX when none is within the radius. */
float tv_clearance_query(const tv_clearance* c, const float p[3], uint32_t* tri);

/* Distance from p to triangle (a, b, c), by brute force; exposed for tests. */
float tv_point_triangle_distance(const float p[3], const float a[3], const float b[3], const float c[3]);

#endif
