#include "tri_box.h"

#include <math.h>

static void sub3(const float a[3], const float b[3], float out[3])
{
    out[0] = a[0] - b[0];
    out[1] = a[1] - b[1];
    out[2] = a[2] - b[2];
}

static float dot3(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const float a[3], const float b[3], float out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* Is `axis` a separating axis between the triangle (vertices relative to the
 * box centre) and the box of half extents h? A zero axis (parallel edges, a
 * degenerate triangle) separates nothing. The projection radius is padded by
 * a relative epsilon so that rounding never separates touching shapes. */
static bool separates(const float axis[3], const float v[3][3], const float h[3])
{
    float p0 = dot3(axis, v[0]), p1 = dot3(axis, v[1]), p2 = dot3(axis, v[2]);
    float lo = fminf(p0, fminf(p1, p2)), hi = fmaxf(p0, fmaxf(p1, p2));
    float r = h[0] * fabsf(axis[0]) + h[1] * fabsf(axis[1]) + h[2] * fabsf(axis[2]);
    float slack = 1e-6f * (r + fmaxf(fabsf(lo), fabsf(hi)));
    return lo > r + slack || hi < -r - slack;
}

bool pvs_tri_box_overlap(const float a[3], const float b[3], const float c[3],
                         const float box_min[3], const float box_max[3])
{
    float centre[3], h[3], v[3][3], e[3][3];
    for (int i = 0; i < 3; i++) {
        centre[i] = 0.5f * (box_min[i] + box_max[i]);
        h[i] = 0.5f * (box_max[i] - box_min[i]);
    }
    sub3(a, centre, v[0]);
    sub3(b, centre, v[1]);
    sub3(c, centre, v[2]);
    for (int i = 0; i < 3; i++) {
        float axis[3] = {0.0f, 0.0f, 0.0f};
        axis[i] = 1.0f;
        if (separates(axis, v, h))
            return false;
    }
    sub3(v[1], v[0], e[0]);
    sub3(v[2], v[1], e[1]);
    sub3(v[0], v[2], e[2]);
    float normal[3];
    cross3(e[0], e[1], normal);
    if (separates(normal, v, h))
        return false;
    for (int i = 0; i < 3; i++) {
        for (int k = 0; k < 3; k++) {
            float unit[3] = {0.0f, 0.0f, 0.0f}, axis[3];
            unit[k] = 1.0f;
            cross3(e[i], unit, axis);
            if (separates(axis, v, h))
                return false;
        }
    }
    return true;
}
