#define _POSIX_C_SOURCE 200809L
#include "app_scene.h"

#include "clock.h"
#include "fs.h"
#include "log.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static bool dir_exists(const char* path)
{
    return access(path, R_OK | X_OK) == 0;
}

/* `rel` relative to the executable's folder (build/trimvr -> build/rel)
 * into buf; false when it does not fit or /proc/self/exe is unreadable. */
static bool beside_exe(const char* rel, char* buf, size_t size)
{
    char exe[4096];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0)
        return false;
    exe[n] = '\0';
    char* slash = strrchr(exe, '/');
    if (!slash)
        return false;
    *slash = '\0';
    int len = snprintf(buf, size, "%s/%s", exe, rel);
    return len > 0 && (size_t)len < size;
}

static bool shared_dir(char* out, size_t out_size)
{
    const char* env = getenv("TRIMVR_SHARED");
    if (env && *env) {
        snprintf(out, out_size, "%s", env);
        return true;
    }
    if (dir_exists("../shared/scenes")) {
        snprintf(out, out_size, "../shared");
        return true;
    }
    char scenes[4096];
    if (beside_exe("../../shared/scenes", scenes, sizeof scenes) && dir_exists(scenes) &&
        beside_exe("../../shared", out, out_size))
        return true;
    snprintf(out, out_size, "../shared");
    return false;
}

const char* tv_bundled_file(const char* rel, char* buf, size_t size)
{
    if (access(rel, R_OK) == 0)
        return rel;
    char up[4096];
    int len = snprintf(up, sizeof up, "../%s", rel);
    if (len > 0 && (size_t)len < sizeof up && beside_exe(up, buf, size) && access(buf, R_OK) == 0)
        return buf;
    return rel;
}

bool tv_resolve_scene_spec(const char* spec, char* out, size_t out_size)
{
    char shared[4096];
    int n;
    if (strcmp(spec, "sponza") == 0) {
        shared_dir(shared, sizeof shared);
        n = snprintf(out, out_size, "%s/scenes/sponza_lod4/sponza_s_lod4.glb", shared);
    } else if (strncmp(spec, "oa:", 3) == 0 && spec[3] != '\0' && !strchr(spec + 3, '/')) {
        shared_dir(shared, sizeof shared);
        n = snprintf(out, out_size, "%s/scenes/openarena/%s/%s.gltf", shared, spec + 3, spec + 3);
    } else {
        n = snprintf(out, out_size, "%s", spec);
    }
    return n >= 0 && (size_t)n < out_size;
}

void tv_eval_pvs_json_of(const char* spec, char* buf, size_t size)
{
    tv_resolve_scene_spec(spec, buf, size - 16);
    char* dot = strrchr(buf, '.');
    if (dot)
        strcpy(dot, ".pvs.json");
}

/* The scene, then out_dir (when not NULL: after the scene, so that a failed
 * load leaves no folder; before Vulkan, whose messages would precede the
 * error), then the context and the upload. */
static bool open_scene(const char* spec, const rnd_desc* rd, const char* out_dir, tv_app_scene* out)
{
    memset(out, 0, sizeof *out);
    char resolved[4096], err[512];
    if (!tv_resolve_scene_spec(spec, resolved, sizeof resolved)) {
        tv_log(TV_LOG_ERROR, "scene name too long: %s", spec);
        return false;
    }
    double t0 = tv_now_ms();
    if (!scn_load(resolved, &out->scene, err, sizeof err)) {
        tv_log(TV_LOG_ERROR, "%s", err);
        return false;
    }
    if (out_dir && !tv_mkdirs(out_dir)) {
        tv_log(TV_LOG_ERROR, "%s: cannot create the output folder", out_dir);
        scn_scene_free(&out->scene);
        return false;
    }
    double t1 = tv_now_ms();
    out->load_ms = t1 - t0;
    out->ctx = rnd_create(rd, err, sizeof err);
    if (!out->ctx) {
        tv_log(TV_LOG_ERROR, "%s", err);
        scn_scene_free(&out->scene);
        return false;
    }
    out->gpu = rnd_scene_create(out->ctx, &out->scene, err, sizeof err);
    if (!out->gpu) {
        tv_log(TV_LOG_ERROR, "%s: %s", resolved, err);
        rnd_destroy(out->ctx);
        scn_scene_free(&out->scene);
        memset(out, 0, sizeof *out);
        return false;
    }
    out->upload_ms = tv_now_ms() - t1;
    return true;
}

bool tv_app_scene_open(const char* spec, tv_app_scene* out)
{
    return open_scene(spec, NULL, NULL, out);
}

bool tv_app_scene_open_desc(const char* spec, const rnd_desc* rd, tv_app_scene* out)
{
    return open_scene(spec, rd, NULL, out);
}

bool tv_app_scene_open_out(const char* spec, const char* out_dir, tv_app_scene* out)
{
    return open_scene(spec, NULL, out_dir, out);
}

const rnd_gpu_scene* tv_app_scene_at(tv_app_scene* s, double t, char* err, size_t err_size)
{
    const scn_scene* sc = &s->scene;
    if (!sc->mover_count)
        return s->gpu;
    if (s->posed && s->posed_t == t)
        return s->posed;
    scn_scene_pose(&s->scene, t);
    if (!s->posed && !(s->posed = rnd_scene_create(s->ctx, sc, err, err_size)))
        return NULL;
    const scn_mover* last = &sc->movers[sc->mover_count - 1]; /* movers' vertices: one range, in order */
    uint32_t first = sc->movers[0].first_vertex;
    if (!rnd_scene_update_vertices(s->ctx, s->posed, sc, first, last->first_vertex + last->vertex_count - first, err,
                                   err_size))
        return NULL;
    s->posed_t = t;
    return s->posed;
}

const rnd_gpu_scene* tv_app_scene_pose(void* user, double t, char* err, size_t err_size)
{
    return tv_app_scene_at(user, t, err, err_size);
}

bool tv_app_scene_close(tv_app_scene* s)
{
    if (s->gpu)
        rnd_scene_destroy(s->ctx, s->gpu);
    if (s->posed)
        rnd_scene_destroy(s->ctx, s->posed);
    uint32_t messages = s->ctx ? rnd_validation_message_count(s->ctx) : 0;
    rnd_destroy(s->ctx);
    scn_scene_free(&s->scene);
    memset(s, 0, sizeof *s);
    if (messages) {
        tv_log(TV_LOG_ERROR, "the Vulkan validation layer reported %u warning(s) or error(s)",
               messages);
        return false;
    }
    return true;
}

rnd_camera tv_camera_at_pose(const pred_pose* pose, float fov_y_deg, float near_m, float far_m)
{
    rnd_camera cam = {.fov_y_deg = fov_y_deg, .near_m = near_m, .far_m = far_m};
    for (int k = 0; k < 3; k++)
        cam.position[k] = (float)pose->p[k];
    for (int k = 0; k < 4; k++)
        cam.orientation[k] = (float)pose->q[k];
    return cam;
}

int tv_app_load_path(const char* path_file, const char* scene_spec, pred_path* path, const char** spec)
{
    char err[512];
    if (!pred_path_load(path_file, path, err, sizeof err)) {
        tv_log(TV_LOG_ERROR, "%s", err);
        return 1;
    }
    *spec = scene_spec ? scene_spec : path->scene;
    if (!(*spec)[0]) {
        tv_log(TV_LOG_ERROR, "%s has no '# scene:' line; pass --scene", path_file);
        pred_path_free(path);
        return 2;
    }
    return 0;
}
