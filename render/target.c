/* target.c - offscreen colour/id/depth targets, their per-target draw
 * resources (stream, subset id buffer, descriptor set) and read-backs.
 *
 * Between draws every attachment rests in TRANSFER_SRC_OPTIMAL, so a
 * read-back is one copy and the next draw starts from a known layout. */
#include "render_vk.h"

#include "mesh_shared.h"
#include "log.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Initial capacity of the subset id buffer (ids); it grows on demand. */
#define INITIAL_DRAW_IDS 4096

static const VkBufferUsageFlags draw_ids_usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;

/* Points the draw set at the current draw_ids buffer. */
static void bind_draw_ids(rnd_context* ctx, rnd_target* t)
{
    VkWriteDescriptorSet write = {.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                                  .dstSet = t->draw_set,
                                  .dstBinding = TV_BIND_DRAW_IDS,
                                  .descriptorCount = 1,
                                  .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                  .pBufferInfo = &(VkDescriptorBufferInfo){t->draw_ids.buffer, 0, VK_WHOLE_SIZE}};
    vkUpdateDescriptorSets(ctx->device, 1, &write, 0, NULL);
}

static bool create_draw_set(rnd_context* ctx, rnd_target* t, char* err, size_t err_size)
{
    const VkDescriptorPoolSize size = {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1};
    if (!rnd_descriptor_set_create(ctx, ctx->draw_set_layout, &size, 1, &t->pool, &t->draw_set, err, err_size))
        return false;
    bind_draw_ids(ctx, t);
    return true;
}

bool rnd_target_reserve_draw_ids(rnd_context* ctx, rnd_target* t, uint32_t count)
{
    const VkDeviceSize bytes = (VkDeviceSize)count * sizeof(uint32_t);
    if (t->draw_ids.size >= bytes)
        return true;
    /* Rebind whenever the buffer is replaced, never by comparing handles:
     * the new buffer can get the freed one's handle value (lavapipe's handles
     * are heap pointers), and the set would keep reading the freed buffer.
     * The validation layer wraps handles uniquely, which hid this. */
    if (!rnd_buffer_reserve(ctx, &t->draw_ids, bytes, draw_ids_usage, NULL, 0))
        return false;
    bind_draw_ids(ctx, t);
    return true;
}

rnd_target* rnd_target_create(rnd_context* ctx, uint32_t width, uint32_t height, char* err, size_t err_size)
{
    const uint32_t max_dim = ctx->props.limits.maxImageDimension2D;
    if (width == 0 || height == 0 || width > max_dim || height > max_dim) {
        snprintf(err, err_size, "render target %ux%u: each side must be 1..%u", width, height, max_dim);
        return NULL;
    }
    rnd_target* t = calloc(1, sizeof *t);
    if (!t) {
        snprintf(err, err_size, "out of memory creating a %ux%u render target", width, height);
        return NULL;
    }
    t->width = width;
    t->height = height;
    const VkImageUsageFlags color_usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    bool ok =
        rnd_image_create(ctx, width, height, 1, VK_IMAGE_VIEW_TYPE_2D, RND_COLOR_FORMAT, color_usage, &t->color, err, err_size) &&
        rnd_image_create(ctx, width, height, 1, VK_IMAGE_VIEW_TYPE_2D, RND_ID_FORMAT, color_usage, &t->ids, err, err_size) &&
        rnd_image_create(ctx, width, height, 1, VK_IMAGE_VIEW_TYPE_2D, RND_DEPTH_FORMAT,
                         VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, &t->depth,
                         err, err_size) &&
        rnd_stream_create(ctx, &t->stream, err, err_size) &&
        rnd_buffer_create(ctx, (VkDeviceSize)width * height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true,
                          &t->readback, err, err_size) &&
        rnd_buffer_create(ctx, INITIAL_DRAW_IDS * sizeof(uint32_t), draw_ids_usage, true, &t->draw_ids, err,
                          err_size) &&
        create_draw_set(ctx, t, err, err_size);
    if (!ok) {
        rnd_target_destroy(ctx, t);
        return NULL;
    }
    return t;
}

void rnd_target_destroy(rnd_context* ctx, rnd_target* t)
{
    if (!t)
        return;
    if (t->pool)
        vkDestroyDescriptorPool(ctx->device, t->pool, NULL);
    rnd_buffer_destroy(ctx, &t->draw_ids);
    rnd_buffer_destroy(ctx, &t->readback);
    rnd_stream_destroy(ctx, &t->stream);
    rnd_image_destroy(ctx, &t->depth);
    rnd_image_destroy(ctx, &t->ids);
    rnd_image_destroy(ctx, &t->color);
    free(t->sort_scratch);
    free(t->blend_keys);
    free(t);
}

uint32_t rnd_target_width(const rnd_target* t) { return t->width; }
uint32_t rnd_target_height(const rnd_target* t) { return t->height; }

/* Copies one attachment (4 bytes per pixel for all three formats) into out. */
static bool read_image(rnd_context* ctx, rnd_target* t, const rnd_image* image, void* out)
{
    if (!t->drawn) {
        tv_log(TV_LOG_ERROR, "rnd_target_read: the %ux%u target holds no finished draw", t->width, t->height);
        return false;
    }
    rnd_stream* s = &t->stream;
    if (!rnd_stream_begin(ctx, s, NULL, 0))
        return false;
    VkBufferImageCopy region = {.imageSubresource = {rnd_format_aspect(image->format), 0, 0, 1},
                                .imageExtent = {t->width, t->height, 1}};
    vkCmdCopyImageToBuffer(s->cmd, image->image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, t->readback.buffer, 1, &region);
    VkMemoryBarrier2 to_host = {.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                                .srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT,
                                .srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                .dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT,
                                .dstAccessMask = VK_ACCESS_2_HOST_READ_BIT};
    vkCmdPipelineBarrier2(s->cmd, &(VkDependencyInfo){.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                                      .memoryBarrierCount = 1,
                                                      .pMemoryBarriers = &to_host});
    if (!rnd_stream_submit_wait(ctx, s, NULL, 0))
        return false;
    memcpy(out, t->readback.mapped, (size_t)t->width * t->height * 4);
    return true;
}

bool rnd_target_read_color(rnd_context* ctx, rnd_target* t, uint8_t* rgba) { return read_image(ctx, t, &t->color, rgba); }
bool rnd_target_read_ids(rnd_context* ctx, rnd_target* t, uint32_t* ids) { return read_image(ctx, t, &t->ids, ids); }
bool rnd_target_read_depth(rnd_context* ctx, rnd_target* t, float* depth) { return read_image(ctx, t, &t->depth, depth); }
