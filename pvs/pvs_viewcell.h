/* pvs_viewcell.h - the viewcell the trim-region PVS is computed for, and the
 * one conversion from predict/'s sized viewcell into it. Vulkan-free. */
#ifndef TRIMVR_PVS_VIEWCELL_H
#define TRIMVR_PVS_VIEWCELL_H

#include "viewcell.h"

#include <stdbool.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A double-cone viewcell with its widened field of view. fov_pvs_deg is the
 * full angle along the smaller image axis of the PVS resolution (the
 * vertical one for landscape; the larger axis follows from the aspect), so
 * the PVS frustum contains the square pyramid of half-angle
 * α = fov_pvs_deg / 2 that predict/ sizes the viewcell for; z = Δ / tan α. */
typedef struct pvs_viewcell {
    float v0[3];          /* centre of the viewcell */
    float forward[3];     /* view axis (need not be unit length) */
    float up[3];          /* not parallel to forward */
    float delta;          /* radius Δ of the double cone's base disk, metres, >= 0 */
    float fov_target_deg; /* display FOV (informational: sizing is the caller's job) */
    float fov_pvs_deg;    /* widened FOV the PVS is computed for, in (0, 180) */
    float far_m;          /* far plane of the eyes' cameras, measured from v0 */
} pvs_viewcell;

/* Why `vc` cannot be computed (non-finite value, zero forward, up parallel
 * to forward, negative delta, fov_pvs_deg outside (0, 180), far_m <= 0), or
 * NULL when it can. */
const char* pvs_viewcell_invalid(const pvs_viewcell* vc);

/* `in` as the PVS's viewcell for eyes whose far plane is far_m; checks it
 * as pvs_viewcell_invalid does, and predict/'s apex offset z as well. On an
 * invalid viewcell returns false with "invalid viewcell: reason" in err. */
bool pvs_viewcell_from_pred(const pred_viewcell* in, float far_m, pvs_viewcell* out, char* err, size_t err_size);

#ifdef __cplusplus
}
#endif

#endif
