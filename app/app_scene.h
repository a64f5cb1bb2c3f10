/* app_scene.h - what every rendering subcommand sets up first: the scene
 * (with the named-scene aliases of ../shared), the Vulkan context and the
 * uploaded scene, and checks at the end that validation stayed silent. */
#ifndef TRIMVR_APP_SCENE_H
#define TRIMVR_APP_SCENE_H

#include "path.h"
#include "pose.h"
#include "render.h"
#include "scene.h"

#include <stdbool.h>
#include <stddef.h>

typedef struct tv_app_scene {
    scn_scene scene;
    rnd_context* ctx;
    rnd_gpu_scene* gpu; /* the scene as loaded (movers at t = 0): what a PVS computation reads */
    rnd_gpu_scene* posed; /* scenes with movers: a second upload, posed per frame for display renders */
    double posed_t;
    double load_ms;   /* scn_load wall time */
    double upload_ms; /* rnd_scene_create wall time */
} tv_app_scene;

/* Expands the short names of the third-party scenes: "sponza" and
 * "oa:<level>" (OpenArena) become files under the shared scenes folder, found
 * through $TRIMVR_SHARED, else ./../shared, else <exe dir>/../../shared.
 * Anything else is copied unchanged. Returns false if the result does not fit. */
bool tv_resolve_scene_spec(const char* spec, char* out, size_t out_size);

/* <level>.pvs.json next to an OpenArena level's .gltf, from a scene spec. */
void tv_eval_pvs_json_of(const char* spec, char* buf, size_t size);

/* Finds the bundled file `rel` (such as "paths/city-walk.csv") from the
 * repository root (the README's commands run there) or next to the
 * executable (build/trimvr -> ../rel). Returns rel itself when neither has
 * it, so the caller's open fails with a one-line error naming it. */
const char* tv_bundled_file(const char* rel, char* buf, size_t size);

/* Loads spec (after alias expansion), creates the Vulkan context and uploads
 * the scene. Prints a one-line error and returns false on failure, leaving
 * nothing allocated. */
bool tv_app_scene_open(const char* spec, tv_app_scene* out);

/* The same with context options (a window's instance extensions, swapchain);
 * rd may be NULL. */
bool tv_app_scene_open_desc(const char* spec, const rnd_desc* rd, tv_app_scene* out);

/* The same, creating out_dir once the scene has loaded (a failed load
 * leaves no folder behind). */
bool tv_app_scene_open_out(const char* spec, const char* out_dir, tv_app_scene* out);

/* The camera of an eye or head pose (float copies of position and
 * orientation) with the given vertical FOV and clip planes. */
rnd_camera tv_camera_at_pose(const pred_pose* pose, float fov_y_deg, float near_m, float far_m);

/* The upload to draw a frame of time t with: `gpu` for a static scene;
 * else the scene is posed at t (scn_scene_pose) and its movers' vertices
 * uploaded to `posed` (created on the first call) unless it holds t already.
 * The PVS worker keeps `gpu`, so posing never races its draws. NULL (err
 * filled) on failure. */
const rnd_gpu_scene* tv_app_scene_at(tv_app_scene* s, double t, char* err, size_t err_size);

/* tv_app_scene_at as pvs_eval_desc.pose (user: the tv_app_scene). */
const rnd_gpu_scene* tv_app_scene_pose(void* user, double t, char* err, size_t err_size);

/* Releases everything. Returns false (after printing why) when the validation
 * layer reported warnings or errors during the run. */
bool tv_app_scene_close(tv_app_scene* s);

/* Loads path_file and names its scene: scene_spec, else the path's
 * '# scene:' line. Returns 0, or the exit status after a one-line error (2
 * when no scene is named, else 1) with the path freed. Render and replay
 * then open the scene with tv_app_scene_open_out. */
int tv_app_load_path(const char* path_file, const char* scene_spec, pred_path* path, const char** spec);

#endif
