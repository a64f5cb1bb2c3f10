/* render.h - the Vulkan renderer: device, scene upload, offscreen targets,
 * the mesh pass (full scene or a triangle subset) and camera math.
 *
 * Conventions (docs/rendering.md has the derivations):
 * - World: metres, right-handed, +Y up (scene.h). A camera looks down its
 *   local -Z with +Y up and +X right; orientation is a unit quaternion
 *   stored x, y, z, w (cglm's versor layout).
 * - Clip space is Vulkan's: +Y down, depth 0 (near) .. 1 (far), standard
 *   (not reversed) Z with a LESS depth test.
 * - A target holds colour (VK_FORMAT_R8G8B8A8_SRGB: the shader writes linear
 *   colour, the stored and read-back bytes are sRGB-encoded), depth
 *   (D32_SFLOAT) and triangle ids (R32_UINT, TV_NO_TRIANGLE where empty).
 *
 * Subset invariant: rnd_draw with a triangle list draws those triangles in
 * ascending id order through the same shaders as a full draw, so every pixel
 * whose front-most full-render triangle is in the list gets bit-identical
 * colour, depth and id (equal-depth ties resolve to the lower id in both).
 * SCN_ALPHA_BLEND triangles are blended after all others, back to front by
 * centroid; depth and ids still name the nearest surface, BLEND included,
 * and the colour invariant holds where that surface is not BLEND.
 *
 * Threading: rnd_create/rnd_destroy and the create/destroy functions of
 * scenes and targets must not race with other calls on the same object.
 * rnd_draw and the rnd_target_read_* functions may run concurrently from
 * several threads provided each thread uses its own target; a gpu scene is
 * read-only after creation and may be shared. Queue submission is serialised
 * inside the context (see render_vk.h for the per-thread stream helpers).
 * rnd_validation_message_count is safe from any thread.
 */
#ifndef TRIMVR_RENDER_H
#define TRIMVR_RENDER_H

#include "scene.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rnd_context rnd_context;
typedef struct rnd_gpu_scene rnd_gpu_scene;
typedef struct rnd_target rnd_target;

typedef struct rnd_desc {
    /* Physical device: a substring of its name or a decimal index. NULL uses
     * env TRIMVR_DEVICE, else the first discrete, then integrated GPU, else
     * a CPU device (lavapipe), else the first device. */
    const char* device;
    /* 0: from env TRIMVR_VALIDATION (=1 enables), 1: on, -1: off. When on,
     * VK_LAYER_KHRONOS_validation must be present or rnd_create fails. */
    int validation;
    /* Extra instance extensions, e.g. what a window system needs for a
     * surface (glfwGetRequiredInstanceExtensions); NULL/0 for none. */
    const char* const* instance_extensions;
    uint32_t instance_extension_count;
    /* Enables VK_KHR_swapchain on the device (render/swapchain.h). */
    bool swapchain;
} rnd_desc;

/* Creates the instance, device, queue and mesh pipeline. desc may be NULL
 * (all defaults). Requires Vulkan 1.3 (dynamic rendering, synchronization2)
 * and fragmentStoresAndAtomics (the PVS passes); on failure returns
 * NULL with a one-line reason in err. */
rnd_context* rnd_create(const rnd_desc* desc, char* err, size_t err_size);

/* Waits for the device to go idle and releases everything. NULL is a no-op.
 * Scenes and targets must be destroyed first. */
void rnd_destroy(rnd_context* ctx);

/* Number of validation-layer messages of severity WARNING or ERROR seen so
 * far (each is also logged through tv_log). Thread-safe. */
uint32_t rnd_validation_message_count(const rnd_context* ctx);

/* The chosen physical device's name (valid for the context's lifetime). */
const char* rnd_device_name(const rnd_context* ctx);

/* Uploads a scene: vertex arrays, indices, per-triangle materials and
 * materials into storage buffers, textures into sRGB sampled images. Fails
 * (NULL, reason in err) when a buffer exceeds the device's
 * maxStorageBufferRange or the scene has more than TV_MAX_TEXTURES textures.
 * The scn_scene is not referenced after the call. */
rnd_gpu_scene* rnd_scene_create(rnd_context* ctx, const scn_scene* scene, char* err, size_t err_size);

/* Uploads the positions and normals of vertices [first, first + count) of
 * `scene` (the one `gpu` was created from, posed since: scn_scene_pose) and
 * waits for the copy. Draws submitted after it see the new pose; the caller
 * keeps draws of `gpu` on other threads out of the way (the replay gives the
 * PVS worker its own upload). */
bool rnd_scene_update_vertices(rnd_context* ctx, rnd_gpu_scene* gpu, const scn_scene* scene, uint32_t first,
                               uint32_t count, char* err, size_t err_size);

/* Triangle count of an uploaded scene. */
uint32_t rnd_scene_triangle_count(const rnd_gpu_scene* scene);

void rnd_scene_destroy(rnd_context* ctx, rnd_gpu_scene* scene);

/* Creates an offscreen target of width x height pixels (both > 0 and within
 * maxImageDimension2D) with its own command stream and read-back buffer. */
rnd_target* rnd_target_create(rnd_context* ctx, uint32_t width, uint32_t height, char* err, size_t err_size);

void rnd_target_destroy(rnd_context* ctx, rnd_target* target);

uint32_t rnd_target_width(const rnd_target* target);
uint32_t rnd_target_height(const rnd_target* target);

/* Read-backs of the last rnd_draw into caller-owned arrays of width*height
 * elements, rows top to bottom. Colour: 4 bytes per pixel, sRGB-encoded RGB
 * and alpha 255 where an opaque triangle was drawn (the clear colour
 * elsewhere, with the largest alpha of the BLEND triangles over it).
 * Return false (logged) when the target holds no successful draw or on a
 * Vulkan failure. */
bool rnd_target_read_color(rnd_context* ctx, rnd_target* target, uint8_t* rgba);
bool rnd_target_read_ids(rnd_context* ctx, rnd_target* target, uint32_t* ids);
bool rnd_target_read_depth(rnd_context* ctx, rnd_target* target, float* depth);

/* Background of every draw, linear RGB (stored sRGB-encoded, alpha 0). */
#define RND_CLEAR_COLOR_LINEAR 0.05f, 0.1f, 0.2f

typedef struct rnd_camera {
    float position[3];
    float orientation[4]; /* x, y, z, w; camera looks down its local -Z, +Y up, +X right */
    float fov_y_deg;      /* full vertical field of view */
    float near_m, far_m;
} rnd_camera;

/* Column-major view and Vulkan projection matrices (cglm layout) for a
 * target of the given aspect (width / height). */
void rnd_camera_view(const rnd_camera* cam, float view[16]);
void rnd_camera_projection(const rnd_camera* cam, float aspect, float proj[16]);
void rnd_camera_view_proj(const rnd_camera* cam, float aspect, float view_proj[16]);

/* Vertical FOV (degrees) whose frustum has the given horizontal FOV at this
 * aspect, and the inverse: the PVS sizes its frustum by the larger angle. */
float rnd_fov_y_from_x(float fov_x_deg, float aspect);
float rnd_fov_x_from_y(float fov_y_deg, float aspect);

/* Eye cameras for a head pose: positions offset by -ipd/2 (left) and +ipd/2
 * (right) along the head's local +X, orientation = head_q, FOV and clip
 * planes copied from base. */
void rnd_stereo_cameras(const float head_pos[3], const float head_q[4], float ipd_m, const rnd_camera* base,
                        rnd_camera* left, rnd_camera* right);

typedef struct rnd_draw_stats {
    double cpu_ms;         /* record + submit + wait, wall clock */
    double gpu_ms;         /* timestamp difference; negative when unsupported */
    uint32_t triangles;    /* triangles submitted */
} rnd_draw_stats;

/* Clears the target and draws the scene from cam. tri_ids == NULL draws every
 * triangle; otherwise exactly tri_ids[0..tri_count) (ids < triangle count, any
 * order; they are drawn in ascending order, see the subset invariant above;
 * an already ascending list is not re-sorted; duplicates are harmless).
 * stats may be NULL. Blocks until the GPU has finished. Returns false (logged,
 * nothing drawn) on an id >= the scene's triangle count or a Vulkan failure. */
bool rnd_draw(rnd_context* ctx, rnd_target* target, const rnd_gpu_scene* scene, const rnd_camera* cam,
              const uint32_t* tri_ids, uint32_t tri_count, rnd_draw_stats* stats);

#ifdef __cplusplus
}
#endif

#endif
