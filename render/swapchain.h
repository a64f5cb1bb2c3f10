/* swapchain.h - presenting CPU-composed RGBA8 frames to a window surface.
 *
 * The demo composes its mirror image on the CPU (eye read-backs, HUD,
 * overlays), so presentation is one upload plus one blit: the frame goes into
 * a host-visible buffer, is copied into a staging image of the frame's size
 * and blitted (linear filter, aspect kept, the rest cleared black) into the
 * acquired swapchain image. The blit also converts RGBA to the surface's
 * BGRA. One frame is in flight: present waits for its own copy to finish,
 * which costs nothing on a CPU device and keeps the code obviously correct.
 *
 * The context must be created with rnd_desc.swapchain = true and the window
 * system's instance extensions. Window-system-agnostic: the caller supplies
 * the surface through a callback (glfwCreateWindowSurface in the demo), and
 * nothing here includes GLFW. Queue use goes through the context's queue
 * mutex, so the PVS worker may keep submitting from its thread. */
#ifndef TRIMVR_RENDER_SWAPCHAIN_H
#define TRIMVR_RENDER_SWAPCHAIN_H

#include "render.h"

#include <vulkan/vulkan.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rnd_swapchain rnd_swapchain;

/* Creates the window surface on the context's instance; VK_SUCCESS or the
 * error to report. */
typedef VkResult (*rnd_surface_fn)(void* user, VkInstance instance, VkSurfaceKHR* surface);

/* Zero means default. */
typedef struct rnd_swapchain_desc {
    rnd_surface_fn create_surface; /* required */
    void* user;
    uint32_t width, height; /* the window's framebuffer size in pixels, both > 0 */
    bool mailbox;           /* MAILBOX when offered (no vsync wait); default FIFO */
} rnd_swapchain_desc;

/* Creates the surface and a swapchain of 2-3 images with an sRGB-encoded
 * 8-bit format. Fails with a one-line reason when the queue cannot present
 * to the surface, no 8-bit format is offered or the format cannot be a blit
 * destination. */
rnd_swapchain* rnd_swapchain_create(rnd_context* ctx, const rnd_swapchain_desc* desc, char* err, size_t err_size);

/* Waits for the queue to go idle and releases the swapchain and the surface. NULL is a no-op. */
void rnd_swapchain_destroy(rnd_context* ctx, rnd_swapchain* sc);

/* Rebuilds the swapchain for a new framebuffer size (both > 0): after a
 * resize or when present asked for it. */
bool rnd_swapchain_resize(rnd_context* ctx, rnd_swapchain* sc, uint32_t width, uint32_t height, char* err,
                          size_t err_size);

/* Current swapchain image size (may differ from the requested size when the
 * surface dictates it). */
void rnd_swapchain_extent(const rnd_swapchain* sc, uint32_t* width, uint32_t* height);

typedef enum rnd_present_result {
    RND_PRESENT_OK = 0,
    RND_PRESENT_SHOWN_STALE, /* presented (shot filled), but call rnd_swapchain_resize before the next */
    RND_PRESENT_RECREATE,    /* out of date, nothing shown: rnd_swapchain_resize, then present again */
    RND_PRESENT_ERROR        /* reason in err */
} rnd_present_result;

/* Shows rgba (width * height pixels, 4 bytes each, sRGB-encoded, rows top
 * to bottom) scaled into the window. When `shot` is not NULL it receives the
 * presented swapchain image itself, read back as RGBA8 (extent from
 * rnd_swapchain_extent, caller-owned, width*height*4 bytes): a screenshot that
 * proves what reached the window. Blocks until the copy has executed. */
rnd_present_result rnd_swapchain_present(rnd_context* ctx, rnd_swapchain* sc, const uint8_t* rgba, uint32_t width,
                                         uint32_t height, uint8_t* shot, char* err, size_t err_size);

#ifdef __cplusplus
}
#endif

#endif
