/* resources.c - buffers, images, layout barriers and staged uploads. Each
 * resource gets its own allocation: the renderer holds a few dozen at most,
 * far below maxMemoryAllocationCount. */
#include "render_vk.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static bool find_memory_type(rnd_context* ctx, uint32_t type_bits, VkMemoryPropertyFlags props, uint32_t* out)
{
    for (uint32_t i = 0; i < ctx->memory.memoryTypeCount; i++) {
        if ((type_bits & (1u << i)) && (ctx->memory.memoryTypes[i].propertyFlags & props) == props) {
            *out = i;
            return true;
        }
    }
    return false;
}

static bool allocate(rnd_context* ctx, VkMemoryRequirements req, VkMemoryPropertyFlags props, VkDeviceMemory* out,
                     char* err, size_t err_size)
{
    uint32_t type;
    if (!find_memory_type(ctx, req.memoryTypeBits, props, &type)) {
        snprintf(err, err_size, "no Vulkan memory type with properties 0x%x for %llu bytes", (unsigned)props,
                 (unsigned long long)req.size);
        return false;
    }
    VkMemoryAllocateInfo info = {.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
                                 .allocationSize = req.size,
                                 .memoryTypeIndex = type};
    return RND_VK_OK(vkAllocateMemory(ctx->device, &info, NULL, out), err, err_size);
}

bool rnd_buffer_create(rnd_context* ctx, VkDeviceSize size, VkBufferUsageFlags usage, bool host_visible,
                       rnd_buffer* out, char* err, size_t err_size)
{
    memset(out, 0, sizeof *out);
    VkBufferCreateInfo info = {.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                               .size = size,
                               .usage = usage,
                               .sharingMode = VK_SHARING_MODE_EXCLUSIVE};
    if (!RND_VK_OK(vkCreateBuffer(ctx->device, &info, NULL, &out->buffer), err, err_size))
        return false;
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(ctx->device, out->buffer, &req);
    VkMemoryPropertyFlags props = host_visible
                                      ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                                      : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    if (!allocate(ctx, req, props, &out->memory, err, err_size) ||
        !RND_VK_OK(vkBindBufferMemory(ctx->device, out->buffer, out->memory, 0), err, err_size) ||
        (host_visible && !RND_VK_OK(vkMapMemory(ctx->device, out->memory, 0, VK_WHOLE_SIZE, 0, &out->mapped), err,
                                    err_size))) {
        rnd_buffer_destroy(ctx, out);
        return false;
    }
    out->size = size;
    return true;
}

void rnd_buffer_destroy(rnd_context* ctx, rnd_buffer* b)
{
    if (b->buffer)
        vkDestroyBuffer(ctx->device, b->buffer, NULL);
    if (b->memory)
        vkFreeMemory(ctx->device, b->memory, NULL); /* implicitly unmaps */
    memset(b, 0, sizeof *b);
}

bool rnd_buffer_reserve(rnd_context* ctx, rnd_buffer* b, VkDeviceSize size, VkBufferUsageFlags usage, char* err,
                        size_t err_size)
{
    if (b->buffer && b->size >= size)
        return true;
    rnd_buffer_destroy(ctx, b);
    return rnd_buffer_create(ctx, size + size / 2, usage, true, b, err, err_size);
}

VkImageAspectFlags rnd_format_aspect(VkFormat format)
{
    return format == VK_FORMAT_D32_SFLOAT ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

bool rnd_image_create(rnd_context* ctx, uint32_t width, uint32_t height, uint32_t layers, VkImageViewType view_type,
                      VkFormat format, VkImageUsageFlags usage, rnd_image* out, char* err, size_t err_size)
{
    memset(out, 0, sizeof *out);
    VkImageCreateInfo info = {.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
                              .imageType = VK_IMAGE_TYPE_2D,
                              .format = format,
                              .extent = {width, height, 1},
                              .mipLevels = 1,
                              .arrayLayers = layers,
                              .samples = VK_SAMPLE_COUNT_1_BIT,
                              .tiling = VK_IMAGE_TILING_OPTIMAL,
                              .usage = usage,
                              .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED};
    if (!RND_VK_OK(vkCreateImage(ctx->device, &info, NULL, &out->image), err, err_size))
        return false;
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(ctx->device, out->image, &req);
    if (!allocate(ctx, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, &out->memory, err, err_size) ||
        !RND_VK_OK(vkBindImageMemory(ctx->device, out->image, out->memory, 0), err, err_size))
        goto fail;
    VkImageViewCreateInfo view = {.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                  .image = out->image,
                                  .viewType = view_type,
                                  .format = format,
                                  .subresourceRange = {rnd_format_aspect(format), 0, 1, 0, layers}};
    if (!RND_VK_OK(vkCreateImageView(ctx->device, &view, NULL, &out->view), err, err_size))
        goto fail;
    out->format = format;
    out->width = width;
    out->height = height;
    out->layers = layers;
    return true;
fail:
    rnd_image_destroy(ctx, out);
    return false;
}

void rnd_image_destroy(rnd_context* ctx, rnd_image* image)
{
    if (image->view)
        vkDestroyImageView(ctx->device, image->view, NULL);
    if (image->image)
        vkDestroyImage(ctx->device, image->image, NULL);
    if (image->memory)
        vkFreeMemory(ctx->device, image->memory, NULL);
    memset(image, 0, sizeof *image);
}

void rnd_image_barrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout old_layout,
                       VkImageLayout new_layout, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                       VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access)
{
    VkImageMemoryBarrier2 barrier = {.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
                                     .srcStageMask = src_stage,
                                     .srcAccessMask = src_access,
                                     .dstStageMask = dst_stage,
                                     .dstAccessMask = dst_access,
                                     .oldLayout = old_layout,
                                     .newLayout = new_layout,
                                     .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                     .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                     .image = image,
                                     .subresourceRange = {aspect, 0, 1, 0, VK_REMAINING_ARRAY_LAYERS}};
    VkDependencyInfo dep = {.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                            .imageMemoryBarrierCount = 1,
                            .pImageMemoryBarriers = &barrier};
    vkCmdPipelineBarrier2(cmd, &dep);
}

/* A new mapped staging buffer holding a copy of data, owned by staging. */
static rnd_buffer* stage(rnd_context* ctx, rnd_staging* staging, const void* data, VkDeviceSize size, char* err,
                         size_t err_size)
{
    if (staging->count == staging->capacity) {
        uint32_t capacity = staging->capacity ? staging->capacity * 2 : 16;
        rnd_buffer* grown = realloc(staging->buffers, capacity * sizeof *grown);
        if (!grown) {
            snprintf(err, err_size, "out of memory for staging buffers");
            return NULL;
        }
        staging->buffers = grown;
        staging->capacity = capacity;
    }
    rnd_buffer* b = &staging->buffers[staging->count];
    if (!rnd_buffer_create(ctx, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true, b, err, err_size))
        return NULL;
    staging->count++;
    memcpy(b->mapped, data, size);
    return b;
}

bool rnd_upload_buffer_at(rnd_context* ctx, VkCommandBuffer cmd, rnd_staging* staging, const void* data,
                          VkDeviceSize size, VkBuffer dst, VkDeviceSize offset, char* err, size_t err_size)
{
    rnd_buffer* src = stage(ctx, staging, data, size, err, err_size);
    if (!src)
        return false;
    vkCmdCopyBuffer(cmd, src->buffer, dst, 1, &(VkBufferCopy){.dstOffset = offset, .size = size});
    return true;
}

bool rnd_upload_buffer(rnd_context* ctx, VkCommandBuffer cmd, rnd_staging* staging, const void* data,
                       VkDeviceSize size, VkBuffer dst, char* err, size_t err_size)
{
    return rnd_upload_buffer_at(ctx, cmd, staging, data, size, dst, 0, err, err_size);
}

bool rnd_upload_image(rnd_context* ctx, VkCommandBuffer cmd, rnd_staging* staging, const void* texels,
                      VkDeviceSize size, const rnd_image* dst, char* err, size_t err_size)
{
    rnd_buffer* src = stage(ctx, staging, texels, size, err, err_size);
    if (!src)
        return false;
    VkImageAspectFlags aspect = rnd_format_aspect(dst->format);
    rnd_image_barrier(cmd, dst->image, aspect, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    VkBufferImageCopy region = {.imageSubresource = {aspect, 0, 0, dst->layers},
                                .imageExtent = {dst->width, dst->height, 1}};
    vkCmdCopyBufferToImage(cmd, src->buffer, dst->image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    rnd_image_barrier(cmd, dst->image, aspect, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    return true;
}

void rnd_staging_release(rnd_context* ctx, rnd_staging* staging)
{
    for (uint32_t i = 0; i < staging->count; i++)
        rnd_buffer_destroy(ctx, &staging->buffers[i]);
    free(staging->buffers);
    memset(staging, 0, sizeof *staging);
}
