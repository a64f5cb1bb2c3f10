#include "silhouette.h"

#include <assert.h>
#include <stdbool.h>

#include "weld.h"

/* Which side of the triangle's plane the point lies on: > 0 its front, < 0
 * its back, 0 on the plane or degenerate. */
static double facing(const float* positions, const uint32_t* indices, uint32_t tri, const float point[3])
{
    const float* a = positions + 3u * indices[3u * tri];
    const float* b = positions + 3u * indices[3u * tri + 1];
    const float* c = positions + 3u * indices[3u * tri + 2];
    double u[3], v[3], w[3];
    for (int i = 0; i < 3; i++) {
        u[i] = (double)b[i] - a[i];
        v[i] = (double)c[i] - a[i];
        w[i] = (double)point[i] - a[i];
    }
    double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    return n[0] * w[0] + n[1] * w[1] + n[2] * w[2];
}

static bool front_facing(const float* positions, const uint32_t* indices, uint32_t tri, const float point[3])
{
    return facing(positions, indices, tri, point) > 0.0;
}

size_t pvs_silhouettes_bound(size_t triangle_count)
{
    return 3 * triangle_count;
}

size_t pvs_find_silhouettes(pvs_silhouette* out, const float* positions, const uint32_t* indices,
                            const uint32_t* adjacency, const uint32_t* tri_ids, size_t count,
                            const float point[3])
{
    assert(positions && indices && adjacency && point && (out || count == 0));
    size_t n = 0;
    for (size_t i = 0; i < count; i++) {
        uint32_t t = tri_ids ? tri_ids[i] : (uint32_t)i;
        double side = facing(positions, indices, t, point);
        bool front = side > 0.0;
        for (uint32_t e = 0; e < 3; e++) {
            uint32_t other = adjacency[3u * t + e];
            bool silhouette;
            if (other == SCN_EDGE_BORDER || other == SCN_EDGE_NONMANIFOLD) {
                silhouette = true;
            } else if (other & SCN_EDGE_REST) {
                /* no edge of the face rested on names it: t does, both ways */
                double f = facing(positions, indices, other & ~SCN_EDGE_REST, point);
                silhouette = !((side > 0.0 && f > 0.0) || (side < 0.0 && f < 0.0));
            } else {
                silhouette = front && !front_facing(positions, indices, other, point);
            }
            if (silhouette)
                out[n++] = (pvs_silhouette){t, e};
        }
    }
    return n;
}
