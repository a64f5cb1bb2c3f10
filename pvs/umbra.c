#include "umbra.h"

#include <assert.h>
#include <math.h>

bool pvs_umbra_quad_make(const pvs_view* view, const float e0[3], const float e1[3],
                         const float inside[3], float width0, float width1, pvs_umbra_quad* out)
{
    assert(view && e0 && e1 && inside && out && width0 >= 0.0f && width1 >= 0.0f);
    pvs_view_frame f = pvs_view_frame_make(view);
    float i0[2], i1[2], ii[2];
    if (pvs_view_project(view, &f, e0, i0) <= 0.0f || pvs_view_project(view, &f, e1, i1) <= 0.0f ||
        pvs_view_project(view, &f, inside, ii) <= 0.0f)
        return false;
    float t[2] = {i1[0] - i0[0], i1[1] - i0[1]};
    float len = sqrtf(t[0] * t[0] + t[1] * t[1]);
    if (len == 0.0f)
        return false;
    float n[2] = {-t[1] / len, t[0] / len};
    float side = n[0] * (ii[0] - i0[0]) + n[1] * (ii[1] - i0[1]);
    if (side == 0.0f)
        return false;
    if (side > 0.0f) { /* n must point away from the occluder */
        n[0] = -n[0];
        n[1] = -n[1];
    }
    const float* ends[2] = {i0, i1};
    float widths[2] = {width0, width1};
    for (int k = 0; k < 2; k++) {
        for (int c = 0; c < 2; c++)
            out->extruded[k][c] = ends[k][c] - widths[k] * n[c];
    }
    for (int a = 0; a < 3; a++) {
        out->corner[0][a] = e0[a];
        out->corner[1][a] = e1[a];
        for (int k = 0; k < 2; k++) {
            out->corner[2 + k][a] = view->apex[a] +
                                    view->far_dist * (f.forward[a] + out->extruded[1 - k][0] * f.right[a] +
                                                      out->extruded[1 - k][1] * f.up[a]);
        }
    }
    return true;
}
