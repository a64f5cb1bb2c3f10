#include "trim_width.h"

#include <assert.h>
#include <math.h>

/* Normalised image displacement (inwards) of the far point seen past s from
 * a viewpoint at depth a whose lateral offset r(a) points outward, relative
 * to the v* ray through s: (r(a) - a·σ) (F - d) / (F (d - a)). */
static double displacement(double a, double r, double depth, double sigma, double far)
{
    return (r - a * sigma) * (far - depth) / (far * (depth - a));
}

float pvs_trim_width_px(const pvs_trim_params* p, float depth, float sigma_outward)
{
    assert(p && p->delta >= 0.0f && p->tan_half_fov > 0.0f && p->far_dist > 0.0f);
    double z = (double)p->delta / (double)p->tan_half_fov;
    if (depth >= p->far_dist)
        return 0.0f;
    if ((double)depth <= 2.0 * z)
        return INFINITY;
    /* The displacement is monotonic in a on each cone (see the docs), so the
     * maximum over the viewcell lies at a = 0 (v*, zero), at the base disk
     * (a = z, r = Δ) or at the far apex (a = 2z, r = 0). */
    double base = displacement(z, p->delta, depth, sigma_outward, p->far_dist);
    double tip = displacement(2.0 * z, 0.0, depth, sigma_outward, p->far_dist);
    double w = fmax(0.0, fmax(base, tip));
    return (float)(w * p->focal_px);
}
