/* gpu_compute.c - pvs_compute: P0 on the CPU, then one command buffer with
 * P1-P3 per layer and P4, one submission, one wait; the flag buffer is then
 * compacted on the CPU into the sorted id list. */
#include "gpu_internal.h"
#include "patches.h"

#include "clock.h"
#include "log.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cglm/cglm.h>

float pvs_max_apex_offset(float near_m)
{
    if (!(near_m > 0.0f))
        near_m = PVS_DEFAULT_NEAR;
    return sqrtf(PVS_MAX_DEPTH_STEP_M * near_m * 16777216.0f); /* step = 2^-24 z^2 / near */
}

/* Vertical FOV of the PVS frustum: fov_pvs_deg spans the smaller axis, so
 * the frustum contains the square one of half-angle α that predict/ sizes
 * the viewcell for (docs/prediction.md) at any resolution. */
static float fov_y_deg(const pvs_context* ctx, const pvs_viewcell* vc)
{
    float aspect = (float)ctx->width / (float)ctx->height;
    return aspect >= 1.0f ? vc->fov_pvs_deg : rnd_fov_y_from_x(vc->fov_pvs_deg, aspect);
}

/* z = Δ / tan α: the apex lies z behind v0 (paper section 3.4). */
static float apex_offset(const pvs_viewcell* vc)
{
    return vc->delta / tanf(glm_rad(vc->fov_pvs_deg) * 0.5f);
}

/* The apex offset the depth buffer resolves (pvs.h, PVS_MAX_DEPTH_STEP_M). */
static bool check_apex_offset(const pvs_context* ctx, const pvs_viewcell* vc, char* err, size_t err_size)
{
    float z_max = pvs_max_apex_offset(ctx->near_m);
    if (apex_offset(vc) <= z_max)
        return true;
    snprintf(err, err_size,
             "pvs_compute: viewcell delta %g m at PVS FOV %g deg is beyond the %g m the PVS depth buffer "
             "resolves (apex %g m behind v0, at most %g m; docs/pvs-gpu-passes.md)",
             vc->delta, vc->fov_pvs_deg, z_max * tanf(glm_rad(vc->fov_pvs_deg) * 0.5f), apex_offset(vc), z_max);
    return false;
}

/* Far plane from v*: an eye up to 2z ahead of v* sees far_m further. */
static float far_dist(const pvs_viewcell* vc)
{
    return vc->far_m + 2.0f * apex_offset(vc);
}

rnd_camera pvs_apex_camera(const pvs_context* ctx, const pvs_viewcell* vc)
{
    vec3 f = {vc->forward[0], vc->forward[1], vc->forward[2]}, up = {vc->up[0], vc->up[1], vc->up[2]};
    glm_vec3_normalize(f);
    float z = apex_offset(vc);
    rnd_camera cam = {.fov_y_deg = fov_y_deg(ctx, vc), .near_m = ctx->near_m,
                      .far_m = far_dist(vc) * (float)TV_PVS_RASTER_FAR_SCALE};
    for (int i = 0; i < 3; i++)
        cam.position[i] = vc->v0[i] - z * f[i];
    versor q;
    glm_quat_for(f, up, q);
    memcpy(cam.orientation, q, sizeof q);
    return cam;
}

static pvs_view layer_view(const pvs_context* ctx, const pvs_viewcell* vc, const rnd_camera* cam)
{
    pvs_view v = {.fov_y_deg = cam->fov_y_deg,
                  .aspect = (float)ctx->width / (float)ctx->height,
                  .near_dist = ctx->near_m,
                  .far_dist = far_dist(vc)};
    memcpy(v.apex, cam->position, sizeof v.apex);
    memcpy(v.forward, vc->forward, sizeof v.forward);
    memcpy(v.up, vc->up, sizeof v.up);
    return v;
}

/* The front patches seen from the apex (pvs/patches.h), triangle labels first in TV_PVS_BIND_PATCH; proxies none. */
static void write_patches(pvs_context* ctx, const float apex[3])
{
    uint32_t* lab = ctx->buffers[TV_PVS_BIND_PATCH].mapped;
    uint32_t n = ctx->triangle_count, drawn = (uint32_t)(ctx->buffers[TV_PVS_BIND_PATCH].size / 16);
    if (!ctx->adjacency || !pvs_front_patches(lab, ctx->adjacency, ctx->tri_corners, ctx->masked, n, apex))
        n = 0;
    for (uint32_t t = n; t < 4 * drawn; t++)
        lab[t] = TV_PVS_PATCH_NONE;
}

static void write_view(pvs_context* ctx, const pvs_viewcell* vc, const rnd_camera* cam, const pvs_view* v)
{
    write_patches(ctx, v->apex);
    pvs_view_frame fr = pvs_view_frame_make(v);
    pvs_view_gpu g = {.tan_half_x = fr.tan_half_x,
                      .tan_half_y = fr.tan_half_y,
                      .tan_alpha = tanf(glm_rad(vc->fov_pvs_deg) * 0.5f),
                      .far_dist = v->far_dist,
                      .near_dist = v->near_dist,
                      .delta = vc->delta,
                      .focal_px = 0.5f * (float)ctx->height / fr.tan_half_y,
                      /* from any edge point in the image, this reaches across it */
                      .max_width = 4.0f * (fr.tan_half_x + fr.tan_half_y),
                      .width = ctx->width,
                      .height = ctx->height,
                      .k = ctx->k_store,
                      .triangle_count = ctx->triangle_count,
                      .explain = ctx->explain,
                      .list_capacity = ctx->list_capacity,
                      .k_exact = ctx->k,
                      .k_lists = ctx->k_lists,
                      .k_regions = ctx->k_regions};
    rnd_camera_view_proj(cam, v->aspect, g.view_proj);
    for (int i = 0; i < 3; i++) {
        g.apex[i] = v->apex[i];
        g.forward[i] = fr.forward[i];
        g.right[i] = fr.right[i];
        g.up[i] = fr.up[i];
    }
    memcpy(ctx->buffers[TV_PVS_BIND_VIEW].mapped, &g, sizeof g);
    memcpy((char*)ctx->buffers[TV_PVS_BIND_VIEW].mapped + sizeof g, ctx->depth_bound.cells,
           sizeof(float) * ctx->depth_bound.cell_count);
}

/* All writes of the commands so far made visible to `dst_stage` / `dst_access`. */
static void memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access)
{
    VkMemoryBarrier2 mb = {.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                           .srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                           .srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT,
                           .dstStageMask = dst_stage,
                           .dstAccessMask = dst_access};
    VkDependencyInfo dep = {.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO, .memoryBarrierCount = 1,
                            .pMemoryBarriers = &mb};
    vkCmdPipelineBarrier2(cmd, &dep);
}

/* Each phase consumes everything the previous one wrote (buffers, the
 * indirect commands, attachments), so one full memory barrier suffices; the
 * passes are far coarser than its cost. */
static void barrier(VkCommandBuffer cmd)
{
    memory_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                   VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
}

void pvs_host_barrier(VkCommandBuffer cmd)
{
    memory_barrier(cmd, VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

void pvs_record_resolve(pvs_context* ctx, VkCommandBuffer cmd)
{
    VkBuffer counters = ctx->buffers[TV_PVS_BIND_COUNTERS].buffer;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, ctx->pipelines[PVS_PIPE_RESOLVE]);
    vkCmdDispatchIndirect(cmd, counters, TV_PVS_C_DISPATCH * sizeof(uint32_t));
    barrier(cmd);
    if (ctx->coop_sort_min == PVS_NEVER_COOP)
        return;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, ctx->pipelines[PVS_PIPE_RESOLVE_GROUP]);
    vkCmdDispatchIndirect(cmd, counters, TV_PVS_C_DISPATCH_COOP * sizeof(uint32_t)); /* empty unless pixels were deferred */
    barrier(cmd);
}

/* Per-layer slots of the counters buffer (empty draws, an empty dispatch),
 * the per-pixel k-buffer counters and list heads, the page pool and P1's
 * workgroup counts. */
static void reset_layer_counters(pvs_context* ctx, VkCommandBuffer cmd)
{
    vkCmdFillBuffer(cmd, ctx->buffers[TV_PVS_BIND_PIXCOUNT].buffer, 0, VK_WHOLE_SIZE, 0);
    for (uint32_t b = TV_PVS_BIND_KHEADS; ctx->kb_paged && b <= TV_PVS_BIND_KLINKS; b++)
        vkCmdFillBuffer(cmd, ctx->buffers[b].buffer, 0, VK_WHOLE_SIZE, TV_PVS_NO_PAGE);
    if (ctx->kb_paged)
        vkCmdFillBuffer(cmd, ctx->buffers[TV_PVS_BIND_KALLOC].buffer, TV_PVS_A_TAKEN * 4, 4, 0);
    vkCmdFillBuffer(cmd, ctx->buffers[TV_PVS_BIND_LOST].buffer, 0, VK_WHOLE_SIZE, 0x7F800000u); /* +inf */
    vkCmdFillBuffer(cmd, ctx->buffers[TV_PVS_BIND_SPILL].buffer, 0, sizeof(uint32_t), 0); /* the list's length */
    vkCmdFillBuffer(cmd, ctx->buffers[TV_PVS_BIND_ORDER].buffer, TV_PVS_ORDER_GROUP(ctx->list_capacity, 0) * 4,
                    VK_WHOLE_SIZE, 0); /* P1's workgroup counts */
    uint32_t c[TV_PVS_C_PER_LAYER] = {0};
    for (uint32_t d = TV_PVS_C_DRAW_FF; d <= TV_PVS_C_DRAW_TRIM; d += 4)
        c[d + 1] = 1; /* instanceCount */
    c[TV_PVS_C_DRAW_SPILL + 1] = c[TV_PVS_C_DRAW_SPILL_WIDE + 1] = 1;
    c[TV_PVS_C_DISPATCH + 1] = c[TV_PVS_C_DISPATCH + 2] = 1;
    c[TV_PVS_C_DISPATCH_COOP + 1] = c[TV_PVS_C_DISPATCH_COOP + 2] = 1;
    vkCmdUpdateBuffer(cmd, ctx->buffers[TV_PVS_BIND_COUNTERS].buffer, 0, sizeof c, c);
}

static void draw_indirect(pvs_context* ctx, VkCommandBuffer cmd, int pipe, uint32_t kind, uint32_t slot)
{
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, ctx->pipelines[pipe]);
    vkCmdPushConstants(cmd, ctx->layout,
                       VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT,
                       offsetof(pvs_push, kind), sizeof(uint32_t), &kind);
    vkCmdDrawIndirect(cmd, ctx->buffers[TV_PVS_BIND_COUNTERS].buffer, slot * sizeof(uint32_t), 1,
                      sizeof(VkDrawIndirectCommand));
}

typedef enum pass_kind { PASS_CLEAR, PASS_FRONTS, PASS_LAYER, PASS_SPILL } pass_kind;

/* One dynamic-rendering pass on visibility buffer `vis` (0 exact, 1 wide)
 * over tile `t`: clear only, P2's draws of the current layer (the wide pass
 * draws the faces only, dilated, for the visibility buffer; the exact pass's
 * fronts are PASS_FRONTS, before the rest: TV_PVS_PRIOR_CULLED_BEHIND), or the spill
 * draw after P3 (exact; it changes neither attachment: every fragment ties in
 * depth). The viewport is the whole image's and the tile a scissor, so every
 * pixel rasterises exactly as without tiling (an offset viewport would round
 * window coordinates differently and move edges by a subpixel step). */
static void render_pass(pvs_context* ctx, VkCommandBuffer cmd, const pvs_tile* t, int vis, pass_kind what)
{
    bool clear = what == PASS_CLEAR;
    VkRenderingAttachmentInfo color = {.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                       .imageView = ctx->vis_ids[vis].view,
                                       .imageLayout = VK_IMAGE_LAYOUT_GENERAL,
                                       .loadOp = clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD,
                                       .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                       .clearValue.color.uint32 = {TV_NO_TRIANGLE, 0, 0, 0}};
    VkRenderingAttachmentInfo depth = {.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                       .imageView = ctx->vis_depth[vis].view,
                                       .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                                       .loadOp = clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD,
                                       .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                       .clearValue.depthStencil = {1.0f, 0}};
    VkRect2D area = {{(int32_t)t->x, (int32_t)t->y}, {t->width, t->height}};
    VkRenderingInfo info = {.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                            .renderArea = area,
                            .layerCount = 1,
                            .colorAttachmentCount = 1,
                            .pColorAttachments = &color,
                            .pDepthAttachment = &depth};
    vkCmdBeginRendering(cmd, &info);
    if (!clear) {
        vkCmdSetViewport(cmd, 0, 1, &(VkViewport){0.0f, 0.0f, (float)ctx->width, (float)ctx->height, 0.0f, 1.0f});
        vkCmdSetScissor(cmd, 0, 1, &area);
    }
    if (what == PASS_SPILL)
        draw_indirect(ctx, cmd, PVS_PIPE_FF, TV_PVS_KIND_FRONT | TV_PVS_KIND_SPILL | (vis ? TV_PVS_KIND_WIDE : 0u),
                      vis ? TV_PVS_C_DRAW_SPILL_WIDE : TV_PVS_C_DRAW_SPILL);
    const uint32_t wide = vis ? TV_PVS_KIND_WIDE : 0u;
    if (what == PASS_FRONTS || (what == PASS_LAYER && vis))
        draw_indirect(ctx, cmd, PVS_PIPE_FF, TV_PVS_KIND_FRONT | wide, TV_PVS_C_DRAW_FF);
    if (what == PASS_LAYER) {
        draw_indirect(ctx, cmd, PVS_PIPE_BF, TV_PVS_KIND_BACK | wide, TV_PVS_C_DRAW_BF);
        if (!vis) {
            draw_indirect(ctx, cmd, PVS_PIPE_QUAD, TV_PVS_KIND_TRIM, TV_PVS_C_DRAW_TRIM);
        }
    }
    vkCmdEndRendering(cmd);
}

/* Before each tile: the per-pixel state, the attachments, the view's tile
 * fields and the region numbering (so that region ids, which break sort ties
 * in P3, are those of an untiled computation); before the first, also what
 * accumulates over tiles (triangle flags, statistics). */
static void reset_tile(pvs_context* ctx, VkCommandBuffer cmd, const pvs_tile* t, bool first)
{
    /* the spill list's layer stamps too: each tile runs every layer again */
    const uint32_t per_tile[] = {TV_PVS_BIND_PIXCOUNT, TV_PVS_BIND_PIXSTATE, TV_PVS_BIND_ACTIVE, TV_PVS_BIND_SPILL};
    const uint32_t per_computation[] = {TV_PVS_BIND_COUNTERS, TV_PVS_BIND_TRI_FLAGS, TV_PVS_BIND_LAYER_STATS,
                                        TV_PVS_BIND_KALLOC};
    barrier(cmd); /* the previous tile's P4 is done with everything rewritten here */
    for (size_t i = 0; i < sizeof per_tile / sizeof per_tile[0]; i++)
        vkCmdFillBuffer(cmd, ctx->buffers[per_tile[i]].buffer, 0, VK_WHOLE_SIZE, 0);
    for (size_t i = 0; first && i < sizeof per_computation / sizeof per_computation[0]; i++)
        vkCmdFillBuffer(cmd, ctx->buffers[per_computation[i]].buffer, 0, VK_WHOLE_SIZE, 0);
    vkCmdFillBuffer(cmd, ctx->buffers[TV_PVS_BIND_COUNTERS].buffer, TV_PVS_C_REGIONS * sizeof(uint32_t),
                    sizeof(uint32_t), 0);
    const uint32_t tile[4] = {t->x, t->y, t->width, t->height};
    vkCmdUpdateBuffer(cmd, ctx->buffers[TV_PVS_BIND_VIEW].buffer, offsetof(pvs_view_gpu, tile_x), sizeof tile, tile);
    vkCmdFillBuffer(cmd, ctx->buffers[TV_PVS_BIND_CENTRE_DEPTH].buffer, 0, VK_WHOLE_SIZE, 0x7F800000u); /* +inf */
    for (int v = 0; v < 2; v++) {
        rnd_image_barrier(cmd, ctx->vis_ids[v].image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                          VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0,
                          VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        rnd_image_barrier(
            cmd, ctx->vis_depth[v].image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
            VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0,
            VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
        render_pass(ctx, cmd, t, v, PASS_CLEAR);
    }
    barrier(cmd);
}

/* P1's draw counts of layer `l` into its P1 statistics (pvs_layout.glsl). */
static void copy_draw_counts(pvs_context* ctx, VkCommandBuffer cmd, uint32_t l)
{
    const VkDeviceSize dst = (VkDeviceSize)(TV_PVS_LAYER_STATS_STRIDE * l + 1) * 16;
    const VkBufferCopy regions[3] = {{TV_PVS_C_DRAW_FF * 4, dst, 4},
                                     {TV_PVS_C_DRAW_BF * 4, dst + 4, 4},
                                     {TV_PVS_C_DRAW_TRIM * 4, dst + 8, 4}};
    vkCmdCopyBuffer(cmd, ctx->buffers[TV_PVS_BIND_COUNTERS].buffer, ctx->buffers[TV_PVS_BIND_LAYER_STATS].buffer, 3,
                    regions);
}

/* P1 of a layer of `count` triangles: classify (its last invocation scans
 * the counts), then list in layer order (pvs_order.comp), so that nothing
 * P1 outputs depends on the order its invocations ran in. */
static void record_classify(pvs_context* ctx, VkCommandBuffer cmd, uint32_t count)
{
    const int pipes[2] = {PVS_PIPE_CLASSIFY, PVS_PIPE_ORDER};
    for (int i = 0; i < 2; i++) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, ctx->pipelines[pipes[i]]);
        vkCmdDispatch(cmd, (count + TV_WG_SIZE - 1) / TV_WG_SIZE, 1, 1);
        barrier(cmd);
    }
}

/* P1-P3 of every layer and P4, for tile `t`. */
static void record_tile(pvs_context* ctx, VkCommandBuffer cmd, const pvs_tile* t, bool first, uint32_t* ts)
{
    const pvs_layers* L = &ctx->layers;
    reset_tile(ctx, cmd, t, first);
    const VkShaderStageFlags stages =
        VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT;
    for (uint32_t l = 0; l < L->layer_count; l++) {
        pvs_push push = {.layer_offset = L->tri_offsets[l],
                         .layer_count = L->tri_offsets[l + 1] - L->tri_offsets[l],
                         .layer = l};
        vkCmdPushConstants(cmd, ctx->layout, stages, 0, sizeof push, &push);
        reset_layer_counters(ctx, cmd);
        barrier(cmd);
        record_classify(ctx, cmd, push.layer_count);
        if (first) /* every tile classifies the same triangles */
            copy_draw_counts(ctx, cmd, l);
        pvs_timestamp(ctx, cmd, ts);
        render_pass(ctx, cmd, t, 0, PASS_FRONTS);
        barrier(cmd); /* the culled backs read the layer's nearest front (TV_PVS_PRIOR_CULLED_BEHIND) */
        render_pass(ctx, cmd, t, 0, PASS_LAYER);
        barrier(cmd); /* the dilated pass reads the exact pass's centre depths */
        render_pass(ctx, cmd, t, 1, PASS_LAYER);
        barrier(cmd);
        pvs_record_pages_taken(ctx, cmd, t, l);
        pvs_timestamp(ctx, cmd, ts);
        pvs_record_resolve(ctx, cmd);
        render_pass(ctx, cmd, t, 0, PASS_SPILL); /* both empty unless P3 asked for them */
        render_pass(ctx, cmd, t, 1, PASS_SPILL);
        barrier(cmd);
        pvs_timestamp(ctx, cmd, ts);
    }
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, ctx->pipelines[PVS_PIPE_GATHER]);
    vkCmdDispatch(cmd, (t->width + 7) / 8, (t->height + 7) / 8, 1);
    pvs_timestamp(ctx, cmd, ts);
}

static void record(pvs_context* ctx, VkCommandBuffer cmd)
{
    uint32_t ts = 0;
    if (ctx->timestamps)
        vkCmdResetQueryPool(cmd, ctx->timestamps, 0, pvs_timestamp_count(ctx));
    pvs_timestamp(ctx, cmd, &ts);
    VkDescriptorSet sets[2];
    sets[TV_SET_SCENE] = ctx->gpu->set;
    sets[TV_PVS_SET] = ctx->set;
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, ctx->layout, 0, 2, sets, 0, NULL);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, ctx->layout, 0, 2, sets, 0, NULL);
    for (uint32_t i = 0; i < pvs_tile_count(&ctx->grid); i++) {
        pvs_tile t = pvs_tile_get(&ctx->grid, i);
        record_tile(ctx, cmd, &t, i == 0, &ts);
    }
    pvs_host_barrier(cmd);
}

/* A proxy is output when it is always or one of its faces was flagged:
 * its ids are flagged here, so that compact() sorts and dedups them. */
static uint32_t flag_proxies(pvs_context* ctx, const pvs_proxy* proxies, uint32_t count)
{
    uint32_t* flags = ctx->buffers[TV_PVS_BIND_TRI_FLAGS].mapped;
    uint32_t output = 0;
    for (uint32_t p = 0; p < count; p++) {
        bool seen = ctx->proxy_always[p];
        for (uint32_t f = 0; f < 12 && !seen; f++)
            seen = flags[ctx->triangle_count + 12 * p + f] != 0;
        for (uint32_t i = 0; seen && i < proxies[p].id_count; i++)
            flags[proxies[p].first_id + i] = 1;
        output += seen;
    }
    return output;
}

static bool compact(pvs_context* ctx, pvs_result* out, char* err, size_t err_size)
{
    const uint32_t* flags = ctx->buffers[TV_PVS_BIND_TRI_FLAGS].mapped;
    uint32_t count = 0;
    for (uint32_t t = 0; t < ctx->triangle_count; t++)
        count += flags[t] != 0;
    uint32_t* ids = realloc(ctx->result, sizeof(uint32_t) * (count ? count : 1));
    if (!ids) {
        snprintf(err, err_size, "pvs_compute: out of memory for %u ids", count);
        return false;
    }
    ctx->result = ids;
    uint32_t* reasons = ctx->explain ? realloc(ctx->reasons, sizeof(uint32_t) * (count ? count : 1)) : NULL;
    if (ctx->explain && !reasons) {
        snprintf(err, err_size, "pvs_compute: out of memory for %u reasons", count);
        return false;
    }
    ctx->reasons = ctx->explain ? reasons : NULL;
    uint32_t n = 0;
    for (uint32_t t = 0; t < ctx->triangle_count; t++) {
        if (flags[t]) {
            if (reasons)
                reasons[n] = flags[t];
            ids[n++] = t;
        }
    }
    out->ids = ids;
    out->reasons = reasons;
    out->count = count;
    return true;
}

/* P1-P4 in one submission, again after the k-buffer pool grew
 * (pvs_pool_regrow). */
static bool run_gpu(pvs_context* ctx, pvs_stats* st, char* err, size_t err_size)
{
    for (bool again = true; again; st->kbuffer_regrows += again) {
        if (!rnd_stream_begin(ctx->rnd, &ctx->stream, err, err_size))
            return false;
        record(ctx, ctx->stream.cmd);
        if (!rnd_stream_submit_wait(ctx->rnd, &ctx->stream, err, err_size) ||
            !pvs_pool_regrow(ctx, &again, err, err_size))
            return false;
    }
    return true;
}

/* Totals and per-layer figures; per-layer ms were read with the timestamps. */
static void collect_stats(pvs_context* ctx, pvs_stats* st)
{
    const uint32_t* c = ctx->buffers[TV_PVS_BIND_COUNTERS].mapped;
    const uint32_t* ls = ctx->buffers[TV_PVS_BIND_LAYER_STATS].mapped;
    const pvs_layers* L = &ctx->layers;
    st->layers = L->layer_count;
    st->layer_triangles = L->tri_count;
    st->silhouettes = c[TV_PVS_C_REGIONS]; /* numbered afresh per tile, so one tile's */
    st->overflow_fronts = c[TV_PVS_C_OVERFLOW_FRONTS];
    st->coop_pixels = c[TV_PVS_C_COOP_TOTAL];
    st->loop_budget_pixels = c[TV_PVS_C_LOOP_BUDGET];
    st->idle_resolves = c[TV_PVS_C_IDLE];
    if (st->loop_budget_pixels)
        tv_log(TV_LOG_WARN, "pvs: %llu pixel resolves of P3 ran out of llvmpipe's loop budget: the PVS may miss "
               "triangles (docs/journal/2026-12-03-k64.md)", (unsigned long long)st->loop_budget_pixels);
    st->tiles = pvs_tile_count(&ctx->grid);
    st->per_layer = ctx->per_layer;
    uint64_t seq = 0;
    for (uint32_t l = 0; l < L->layer_count; l++) {
        const uint32_t* s = ls + 4 * TV_PVS_LAYER_STATS_STRIDE * l; /* P3's, then P1's draw counts */
        pvs_layer_stats* pl = &ctx->per_layer[l];
        pl->triangles = L->tri_offsets[l + 1] - L->tri_offsets[l];
        pl->fronts = s[4] / 3;
        pl->backs = s[5] / 3;
        pl->silhouettes = s[6] / 6;
        pl->active_pixels = s[1];
        pl->sequence_entries = s[2];
        pl->overflow_pixels = s[3];
        st->active_pixels += s[1];
        seq += s[2];
        st->overflow_pixels += s[3];
    }
    st->mean_sequence = st->active_pixels ? (double)seq / (double)st->active_pixels : 0.0;
    pvs_kbuffer_stats(ctx, st);
}

static bool check_proxies(const pvs_context* ctx, const pvs_proxy* proxies, uint32_t count, char* err,
                          size_t err_size)
{
    if (count > ctx->max_proxies) {
        snprintf(err, err_size, "pvs_compute: %u proxies, over pvs_desc.max_proxies %u", count, ctx->max_proxies);
        return false;
    }
    for (uint32_t p = 0; p < count; p++) {
        const pvs_proxy* x = &proxies[p];
        for (int i = 0; i < 3; i++) {
            if (!isfinite(x->box_min[i]) || !isfinite(x->box_max[i]) || x->box_min[i] > x->box_max[i]) {
                snprintf(err, err_size, "pvs_compute: proxy %u: box axis %d [%g, %g] is not a finite range", p, i,
                         x->box_min[i], x->box_max[i]);
                return false;
            }
        }
        if ((uint64_t)x->first_id + x->id_count > ctx->triangle_count) {
            snprintf(err, err_size, "pvs_compute: proxy %u: ids %u + %u leave the scene's %u triangles", p,
                     x->first_id, x->id_count, ctx->triangle_count);
            return false;
        }
    }
    return true;
}

/* The proxies' boxes into their GPU buffer, then sorted into the octree's
 * leaves; returns the tree to build the layers from (NULL: out of memory).
 * Whatever meets the sphere around v0 holding the viewcell and the part of
 * the PVS frustum before its near plane is output outright. */
static const pvs_octree* sort_proxies(pvs_context* ctx, const pvs_viewcell* vc, const pvs_view* view,
                                      const pvs_proxy* proxies, uint32_t count)
{
    float* boxes = ctx->buffers[TV_PVS_BIND_PROXIES].mapped;
    for (uint32_t p = 0; p < count; p++) {
        float* b = boxes + PVS_PROXY_FLOATS * p;
        memcpy(b, proxies[p].box_min, 3 * sizeof(float));
        memcpy(b + 4, proxies[p].box_max, 3 * sizeof(float));
        b[3] = b[7] = 0.0f;
    }
    pvs_view_frame fr = pvs_view_frame_make(view);
    float z = apex_offset(vc);
    float radius = (z > vc->delta ? z : vc->delta) +
                   ctx->near_m * sqrtf(1.0f + fr.tan_half_x * fr.tan_half_x + fr.tan_half_y * fr.tan_half_y);
    return pvs_proxies_sort(&ctx->proxy_sort, &ctx->octree, boxes, count, ctx->triangle_count, vc->v0, radius,
                            ctx->proxy_always);
}

bool pvs_compute(pvs_context* ctx, const pvs_viewcell* vc, pvs_result* out, char* err, size_t err_size)
{
    return pvs_compute_dynamic(ctx, vc, NULL, 0, out, err, err_size);
}

bool pvs_compute_dynamic(pvs_context* ctx, const pvs_viewcell* vc, const pvs_proxy* proxies, uint32_t proxy_count,
                         pvs_result* out, char* err, size_t err_size)
{
    assert(ctx && vc && out && (proxies || proxy_count == 0));
    const double start = tv_now_ms();
    const char* invalid = pvs_viewcell_invalid(vc);
    if (invalid) {
        snprintf(err, err_size, "pvs_compute: invalid viewcell: %s", invalid);
        return false;
    }
    if (!check_apex_offset(ctx, vc, err, err_size) || !check_proxies(ctx, proxies, proxy_count, err, err_size))
        return false;
    *out = (pvs_result){0};
    pvs_stats* st = &out->stats;
    rnd_camera cam = pvs_apex_camera(ctx, vc);
    pvs_view view = layer_view(ctx, vc, &cam);
    const pvs_octree* tree = sort_proxies(ctx, vc, &view, proxies, proxy_count);
    if (!tree) {
        snprintf(err, err_size, "pvs_compute: out of memory sorting %u proxies", proxy_count);
        return false;
    }
    if (!pvs_layers_build(tree, &view, ctx->max_layers, &ctx->layers, err, err_size))
        return false;
    const pvs_layers* L = &ctx->layers;
    uint32_t widest = 0;
    for (uint32_t l = 0; l < L->layer_count; l++) {
        uint32_t n = L->tri_offsets[l + 1] - L->tri_offsets[l];
        widest = n > widest ? n : widest;
    }
    if (!pvs_reserve(ctx, widest, L->layer_count, err, err_size) ||
        !pvs_reserve_timestamps(ctx, pvs_timestamp_count(ctx), err, err_size))
        return false;
    memset(ctx->per_layer, 0, sizeof *ctx->per_layer * L->layer_count);
    memcpy(ctx->buffers[TV_PVS_BIND_LAYER_TRIS].mapped, L->tri_ids, sizeof(uint32_t) * L->tri_count);
    pvs_depth_bound_begin(&ctx->depth_bound, &view);
    pvs_depth_bound_add_ids(&ctx->depth_bound, L->tri_ids, L->tri_count, ctx->tri_corners, ctx->triangle_count,
                            ctx->buffers[TV_PVS_BIND_PROXIES].mapped);
    pvs_depth_bound_finish(&ctx->depth_bound);
    write_view(ctx, vc, &cam, &view);
    st->ms[0] = tv_now_ms() - start;

    const double gpu_start = tv_now_ms();
    if (!run_gpu(ctx, st, err, err_size))
        return false;
    if (ctx->timestamps)
        pvs_read_timestamps(ctx, st);
    else
        st->ms[2] = tv_now_ms() - gpu_start;

    const double p4 = tv_now_ms();
    st->proxies = proxy_count;
    st->proxies_always = ctx->proxy_sort.always_count;
    st->proxies_output = flag_proxies(ctx, proxies, proxy_count);
    if (!compact(ctx, out, err, err_size))
        return false;
    collect_stats(ctx, st);
    st->ms[4] += tv_now_ms() - p4;
    st->total_ms = tv_now_ms() - start;
    return true;
}
