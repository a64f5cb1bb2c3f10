/* cli_viewcell.h - viewcells given on the command line (`trimvr pvs`,
 * `trimvr eval`, `trimvr bench`): a centre, a view direction, Δ and the two
 * FOVs, with no prediction involved. */
#ifndef TRIMVR_EVAL_CLI_VIEWCELL_H
#define TRIMVR_EVAL_CLI_VIEWCELL_H

#include "path.h"
#include "viewcell.h"

#include <stdbool.h>

/* Builds the double-cone viewcell at pos looking along dir (any length > 0),
 * up = `up` made perpendicular to dir, or when up is NULL world +Y (world +Z
 * when dir is vertical), radius delta, display FOV fov_deg and PVS FOV
 * fov_pvs_deg (square frustum). A unit dir, and a unit up perpendicular to
 * it (both within 1e-6), are kept bit for bit: a replay's viewcell (its
 * pvs.csv) is reproduced only with its own up and digits, and a facing test
 * at an edge-on triangle can turn on the last bit. False when dir is zero or too long for a float length (a
 * component beyond about 1e19; up alike), up is within 0.1 degree of parallel to it, fov_deg is out of
 * (0, 180) or fov_pvs_deg out of (0, TV_VIEWCELL_MAX_FOV_PVS). */
bool tv_viewcell_make(const float pos[3], const float dir[3], const float* up, float delta, float fov_deg,
                      float fov_pvs_deg, pred_viewcell* out);

/* The widest PVS FOV, as replay and bench take it: near 180 degrees the
 * frustum degenerates (at 179.9 the unit scene's PVS loses triangles that
 * the 90-degree one holds). */
#define TV_VIEWCELL_MAX_FOV_PVS 179.0f

/* The use window of these viewcells (what scenes with movers are sampled
 * over): the replay's default, one 50 ms latency plus one 90 Hz frame, from
 * the pose's time (tv_viewcell_make: from 0). */
#define TV_VIEWCELL_WINDOW_S (0.05 + 1.0 / 90.0)

/* The same at a head pose (position, forward and up of its orientation). */
void tv_viewcell_at_pose(const pred_pose* head, float delta, float fov_deg, float fov_pvs_deg, pred_viewcell* out);

#endif
