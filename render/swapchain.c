/* swapchain.c - surface, swapchain and the upload-and-blit present path
 * (see swapchain.h for why the frame is composed on the CPU). */
#include "swapchain.h"

#include "render_vk.h"

#include <assert.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_IMAGES 8

struct rnd_swapchain {
    VkSurfaceKHR surface;
    VkSwapchainKHR swapchain;
    VkSurfaceFormatKHR format;
    VkPresentModeKHR mode;
    VkExtent2D extent;
    VkImageUsageFlags usage;
    uint32_t image_count;
    VkImage images[MAX_IMAGES];
    /* present waits on the semaphore of its own image: a single one could be
     * re-signalled while the presentation engine still waits on it */
    VkSemaphore rendered[MAX_IMAGES];
    VkSemaphore acquired; /* safe to reuse: present waits for the fence of the submit that consumed it */
    rnd_stream stream;
    rnd_buffer upload, shot;
    rnd_image frame;  /* the composed frame, blit source */
    VkFormat frame_format;
    VkFilter filter;
};

/* 8-bit formats in order of preference: sRGB-encoded so the blit from an
 * sRGB frame image needs no conversion the hardware might not offer. */
static bool choose_format(rnd_context* ctx, rnd_swapchain* sc, char* err, size_t err_size)
{
    uint32_t count = 0;
    if (!RND_VK_OK(vkGetPhysicalDeviceSurfaceFormatsKHR(ctx->physical, sc->surface, &count, NULL), err, err_size))
        return false;
    VkSurfaceFormatKHR formats[64];
    if (count > 64)
        count = 64;
    VkResult r = vkGetPhysicalDeviceSurfaceFormatsKHR(ctx->physical, sc->surface, &count, formats);
    if (r != VK_SUCCESS && r != VK_INCOMPLETE)
        return rnd_vk_ok(r, "vkGetPhysicalDeviceSurfaceFormatsKHR", err, err_size);
    const VkFormat wanted[] = {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_B8G8R8A8_UNORM,
                               VK_FORMAT_R8G8B8A8_UNORM};
    for (size_t w = 0; w < sizeof wanted / sizeof wanted[0]; w++)
        for (uint32_t i = 0; i < count; i++)
            if (formats[i].format == wanted[w] && formats[i].colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) {
                sc->format = formats[i];
                bool srgb = wanted[w] == VK_FORMAT_B8G8R8A8_SRGB || wanted[w] == VK_FORMAT_R8G8B8A8_SRGB;
                /* a UNORM surface shows stored bytes as they are, and ours are already sRGB-encoded */
                sc->frame_format = srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
                VkFormatProperties src, dst;
                vkGetPhysicalDeviceFormatProperties(ctx->physical, sc->frame_format, &src);
                vkGetPhysicalDeviceFormatProperties(ctx->physical, sc->format.format, &dst);
                if (!(src.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_SRC_BIT) ||
                    !(dst.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT)) {
                    snprintf(err, err_size, "%s cannot blit into the window's surface format %d",
                             ctx->props.deviceName, (int)sc->format.format);
                    return false;
                }
                sc->filter = src.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT
                                 ? VK_FILTER_LINEAR
                                 : VK_FILTER_NEAREST;
                return true;
            }
    snprintf(err, err_size, "the window surface offers no 8-bit RGBA/BGRA sRGB-colour-space format (%u formats)",
             count);
    return false;
}

static void choose_mode(rnd_context* ctx, rnd_swapchain* sc, bool mailbox)
{
    sc->mode = VK_PRESENT_MODE_FIFO_KHR; /* always supported */
    if (!mailbox)
        return;
    uint32_t count = 0;
    VkPresentModeKHR modes[16];
    vkGetPhysicalDeviceSurfacePresentModesKHR(ctx->physical, sc->surface, &count, NULL);
    if (count > 16)
        count = 16;
    vkGetPhysicalDeviceSurfacePresentModesKHR(ctx->physical, sc->surface, &count, modes);
    for (uint32_t i = 0; i < count; i++)
        if (modes[i] == VK_PRESENT_MODE_MAILBOX_KHR)
            sc->mode = VK_PRESENT_MODE_MAILBOX_KHR;
}

static void destroy_semaphores(rnd_context* ctx, rnd_swapchain* sc)
{
    for (uint32_t i = 0; i < MAX_IMAGES; i++)
        if (sc->rendered[i])
            vkDestroySemaphore(ctx->device, sc->rendered[i], NULL);
    memset(sc->rendered, 0, sizeof sc->rendered);
}

/* Every use of the shared queue, presentation included, holds its mutex. */
static void wait_queue_idle(rnd_context* ctx)
{
    pthread_mutex_lock(&ctx->queue_mutex);
    vkQueueWaitIdle(ctx->queue);
    pthread_mutex_unlock(&ctx->queue_mutex);
}

static bool build(rnd_context* ctx, rnd_swapchain* sc, uint32_t width, uint32_t height, char* err, size_t err_size)
{
    VkSurfaceCapabilitiesKHR caps;
    if (!RND_VK_OK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx->physical, sc->surface, &caps), err, err_size))
        return false;
    VkExtent2D extent = caps.currentExtent;
    if (extent.width == UINT32_MAX) { /* the surface takes the swapchain's size */
        extent.width = width < caps.minImageExtent.width ? caps.minImageExtent.width
                       : width > caps.maxImageExtent.width ? caps.maxImageExtent.width
                                                           : width;
        extent.height = height < caps.minImageExtent.height ? caps.minImageExtent.height
                        : height > caps.maxImageExtent.height ? caps.maxImageExtent.height
                                                              : height;
    }
    if (extent.width == 0 || extent.height == 0) {
        snprintf(err, err_size, "the window surface has zero size (minimised)");
        return false;
    }
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT)) {
        snprintf(err, err_size, "the window surface cannot be a transfer destination");
        return false;
    }
    uint32_t images = caps.minImageCount + 1;
    if (caps.maxImageCount && images > caps.maxImageCount)
        images = caps.maxImageCount;
    if (images > MAX_IMAGES)
        images = MAX_IMAGES;
    /* read-back for screenshots where the surface allows it */
    sc->usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    VkSwapchainKHR old = sc->swapchain;
    VkSwapchainCreateInfoKHR info = {
        .sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR,
        .surface = sc->surface,
        .minImageCount = images,
        .imageFormat = sc->format.format,
        .imageColorSpace = sc->format.colorSpace,
        .imageExtent = extent,
        .imageArrayLayers = 1,
        .imageUsage = sc->usage,
        .imageSharingMode = VK_SHARING_MODE_EXCLUSIVE,
        .preTransform = caps.currentTransform,
        .compositeAlpha = caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                              ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                              : (VkCompositeAlphaFlagBitsKHR)(caps.supportedCompositeAlpha &
                                                              -caps.supportedCompositeAlpha),
        .presentMode = sc->mode,
        .clipped = VK_TRUE,
        .oldSwapchain = old,
    };
    VkResult r = vkCreateSwapchainKHR(ctx->device, &info, NULL, &sc->swapchain);
    if (old)
        vkDestroySwapchainKHR(ctx->device, old, NULL);
    if (r != VK_SUCCESS) {
        sc->swapchain = VK_NULL_HANDLE;
        return rnd_vk_ok(r, "vkCreateSwapchainKHR", err, err_size);
    }
    sc->extent = extent;
    sc->image_count = MAX_IMAGES;
    r = vkGetSwapchainImagesKHR(ctx->device, sc->swapchain, &sc->image_count, sc->images);
    if (r != VK_SUCCESS && r != VK_INCOMPLETE)
        return rnd_vk_ok(r, "vkGetSwapchainImagesKHR", err, err_size);
    destroy_semaphores(ctx, sc);
    VkSemaphoreCreateInfo si = {.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    for (uint32_t i = 0; i < sc->image_count; i++)
        if (!RND_VK_OK(vkCreateSemaphore(ctx->device, &si, NULL, &sc->rendered[i]), err, err_size))
            return false;
    return true;
}

rnd_swapchain* rnd_swapchain_create(rnd_context* ctx, const rnd_swapchain_desc* desc, char* err, size_t err_size)
{
    assert(desc && desc->create_surface && desc->width > 0 && desc->height > 0);
    rnd_swapchain* sc = calloc(1, sizeof *sc);
    if (!sc) {
        snprintf(err, err_size, "out of memory creating the swapchain");
        return NULL;
    }
    VkResult r = desc->create_surface(desc->user, ctx->instance, &sc->surface);
    if (r != VK_SUCCESS) {
        rnd_vk_ok(r, "window surface creation", err, err_size);
        free(sc);
        return NULL;
    }
    VkBool32 supported = VK_FALSE;
    vkGetPhysicalDeviceSurfaceSupportKHR(ctx->physical, ctx->queue_family, sc->surface, &supported);
    VkSemaphoreCreateInfo si = {.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    if (!supported) {
        snprintf(err, err_size, "%s cannot present to this window (queue family %u)", ctx->props.deviceName,
                 ctx->queue_family);
    } else if (choose_format(ctx, sc, err, err_size) &&
               RND_VK_OK(vkCreateSemaphore(ctx->device, &si, NULL, &sc->acquired), err, err_size) &&
               rnd_stream_create(ctx, &sc->stream, err, err_size)) {
        choose_mode(ctx, sc, desc->mailbox);
        if (build(ctx, sc, desc->width, desc->height, err, err_size))
            return sc;
    }
    rnd_swapchain_destroy(ctx, sc);
    return NULL;
}

void rnd_swapchain_destroy(rnd_context* ctx, rnd_swapchain* sc)
{
    if (!sc)
        return;
    wait_queue_idle(ctx);
    destroy_semaphores(ctx, sc);
    if (sc->acquired)
        vkDestroySemaphore(ctx->device, sc->acquired, NULL);
    rnd_stream_destroy(ctx, &sc->stream);
    rnd_buffer_destroy(ctx, &sc->upload);
    rnd_buffer_destroy(ctx, &sc->shot);
    rnd_image_destroy(ctx, &sc->frame);
    if (sc->swapchain)
        vkDestroySwapchainKHR(ctx->device, sc->swapchain, NULL);
    if (sc->surface)
        vkDestroySurfaceKHR(ctx->instance, sc->surface, NULL);
    free(sc);
}

bool rnd_swapchain_resize(rnd_context* ctx, rnd_swapchain* sc, uint32_t width, uint32_t height, char* err,
                          size_t err_size)
{
    assert(width > 0 && height > 0);
    wait_queue_idle(ctx);
    return build(ctx, sc, width, height, err, err_size);
}

void rnd_swapchain_extent(const rnd_swapchain* sc, uint32_t* width, uint32_t* height)
{
    *width = sc->extent.width;
    *height = sc->extent.height;
}

/* The composed frame's staging image, recreated when its size changes. */
static bool reserve_frame(rnd_context* ctx, rnd_swapchain* sc, uint32_t width, uint32_t height, char* err,
                          size_t err_size)
{
    if (sc->frame.image && sc->frame.width == width && sc->frame.height == height)
        return true;
    rnd_image_destroy(ctx, &sc->frame);
    return rnd_image_create(ctx, width, height, 1, VK_IMAGE_VIEW_TYPE_2D, sc->frame_format,
                            VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, &sc->frame, err,
                            err_size);
}

/* Largest rectangle of the frame's aspect centred in the swapchain image. */
static void fit(const rnd_swapchain* sc, uint32_t w, uint32_t h, VkOffset3D out[2])
{
    double s = (double)sc->extent.width / w < (double)sc->extent.height / h ? (double)sc->extent.width / w
                                                                             : (double)sc->extent.height / h;
    int32_t dw = (int32_t)(w * s + 0.5), dh = (int32_t)(h * s + 0.5);
    dw = dw < 1 ? 1 : dw;
    dh = dh < 1 ? 1 : dh;
    out[0] = (VkOffset3D){((int32_t)sc->extent.width - dw) / 2, ((int32_t)sc->extent.height - dh) / 2, 0};
    out[1] = (VkOffset3D){out[0].x + dw, out[0].y + dh, 1};
}

static void record(rnd_swapchain* sc, VkImage target, uint32_t w, uint32_t h, bool shot)
{
    VkCommandBuffer cmd = sc->stream.cmd;
    const VkImageAspectFlags color = VK_IMAGE_ASPECT_COLOR_BIT;
    rnd_image_barrier(cmd, sc->frame.image, color, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    VkBufferImageCopy up = {.imageSubresource = {color, 0, 0, 1}, .imageExtent = {w, h, 1}};
    vkCmdCopyBufferToImage(cmd, sc->upload.buffer, sc->frame.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &up);
    rnd_image_barrier(cmd, sc->frame.image, color, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    /* src stage = the acquire semaphore's wait stage, so the transition waits for the image */
    rnd_image_barrier(cmd, target, color, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT);
    VkClearColorValue black = {.float32 = {0.0f, 0.0f, 0.0f, 1.0f}};
    VkImageSubresourceRange range = {color, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1, &range);
    rnd_image_barrier(cmd, target, color, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_BLIT_BIT,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT);
    VkImageBlit blit = {.srcSubresource = {color, 0, 0, 1},
                        .srcOffsets = {{0, 0, 0}, {(int32_t)w, (int32_t)h, 1}},
                        .dstSubresource = {color, 0, 0, 1}};
    fit(sc, w, h, blit.dstOffsets);
    vkCmdBlitImage(cmd, sc->frame.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, sc->filter);
    VkImageLayout last = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    if (shot) {
        rnd_image_barrier(cmd, target, color, last, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_BLIT_BIT,
                          VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        VkBufferImageCopy down = {.imageSubresource = {color, 0, 0, 1},
                                  .imageExtent = {sc->extent.width, sc->extent.height, 1}};
        vkCmdCopyImageToBuffer(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, sc->shot.buffer, 1, &down);
        last = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    }
    /* the present semaphore makes the writes available to the presentation engine */
    rnd_image_barrier(cmd, target, color, last, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_NONE, 0);
}

static bool submit(rnd_context* ctx, rnd_swapchain* sc, uint32_t index, char* err, size_t err_size)
{
    if (!RND_VK_OK(vkEndCommandBuffer(sc->stream.cmd), err, err_size))
        return false;
    VkPipelineStageFlags wait_stage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    VkSubmitInfo info = {.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
                         .waitSemaphoreCount = 1,
                         .pWaitSemaphores = &sc->acquired,
                         .pWaitDstStageMask = &wait_stage,
                         .commandBufferCount = 1,
                         .pCommandBuffers = &sc->stream.cmd,
                         .signalSemaphoreCount = 1,
                         .pSignalSemaphores = &sc->rendered[index]};
    pthread_mutex_lock(&ctx->queue_mutex);
    VkResult r = vkQueueSubmit(ctx->queue, 1, &info, sc->stream.fence);
    pthread_mutex_unlock(&ctx->queue_mutex);
    if (!rnd_vk_ok(r, "vkQueueSubmit", err, err_size))
        return false;
    bool ok = RND_VK_OK(vkWaitForFences(ctx->device, 1, &sc->stream.fence, VK_TRUE, UINT64_MAX), err, err_size);
    return RND_VK_OK(vkResetFences(ctx->device, 1, &sc->stream.fence), err, err_size) && ok;
}

/* The swapchain image's bytes as RGBA with opaque alpha. */
static void shot_to_rgba(const rnd_swapchain* sc, uint8_t* shot)
{
    const uint8_t* src = sc->shot.mapped;
    size_t pixels = (size_t)sc->extent.width * sc->extent.height;
    bool bgra = sc->format.format == VK_FORMAT_B8G8R8A8_SRGB || sc->format.format == VK_FORMAT_B8G8R8A8_UNORM;
    for (size_t i = 0; i < pixels; i++) {
        shot[4 * i + 0] = src[4 * i + (bgra ? 2 : 0)];
        shot[4 * i + 1] = src[4 * i + 1];
        shot[4 * i + 2] = src[4 * i + (bgra ? 0 : 2)];
        shot[4 * i + 3] = 255;
    }
}

rnd_present_result rnd_swapchain_present(rnd_context* ctx, rnd_swapchain* sc, const uint8_t* rgba, uint32_t width,
                                         uint32_t height, uint8_t* shot, char* err, size_t err_size)
{
    assert(rgba && width > 0 && height > 0);
    if (shot && !(sc->usage & VK_IMAGE_USAGE_TRANSFER_SRC_BIT)) {
        snprintf(err, err_size, "this window surface cannot be read back (no TRANSFER_SRC usage)");
        return RND_PRESENT_ERROR;
    }
    VkDeviceSize bytes = (VkDeviceSize)width * height * 4;
    VkDeviceSize shot_bytes = (VkDeviceSize)sc->extent.width * sc->extent.height * 4;
    if (!reserve_frame(ctx, sc, width, height, err, err_size) ||
        !rnd_buffer_reserve(ctx, &sc->upload, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, err, err_size) ||
        (shot && !rnd_buffer_reserve(ctx, &sc->shot, shot_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, err, err_size)))
        return RND_PRESENT_ERROR;
    uint32_t index = 0;
    VkResult r = vkAcquireNextImageKHR(ctx->device, sc->swapchain, UINT64_MAX, sc->acquired, VK_NULL_HANDLE, &index);
    if (r == VK_ERROR_OUT_OF_DATE_KHR)
        return RND_PRESENT_RECREATE; /* nothing was signalled: safe to rebuild */
    bool suboptimal = r == VK_SUBOPTIMAL_KHR; /* the semaphore is signalled: finish this frame first */
    if (r != VK_SUCCESS && !suboptimal)
    {
        rnd_vk_ok(r, "vkAcquireNextImageKHR", err, err_size);
        return RND_PRESENT_ERROR;
    }
    memcpy(sc->upload.mapped, rgba, (size_t)bytes);
    if (!rnd_stream_begin(ctx, &sc->stream, err, err_size))
        return RND_PRESENT_ERROR;
    record(sc, sc->images[index], width, height, shot != NULL);
    if (!submit(ctx, sc, index, err, err_size))
        return RND_PRESENT_ERROR;
    if (shot)
        shot_to_rgba(sc, shot);
    VkPresentInfoKHR present = {.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR,
                                .waitSemaphoreCount = 1,
                                .pWaitSemaphores = &sc->rendered[index],
                                .swapchainCount = 1,
                                .pSwapchains = &sc->swapchain,
                                .pImageIndices = &index};
    pthread_mutex_lock(&ctx->queue_mutex);
    r = vkQueuePresentKHR(ctx->queue, &present);
    pthread_mutex_unlock(&ctx->queue_mutex);
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR || (r == VK_SUCCESS && suboptimal))
        return RND_PRESENT_SHOWN_STALE; /* an out-of-date present drops the frame: nothing to redo */
    return rnd_vk_ok(r, "vkQueuePresentKHR", err, err_size) ? RND_PRESENT_OK : RND_PRESENT_ERROR;
}
