#include "tri_box.h"

#include <cglm/cglm.h>
#include <math.h>

/* Is `axis` a separating axis between the triangle (vertices relative to the
 * box centre) and the box of half extents h? A zero axis (parallel edges, a
 * degenerate triangle) separates nothing. The projection radius is padded by
 * a relative epsilon so that rounding never separates touching shapes. */
static bool separates(vec3 axis, vec3 v[3], const float h[3])
{
    float p0 = glm_vec3_dot(axis, v[0]), p1 = glm_vec3_dot(axis, v[1]), p2 = glm_vec3_dot(axis, v[2]);
    float lo = fminf(p0, fminf(p1, p2)), hi = fmaxf(p0, fmaxf(p1, p2));
    float r = h[0] * fabsf(axis[0]) + h[1] * fabsf(axis[1]) + h[2] * fabsf(axis[2]);
    float slack = 1e-6f * (r + fmaxf(fabsf(lo), fabsf(hi)));
    return lo > r + slack || hi < -r - slack;
}

bool pvs_tri_box_overlap(const float a[3], const float b[3], const float c[3],
                         const float box_min[3], const float box_max[3])
{
    float h[3];
    vec3 v[3], e[3]; /* vertices relative to the box centre, edges */
    for (int i = 0; i < 3; i++) {
        float centre = 0.5f * (box_min[i] + box_max[i]);
        h[i] = 0.5f * (box_max[i] - box_min[i]);
        v[0][i] = a[i] - centre;
        v[1][i] = b[i] - centre;
        v[2][i] = c[i] - centre;
    }
    for (int i = 0; i < 3; i++) {
        vec3 axis = {0.0f, 0.0f, 0.0f};
        axis[i] = 1.0f;
        if (separates(axis, v, h))
            return false;
    }
    glm_vec3_sub(v[1], v[0], e[0]);
    glm_vec3_sub(v[2], v[1], e[1]);
    glm_vec3_sub(v[0], v[2], e[2]);
    vec3 normal;
    glm_vec3_cross(e[0], e[1], normal);
    if (separates(normal, v, h))
        return false;
    for (int i = 0; i < 3; i++) {
        for (int k = 0; k < 3; k++) {
            vec3 unit = {0.0f, 0.0f, 0.0f}, axis;
            unit[k] = 1.0f;
            glm_vec3_cross(e[i], unit, axis);
            if (separates(axis, v, h))
                return false;
        }
    }
    return true;
}
