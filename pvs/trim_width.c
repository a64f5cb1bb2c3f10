#include "trim_width.h"

#include <assert.h>
#include <math.h>
#include <stdbool.h>

/* (F - d) / F times the larger of (Δ + z s) / (d - z) and 2 z s / (d - 2z):
 * the maximum over the double cone of (r(a) + a s) / (d - a), reached at the
 * base disk or the far apex (docs/trim-width.md). s = -sigma_n gives the
 * inward displacement, s = |sigma| a bound of the displacement's length. */
static double cone_max(const pvs_trim_params* p, double depth, double s)
{
    double z = (double)p->delta / (double)p->tan_half_fov;
    double base = ((double)p->delta + z * s) / (depth - z), tip = 2.0 * z * s / (depth - 2.0 * z);
    return fmax(0.0, fmax(base, tip)) * (p->far_dist - depth) / p->far_dist;
}

static bool in_range(const pvs_trim_params* p, float depth)
{
    assert(p && p->delta >= 0.0f && p->tan_half_fov > 0.0f && p->far_dist > 0.0f);
    return (double)depth > 2.0 * (double)p->delta / (double)p->tan_half_fov;
}

float pvs_trim_width_px(const pvs_trim_params* p, float depth, float sigma_outward)
{
    if (!in_range(p, depth))
        return INFINITY;
    if (depth >= p->far_dist)
        return 0.0f;
    return (float)(cone_max(p, depth, -(double)sigma_outward) * p->focal_px);
}

float pvs_trim_reach_px(const pvs_trim_params* p, float depth, float sigma_length)
{
    assert(sigma_length >= 0.0f);
    if (!in_range(p, depth))
        return INFINITY;
    if (depth >= p->far_dist)
        return 0.0f;
    return (float)(cone_max(p, depth, sigma_length) * p->focal_px);
}
