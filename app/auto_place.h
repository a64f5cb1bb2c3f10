/* auto_place.h - viewcells and head-motion paths for a scene that has no
 * bundled path: what trimvr bench, info --floor-points, path synth --scene
 * and replay fall back on (docs/scenes.md, "Automatic viewcells and paths").
 *
 * A scene with Quake 3 vis data next to it (<name>.pvs.json, the OpenArena
 * levels) keeps its floor points (tv_eval_floor_points) for viewcells, and
 * its walks stay inside the vis clusters; any other scene uses the walkable
 * rule of walkable.h alone. */
#ifndef TRIMVR_APP_AUTO_PLACE_H
#define TRIMVR_APP_AUTO_PLACE_H

#include "path.h"
#include "scene.h"
#include "walk_path.h"

#include <stdbool.h>
#include <stddef.h>

/* paths/NAME-walk.csv of a scene with a bundled walk (builtin:NAME, sponza)
 * into buf, or NULL when the scene has none. */
const char* tv_bundled_walk(const char* spec, char* buf, size_t size);

/* Up to max eye positions pos[3 * i] looking along dir[3 * i] in scene
 * `spec` (loaded as `scene`). Returns the count, or -1 with a one-line reason
 * (also when the scene has no place to stand). *rule (may be NULL) names the
 * rule used: "q3 vis floor points" or "walkable floor". */
int tv_auto_viewcells(const char* spec, const scn_scene* scene, int max, float* pos, float* dir, const char** rule,
                      char* err, size_t err_size);

bool tv_auto_path(const char* spec, const scn_scene* scene, tv_auto_path_kind kind, uint64_t seed, pred_path* out,
                  char* err, size_t err_size);

/* The path `trimvr replay --scene S` (no --path) replays: S's bundled walk,
 * else an automatic walk written to OUT_DIR/auto-walk.csv (the folder is
 * created), saying so on stderr. NULL after printing a one-line error. */
const char* tv_default_walk(const char* spec, const char* out_dir, char* buf, size_t size);

#endif
