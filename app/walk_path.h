/* walk_path.h - head-motion paths through a scene's walkable free space
 * (walkable.h), with predict/path_synth's head-motion model. Vulkan-free. */
#ifndef TRIMVR_APP_WALK_PATH_H
#define TRIMVR_APP_WALK_PATH_H

#include "path.h"
#include "walkable.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef enum tv_auto_path_kind { TV_AUTO_WALK, TV_AUTO_RUN, TV_AUTO_LOOKAROUND } tv_auto_path_kind;

/* Parses "walk", "run" or "lookaround". */
bool tv_auto_path_kind_from_name(const char* name, tv_auto_path_kind* out);

/* A synthetic path through the free space of `scene` (predict/path_synth's
 * head-motion model): a walk (1.4 m/s, about 40 m) or run (3 m/s, about
 * 90 m) over the largest walkable region, visiting its farthest-point
 * samples in nearest-first order along joined points, straightened where the
 * straight line stays walkable, with the eye 1.6 m above the floor under it;
 * or a seated look-around (15 s) at the region's first sample facing its
 * longest line of sight. The path's scene line is `spec`. False with a
 * one-line reason. */
/* A synthetic path over w's largest region: a walk (1.4 m/s) or run
 * (3 m/s, the bundled runs' gait) tours the region's farthest-point samples
 * (up to 12), each time to the nearest one not yet visited, along joined
 * points (tv_walkable_route) until at least 40 m (walk) or 90 m (run) are
 * covered; the route is straightened wherever the straight line is walkable
 * (tv_walkable_segment), cut at 64 waypoints, and each pose is lifted by the
 * floor height under it (so ramps and stairs between storeys are followed).
 * A look-around is seated for 15 s at the region's first sample facing its
 * longest line of sight. The path's scene line is `spec`. w must have a
 * walkable point. False with a one-line reason. */
bool tv_walkable_path(const tv_walkable* w, const char* spec, tv_auto_path_kind kind, uint64_t seed, pred_path* out,
                      char* err, size_t err_size);

#endif
