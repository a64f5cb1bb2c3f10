/* gpu_pipelines.c - descriptor set layout, pipeline layout and the pipelines
 * of the PVS passes: five compute (P1 classify and order, P3
 * resolve per thread and per workgroup, P4 gather) and
 * four raster pipelines of P2 sharing one dynamic-rendering format (the
 * visibility buffer's id + depth attachments). */
#include "gpu_internal.h"

#include "log.h"

#include <stdatomic.h>

#include "pvs_classify_comp.spv.h"
#include "pvs_face_frag.spv.h"
#include "pvs_face_noi64_frag.spv.h"
#include "pvs_face_vert.spv.h"
#include "pvs_gather_comp.spv.h"
#include "pvs_order_comp.spv.h"
#include "pvs_quad_frag.spv.h"
#include "pvs_quad_vert.spv.h"
#include "pvs_resolve_comp.spv.h"
#include "pvs_resolve_group_comp.spv.h"

static const VkShaderStageFlags all_stages =
    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT;

static bool create_layouts(pvs_context* ctx, char* err, size_t err_size)
{
    VkDescriptorSetLayoutBinding b[TV_PVS_BINDINGS];
    for (uint32_t i = 0; i < TV_PVS_BINDINGS; i++) {
        VkDescriptorType type = i == TV_PVS_BIND_VIS_IDS || i == TV_PVS_BIND_VIS_WIDE
                                    ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE
                                    : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        b[i] = (VkDescriptorSetLayoutBinding){i, type, 1, all_stages, NULL};
    }
    VkDescriptorSetLayoutCreateInfo info = {.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
                                            .bindingCount = TV_PVS_BINDINGS,
                                            .pBindings = b};
    VkDevice dev = ctx->rnd->device;
    if (!RND_VK_OK(vkCreateDescriptorSetLayout(dev, &info, NULL, &ctx->set_layout), err, err_size))
        return false;
    VkDescriptorSetLayout sets[2];
    sets[TV_SET_SCENE] = ctx->rnd->scene_set_layout;
    sets[TV_PVS_SET] = ctx->set_layout;
    VkPipelineLayoutCreateInfo layout = {
        .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
        .setLayoutCount = 2,
        .pSetLayouts = sets,
        .pushConstantRangeCount = 1,
        .pPushConstantRanges = &(VkPushConstantRange){all_stages, 0, sizeof(pvs_push)},
    };
    return RND_VK_OK(vkCreatePipelineLayout(dev, &layout, NULL, &ctx->layout), err, err_size);
}

static bool create_compute(pvs_context* ctx, const uint32_t* code, size_t size,
                           const VkSpecializationInfo* spec, VkPipeline* out, char* err, size_t err_size)
{
    VkShaderModule module = rnd_shader_module(ctx->rnd, code, size, err, err_size);
    if (!module)
        return false;
    VkComputePipelineCreateInfo info = {.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
                                        .stage = {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                                                  .stage = VK_SHADER_STAGE_COMPUTE_BIT,
                                                  .module = module,
                                                  .pName = "main",
                                                  .pSpecializationInfo = spec},
                                        .layout = ctx->layout};
    bool ok = RND_VK_OK(vkCreateComputePipelines(ctx->rnd->device, VK_NULL_HANDLE, 1, &info, NULL, out), err,
                        err_size);
    vkDestroyShaderModule(ctx->rnd->device, module, NULL);
    return ok;
}

/* vis: the scene-triangle pipelines depth-test and write the visibility
 * buffer; the quad pipeline only feeds k-buffers from the fragment shader
 * (no depth test: every fragment must reach its list). Back faces take part
 * in the visibility buffer because the renderer does not cull them: the
 * back of a single-sided quad is what an eye sees there. */
static bool create_raster(pvs_context* ctx, VkShaderModule vert, VkShaderModule frag, bool vis, VkPipeline* out,
                          char* err, size_t err_size)
{
    const VkFormat color_format = PVS_VIS_ID_FORMAT;
    const VkSpecializationMapEntry entry = {TV_PVS_SPEC_KB_PAGED, 0, sizeof(uint32_t)};
    rnd_raster_desc d = {.vert = vert,
                         .frag = frag,
                         .frag_spec = &(VkSpecializationInfo){1, &entry, sizeof(uint32_t), &ctx->kb_paged},
                         .layout = ctx->layout,
                         .color_count = 1,
                         .color_formats = &color_format,
                         .color_write = vis ? VK_COLOR_COMPONENT_R_BIT : 0,
                         .depth_format = PVS_VIS_DEPTH_FORMAT,
                         .depth_test = vis};
    return rnd_raster_pipeline_create(ctx->rnd, &d, out, err, err_size);
}

static bool create_rasters(pvs_context* ctx, char* err, size_t err_size)
{
    rnd_context* r = ctx->rnd;
    /* A module declaring Int64Atomics is invalid on a device without the feature (render/device.c), so P2 takes
     * the variant built without it there: front-patch rule off, a PVS never smaller (docs/pvs-gpu-passes.md). */
    static atomic_flag logged = ATOMIC_FLAG_INIT;
    if (!atomic_flag_test_and_set(&logged))
        tv_log(TV_LOG_INFO, "pvs: %s", r->int64_atomics ? "P2 with 64-bit atomics (front-patch rule on)"
                                                        : "P2 without 64-bit atomics (front-patch rule off)");
    VkShaderModule m[4] = {
        rnd_shader_module(r, tv_spv_pvs_face_vert, sizeof tv_spv_pvs_face_vert, err, err_size),
        r->int64_atomics ? rnd_shader_module(r, tv_spv_pvs_face_frag, sizeof tv_spv_pvs_face_frag, err, err_size)
                         : rnd_shader_module(r, tv_spv_pvs_face_noi64_frag, sizeof tv_spv_pvs_face_noi64_frag, err,
                                             err_size),
        rnd_shader_module(r, tv_spv_pvs_quad_vert, sizeof tv_spv_pvs_quad_vert, err, err_size),
        rnd_shader_module(r, tv_spv_pvs_quad_frag, sizeof tv_spv_pvs_quad_frag, err, err_size),
    };
    bool ok = m[0] && m[1] && m[2] && m[3] &&
              create_raster(ctx, m[0], m[1], true, &ctx->pipelines[PVS_PIPE_FF], err, err_size) &&
              create_raster(ctx, m[0], m[1], true, &ctx->pipelines[PVS_PIPE_BF], err, err_size) &&
              create_raster(ctx, m[2], m[3], false, &ctx->pipelines[PVS_PIPE_QUAD], err, err_size);
    for (int i = 0; i < 4; i++) {
        if (m[i])
            vkDestroyShaderModule(r->device, m[i], NULL);
    }
    return ok;
}

bool pvs_pipelines_create(pvs_context* ctx, char* err, size_t err_size)
{
    /* constant 0: the pass's own; TV_PVS_SPEC_KB_PAGED: the k-buffer layout */
    const VkSpecializationMapEntry entries[2] = {{0, 0, sizeof(uint32_t)},
                                                 {TV_PVS_SPEC_KB_PAGED, sizeof(uint32_t), sizeof(uint32_t)}};
    const uint32_t min_data[2] = {ctx->coop_sort_min, ctx->kb_paged};
    const uint32_t width_data[2] = {ctx->coop_width, ctx->kb_paged};
    const VkSpecializationInfo coop_min = {2, entries, sizeof min_data, min_data};
    const VkSpecializationInfo coop_width = {2, entries, sizeof width_data, width_data};
    return create_layouts(ctx, err, err_size) &&
           create_compute(ctx, tv_spv_pvs_classify_comp, sizeof tv_spv_pvs_classify_comp, NULL,
                          &ctx->pipelines[PVS_PIPE_CLASSIFY], err, err_size) &&
           create_compute(ctx, tv_spv_pvs_order_comp, sizeof tv_spv_pvs_order_comp, NULL,
                          &ctx->pipelines[PVS_PIPE_ORDER], err, err_size) &&
           create_compute(ctx, tv_spv_pvs_resolve_comp, sizeof tv_spv_pvs_resolve_comp, &coop_min,
                          &ctx->pipelines[PVS_PIPE_RESOLVE], err, err_size) &&
           create_compute(ctx, tv_spv_pvs_resolve_group_comp, sizeof tv_spv_pvs_resolve_group_comp, &coop_width,
                          &ctx->pipelines[PVS_PIPE_RESOLVE_GROUP], err, err_size) &&
           create_compute(ctx, tv_spv_pvs_gather_comp, sizeof tv_spv_pvs_gather_comp, NULL,
                          &ctx->pipelines[PVS_PIPE_GATHER], err, err_size) &&
           create_rasters(ctx, err, err_size);
}

void pvs_pipelines_destroy(pvs_context* ctx)
{
    VkDevice dev = ctx->rnd->device;
    for (int i = 0; i < PVS_PIPE_COUNT; i++) {
        if (ctx->pipelines[i])
            vkDestroyPipeline(dev, ctx->pipelines[i], NULL);
    }
    if (ctx->layout)
        vkDestroyPipelineLayout(dev, ctx->layout, NULL);
    if (ctx->set_layout)
        vkDestroyDescriptorSetLayout(dev, ctx->set_layout, NULL);
}
