/* weld_geom.h - what the scene passes that join border edges share
 * (tjunction.c, rest.c): a triangle's corners and unit normal, and the
 * tolerances that decide whether an edge lies on a line or a face. */
#ifndef TRIMVR_SCENE_WELD_GEOM_H
#define TRIMVR_SCENE_WELD_GEOM_H

#include <cglm/cglm.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Relative to the edge length: a vertex computed by a map compiler (a
 * T-junction, a wall's foot on a floor) lies on the line or face up to
 * rounding. */
#define SCN_WELD_LINE_EPS 1e-4f
/* Faces whose unit normals agree to this count as coplanar. */
#define SCN_WELD_NORMAL_COS 0.99999f

static inline const float* scn_tri_corner(const float* positions, const uint32_t* indices, uint32_t tri, uint32_t c)
{
    return positions + 3 * (size_t)indices[3 * (size_t)tri + c];
}

/* Unit normal of a triangle; false when degenerate. */
static inline bool scn_tri_unit_normal(const float* positions, const uint32_t* indices, uint32_t tri, vec3 n)
{
    vec3 p[3];
    for (uint32_t c = 0; c < 3; c++)
        glm_vec3_copy((float*)scn_tri_corner(positions, indices, tri, c), p[c]);
    glm_vec3_sub(p[1], p[0], p[1]);
    glm_vec3_sub(p[2], p[0], p[2]);
    glm_vec3_cross(p[1], p[2], n);
    float len = glm_vec3_norm(n);
    if (!(len > 0.0f))
        return false;
    glm_vec3_divs(n, len, n);
    return true;
}

#endif
