/* draw.c - the mesh pass: clear, draw all triangles or an ascending subset
 * through the vertex-pulling pipeline, leave the attachments ready for
 * read-back. Synchronous: returns when the GPU is done. */
#include "render_vk.h"

#include "clock.h"
#include "mesh_shared.h"
#include "log.h"

#include <assert.h>
#include <stdlib.h>
#include <string.h>

static int compare_u32(const void* a, const void* b)
{
    uint32_t x = *(const uint32_t*)a, y = *(const uint32_t*)b;
    return (x > y) - (x < y);
}

/* Checks every id against the scene (an out-of-range id would make the
 * vertex shader read past its buffers) and reports whether the list is
 * already ascending. */
static bool check_ids(const uint32_t* ids, uint32_t count, uint32_t triangle_count, bool* ascending)
{
    *ascending = true;
    for (uint32_t i = 0; i < count; i++) {
        if (ids[i] >= triangle_count) {
            tv_log(TV_LOG_ERROR, "rnd_draw: tri_ids[%u] = %u, the scene has %u triangles", i, ids[i], triangle_count);
            return false;
        }
        if (i > 0 && ids[i] < ids[i - 1])
            *ascending = false;
    }
    return true;
}

/* Writes the subset in ascending order into the target's id buffer. Drawing
 * in ascending id order is what makes equal-depth ties resolve as in the
 * full draw (the first triangle in primitive order keeps the pixel under a
 * LESS test). */
static bool upload_subset(rnd_context* ctx, rnd_target* t, const uint32_t* ids, uint32_t count,
                          uint32_t triangle_count)
{
    bool ascending;
    if (!check_ids(ids, count, triangle_count, &ascending) || !rnd_target_reserve_draw_ids(ctx, t, count))
        return false;
    const size_t bytes = (size_t)count * sizeof(uint32_t);
    if (ascending) {
        memcpy(t->draw_ids.mapped, ids, bytes);
        return true;
    }
    if (t->sort_capacity < count) {
        uint32_t* grown = realloc(t->sort_scratch, bytes);
        if (!grown) {
            tv_log(TV_LOG_ERROR, "rnd_draw: out of memory sorting %u triangle ids", count);
            return false;
        }
        t->sort_scratch = grown;
        t->sort_capacity = count;
    }
    memcpy(t->sort_scratch, ids, bytes);
    qsort(t->sort_scratch, count, sizeof(uint32_t), compare_u32);
    memcpy(t->draw_ids.mapped, t->sort_scratch, bytes);
    return true;
}

static void begin_attachments(VkCommandBuffer cmd, rnd_target* t)
{
    /* UNDEFINED: every draw clears, so the previous contents never matter;
     * the source scope waits for read-back copies of the previous draw. */
    const VkPipelineStageFlags2 out = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
    const VkAccessFlags2 write = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
    rnd_image_barrier(cmd, t->color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT, 0, out, write);
    rnd_image_barrier(cmd, t->ids.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT, 0, out, write);
    rnd_image_barrier(cmd, t->depth.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT, 0,
                      VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
}

static void end_attachments(VkCommandBuffer cmd, rnd_target* t)
{
    const VkPipelineStageFlags2 out = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
    const VkAccessFlags2 write = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
    const VkPipelineStageFlags2 copy = VK_PIPELINE_STAGE_2_COPY_BIT;
    const VkAccessFlags2 read = VK_ACCESS_2_TRANSFER_READ_BIT;
    rnd_image_barrier(cmd, t->color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, out, write, copy, read);
    rnd_image_barrier(cmd, t->ids.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, out, write, copy, read);
    rnd_image_barrier(cmd, t->depth.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, copy, read);
}

static void record_pass(rnd_context* ctx, rnd_target* t, const rnd_gpu_scene* scene, const rnd_mesh_push* push,
                        uint32_t tri_count)
{
    VkCommandBuffer cmd = t->stream.cmd;
    VkRenderingAttachmentInfo colors[2] = {
        {.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
         .imageView = t->color.view,
         .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
         .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
         .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
         .clearValue.color.float32 = {RND_CLEAR_COLOR_LINEAR, 0.0f}},
        {.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
         .imageView = t->ids.view,
         .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
         .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
         .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
         .clearValue.color.uint32 = {TV_NO_TRIANGLE, 0, 0, 0}},
    };
    VkRenderingAttachmentInfo depth = {.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                       .imageView = t->depth.view,
                                       .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                                       .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                       .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                       .clearValue.depthStencil = {1.0f, 0}};
    VkRect2D area = {{0, 0}, {t->width, t->height}};
    VkRenderingInfo rendering = {.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                                 .renderArea = area,
                                 .layerCount = 1,
                                 .colorAttachmentCount = 2,
                                 .pColorAttachments = colors,
                                 .pDepthAttachment = &depth};
    vkCmdBeginRendering(cmd, &rendering);
    VkDescriptorSet sets[2];
    sets[TV_SET_SCENE] = scene->set;
    sets[TV_SET_DRAW] = t->draw_set;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, ctx->mesh_pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, ctx->mesh_layout, 0, 2, sets, 0, NULL);
    vkCmdSetViewport(cmd, 0, 1, &(VkViewport){0.0f, 0.0f, (float)t->width, (float)t->height, 0.0f, 1.0f});
    vkCmdSetScissor(cmd, 0, 1, &area);
    vkCmdPushConstants(cmd, ctx->mesh_layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof *push, push);
    if (tri_count > 0)
        vkCmdDraw(cmd, tri_count * 3, 1, 0, 0);
    vkCmdEndRendering(cmd);
}

bool rnd_draw(rnd_context* ctx, rnd_target* t, const rnd_gpu_scene* scene, const rnd_camera* cam,
              const uint32_t* tri_ids, uint32_t tri_count, rnd_draw_stats* stats)
{
    assert(ctx && t && scene && cam);
    const double start = tv_now_ms();
    t->drawn = false; /* until this draw has completed */
    rnd_mesh_push push = {.use_draw_ids = tri_ids != NULL};
    rnd_camera_view_proj(cam, (float)t->width / (float)t->height, push.view_proj);
    if (tri_ids) {
        if (!upload_subset(ctx, t, tri_ids, tri_count, scene->triangle_count))
            return false;
    } else {
        tri_count = scene->triangle_count;
    }
    /* 3 vertices per triangle must fit vkCmdDraw's uint32_t vertex count */
    assert(tri_count <= UINT32_MAX / 3);
    rnd_stream* s = &t->stream;
    if (!rnd_stream_begin(ctx, s, NULL, 0))
        return false;
    rnd_stream_timestamp(ctx, s, 0);
    begin_attachments(s->cmd, t);
    record_pass(ctx, t, scene, &push, tri_count);
    end_attachments(s->cmd, t);
    rnd_stream_timestamp(ctx, s, 1);
    if (!rnd_stream_submit_wait(ctx, s, NULL, 0))
        return false;
    t->drawn = true;
    if (stats) {
        stats->cpu_ms = tv_now_ms() - start;
        stats->gpu_ms = rnd_stream_gpu_ms(ctx, s);
        stats->triangles = tri_count;
    }
    return true;
}
