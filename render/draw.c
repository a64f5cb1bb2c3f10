/* draw.c - the mesh pass: clear, draw all triangles or an ascending subset
 * through the vertex-pulling pipeline, leave the attachments ready for
 * read-back. Synchronous: returns when the GPU is done.
 *
 * A draw that holds BLEND triangles takes three passes (docs/rendering.md,
 * "Blended materials"): every other triangle with BLEND ones clipped away;
 * the BLEND ones back to front by the view depth of their centroids,
 * blended, depth tested but not written; the BLEND ones again in ascending
 * id order writing depth and ids only, so that depth and ids keep the
 * nearest surface, BLEND included, exactly as an opaque draw would. */
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

/* Writes the subset in ascending order into the target's id buffer, with
 * room for 2 * blend_count ids after it, and returns the ascending list (NULL
 * on failure). Drawing in ascending id order is what makes equal-depth ties
 * resolve as in the full draw (the first triangle in primitive order keeps
 * the pixel under a LESS test). */
static const uint32_t* upload_subset(rnd_context* ctx, rnd_target* t, const uint32_t* ids, uint32_t count,
                                     uint32_t triangle_count, uint32_t blend_count)
{
    bool ascending;
    if (!check_ids(ids, count, triangle_count, &ascending) ||
        !rnd_target_reserve_draw_ids(ctx, t, count + 2 * blend_count))
        return NULL;
    const size_t bytes = (size_t)count * sizeof(uint32_t);
    if (ascending) {
        memcpy(t->draw_ids.mapped, ids, bytes);
        return ids;
    }
    if (t->sort_capacity < count) {
        uint32_t* grown = realloc(t->sort_scratch, bytes);
        if (!grown) {
            tv_log(TV_LOG_ERROR, "rnd_draw: out of memory sorting %u triangle ids", count);
            return NULL;
        }
        t->sort_scratch = grown;
        t->sort_capacity = count;
    }
    memcpy(t->sort_scratch, ids, bytes);
    qsort(t->sort_scratch, count, sizeof(uint32_t), compare_u32);
    memcpy(t->draw_ids.mapped, t->sort_scratch, bytes);
    return t->sort_scratch;
}

/* A BLEND triangle of a draw: its view-space z (more negative is farther)
 * and its index in the scene's blend list. */
typedef struct rnd_blend_key {
    float z;
    uint32_t blend;
} rnd_blend_key;

static int farther_first(const void* a, const void* b)
{
    const rnd_blend_key *x = a, *y = b;
    if (x->z != y->z)
        return x->z < y->z ? -1 : 1;
    return (x->blend > y->blend) - (x->blend < y->blend);
}

/* Writes the BLEND triangles of the draw (all of them when drawn == NULL,
 * else those in the ascending list drawn[0..count)) after slot `first` of
 * the id buffer: ascending, then back to front. Returns how many, or
 * UINT32_MAX when out of memory. */
static uint32_t upload_blend(rnd_target* t, const rnd_gpu_scene* scene, const float view[16], const uint32_t* drawn,
                             uint32_t count, uint32_t first)
{
    if (scene->blend_count == 0)
        return 0;
    if (t->blend_key_capacity < scene->blend_count) {
        rnd_blend_key* grown = realloc(t->blend_keys, sizeof *grown * scene->blend_count);
        if (!grown) {
            tv_log(TV_LOG_ERROR, "rnd_draw: out of memory sorting %u blended triangles", scene->blend_count);
            return UINT32_MAX;
        }
        t->blend_keys = grown;
        t->blend_key_capacity = scene->blend_count;
    }
    uint32_t n = 0;
    for (uint32_t b = 0, i = 0; b < scene->blend_count; b++) { /* merge of two ascending lists */
        if (drawn) {
            while (i < count && drawn[i] < scene->blend_ids[b])
                i++;
            if (i == count)
                break;
            if (drawn[i] != scene->blend_ids[b])
                continue;
        }
        const float* c = scene->blend_centroids + 3 * (size_t)b;
        t->blend_keys[n++] = (rnd_blend_key){view[2] * c[0] + view[6] * c[1] + view[10] * c[2] + view[14], b};
    }
    uint32_t* ascending = (uint32_t*)t->draw_ids.mapped + first;
    for (uint32_t k = 0; k < n; k++)
        ascending[k] = scene->blend_ids[t->blend_keys[k].blend];
    qsort(t->blend_keys, n, sizeof *t->blend_keys, farther_first);
    for (uint32_t k = 0; k < n; k++)
        ascending[n + k] = scene->blend_ids[t->blend_keys[k].blend];
    return n;
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

/* Draws slots [0, tri_count) and, when blend_count > 0, the BLEND lists at
 * id-buffer slot blend_first (ascending) and blend_first + blend_count (back
 * to front). */
static void record_pass(rnd_context* ctx, rnd_target* t, const rnd_gpu_scene* scene, rnd_mesh_push* push,
                        uint32_t tri_count, uint32_t blend_first, uint32_t blend_count)
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
    push->skip_blend = blend_count > 0;
    vkCmdPushConstants(cmd, ctx->mesh_layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof *push, push);
    if (tri_count > 0)
        vkCmdDraw(cmd, tri_count * 3, 1, 0, 0);
    if (blend_count > 0) {
        push->use_draw_ids = 1;
        push->skip_blend = 0;
        vkCmdPushConstants(cmd, ctx->mesh_layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof *push, push);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, ctx->blend_pipeline);
        vkCmdDraw(cmd, blend_count * 3, 1, (blend_first + blend_count) * 3, 0);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, ctx->blend_depth_pipeline);
        vkCmdDraw(cmd, blend_count * 3, 1, blend_first * 3, 0);
    }
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
    const uint32_t* drawn = NULL;
    /* the draw's slots, its BLEND lists included, must fit vkCmdDraw's uint32_t vertex count */
    assert((uint64_t)(tri_ids ? tri_count : scene->triangle_count) + 2 * (uint64_t)scene->blend_count <=
           UINT32_MAX / 3);
    if (tri_ids) {
        drawn = upload_subset(ctx, t, tri_ids, tri_count, scene->triangle_count, scene->blend_count);
        if (!drawn)
            return false;
    } else {
        tri_count = scene->triangle_count;
        if (scene->blend_count > 0 && !rnd_target_reserve_draw_ids(ctx, t, 2 * scene->blend_count))
            return false;
    }
    float view[16];
    rnd_camera_view(cam, view);
    const uint32_t blend_first = tri_ids ? tri_count : 0;
    const uint32_t blend_count = upload_blend(t, scene, view, drawn, tri_count, blend_first);
    if (blend_count == UINT32_MAX)
        return false;
    rnd_stream* s = &t->stream;
    if (!rnd_stream_begin(ctx, s, NULL, 0))
        return false;
    rnd_stream_timestamp(ctx, s, 0);
    begin_attachments(s->cmd, t);
    record_pass(ctx, t, scene, &push, tri_count, blend_first, blend_count);
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
