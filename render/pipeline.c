/* pipeline.c - shader modules from the embedded SPIR-V, descriptor set
 * layouts, the raster pipeline set-up shared with the PVS passes, and the
 * mesh pipeline (dynamic rendering, no vertex input). */
#include "render_vk.h"

#include <assert.h>

#include "mesh_shared.h"
#include "mesh_frag.spv.h"
#include "mesh_vert.spv.h"

VkShaderModule rnd_shader_module(rnd_context* ctx, const uint32_t* code, size_t code_size, char* err,
                                 size_t err_size)
{
    VkShaderModuleCreateInfo info = {.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
                                     .codeSize = code_size,
                                     .pCode = code};
    VkShaderModule module = VK_NULL_HANDLE;
    RND_VK_OK(vkCreateShaderModule(ctx->device, &info, NULL, &module), err, err_size);
    return module;
}

bool rnd_descriptor_set_create(rnd_context* ctx, VkDescriptorSetLayout layout, const VkDescriptorPoolSize* sizes,
                               uint32_t size_count, VkDescriptorPool* pool, VkDescriptorSet* set, char* err,
                               size_t err_size)
{
    VkDescriptorPoolCreateInfo pool_info = {.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                            .maxSets = 1,
                                            .poolSizeCount = size_count,
                                            .pPoolSizes = sizes};
    if (!RND_VK_OK(vkCreateDescriptorPool(ctx->device, &pool_info, NULL, pool), err, err_size))
        return false;
    VkDescriptorSetAllocateInfo alloc = {.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                         .descriptorPool = *pool,
                                         .descriptorSetCount = 1,
                                         .pSetLayouts = &layout};
    return RND_VK_OK(vkAllocateDescriptorSets(ctx->device, &alloc, set), err, err_size);
}

static bool create_set_layouts(rnd_context* ctx, char* err, size_t err_size)
{
    /* Compute is included so the PVS passes can bind the same scene set. */
    const VkShaderStageFlags stages =
        VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT;
    const uint32_t buffers[] = {TV_BIND_POSITIONS, TV_BIND_ATTRIBS, TV_BIND_INDICES, TV_BIND_TRI_MAT,
                                TV_BIND_MATERIALS};
    VkDescriptorSetLayoutBinding scene[6];
    for (uint32_t i = 0; i < 5; i++)
        scene[i] = (VkDescriptorSetLayoutBinding){buffers[i], VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, stages, NULL};
    scene[5] = (VkDescriptorSetLayoutBinding){TV_BIND_TEXTURES, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages,
                                              NULL};
    VkDescriptorSetLayoutCreateInfo info = {.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
                                            .bindingCount = 6,
                                            .pBindings = scene};
    if (!RND_VK_OK(vkCreateDescriptorSetLayout(ctx->device, &info, NULL, &ctx->scene_set_layout), err, err_size))
        return false;
    VkDescriptorSetLayoutBinding draw = {TV_BIND_DRAW_IDS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                                         VK_SHADER_STAGE_VERTEX_BIT, NULL};
    info.bindingCount = 1;
    info.pBindings = &draw;
    return RND_VK_OK(vkCreateDescriptorSetLayout(ctx->device, &info, NULL, &ctx->draw_set_layout), err, err_size);
}

static bool create_sampler(rnd_context* ctx, char* err, size_t err_size)
{
    VkSamplerCreateInfo info = {.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
                                .magFilter = VK_FILTER_LINEAR,
                                .minFilter = VK_FILTER_LINEAR,
                                .mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST,
                                .addressModeU = VK_SAMPLER_ADDRESS_MODE_REPEAT,
                                .addressModeV = VK_SAMPLER_ADDRESS_MODE_REPEAT,
                                .addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT,
                                .maxLod = 0.0f};
    return RND_VK_OK(vkCreateSampler(ctx->device, &info, NULL, &ctx->sampler), err, err_size);
}

bool rnd_raster_pipeline_create(rnd_context* ctx, const rnd_raster_desc* desc, VkPipeline* out, char* err,
                                size_t err_size)
{
    assert(desc->color_count <= 2);
    VkPipelineShaderStageCreateInfo stages[2] = {
        {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
         .stage = VK_SHADER_STAGE_VERTEX_BIT,
         .module = desc->vert,
         .pName = "main"},
        {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
         .stage = VK_SHADER_STAGE_FRAGMENT_BIT,
         .module = desc->frag,
         .pName = "main",
         .pSpecializationInfo = desc->frag_spec},
    };
    VkPipelineVertexInputStateCreateInfo vertex_input = {.sType =
                                                             VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    VkPipelineInputAssemblyStateCreateInfo assembly = {.sType =
                                                           VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
                                                       .topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST};
    VkPipelineViewportStateCreateInfo viewport = {.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
                                                  .viewportCount = 1,
                                                  .scissorCount = 1};
    /* No fixed-function culling: one draw mixes single- and double-sided
     * materials, so mesh.frag culls single-sided backs itself. With the
     * projection's Y flip, counter-clockwise world triangles stay
     * counter-clockwise in framebuffer space (gl_FrontFacing). */
    VkPipelineRasterizationStateCreateInfo raster = {.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
                                                     .polygonMode = VK_POLYGON_MODE_FILL,
                                                     .cullMode = VK_CULL_MODE_NONE,
                                                     .frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE,
                                                     .lineWidth = 1.0f};
    VkPipelineMultisampleStateCreateInfo multisample = {.sType =
                                                            VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
                                                        .rasterizationSamples = VK_SAMPLE_COUNT_1_BIT};
    VkPipelineDepthStencilStateCreateInfo depth = {.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO,
                                                   .depthTestEnable = desc->depth_test,
                                                   .depthWriteEnable = desc->depth_test && !desc->depth_read_only,
                                                   .depthCompareOp = VK_COMPARE_OP_LESS};
    /* Without blending the states are identical (no independentBlend
     * needed); a blend applies to attachment 0 only, as the id attachment
     * is an integer format that cannot blend. */
    const VkPipelineColorBlendAttachmentState write = {.colorWriteMask = desc->color_write};
    VkPipelineColorBlendAttachmentState blend[2] = {write, write};
    if (desc->blend != RND_BLEND_NONE) {
        /* ALPHA: colour src over dst, alpha the most opaque layer (MAX
         * ignores the factors); KEEP: dst unchanged */
        const bool over = desc->blend == RND_BLEND_ALPHA;
        blend[0] = (VkPipelineColorBlendAttachmentState){
            .blendEnable = VK_TRUE,
            .srcColorBlendFactor = over ? VK_BLEND_FACTOR_SRC_ALPHA : VK_BLEND_FACTOR_ZERO,
            .dstColorBlendFactor = over ? VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA : VK_BLEND_FACTOR_ONE,
            .colorBlendOp = VK_BLEND_OP_ADD,
            .srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO,
            .dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE,
            .alphaBlendOp = over ? VK_BLEND_OP_MAX : VK_BLEND_OP_ADD,
            .colorWriteMask = desc->color_write};
    }
    VkPipelineColorBlendStateCreateInfo blending = {.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
                                                    .attachmentCount = desc->color_count,
                                                    .pAttachments = blend};
    VkDynamicState dynamic_states[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic = {.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO,
                                                .dynamicStateCount = 2,
                                                .pDynamicStates = dynamic_states};
    VkPipelineRenderingCreateInfo rendering = {.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
                                               .colorAttachmentCount = desc->color_count,
                                               .pColorAttachmentFormats = desc->color_formats,
                                               .depthAttachmentFormat = desc->depth_format};
    VkGraphicsPipelineCreateInfo info = {.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
                                         .pNext = &rendering,
                                         .stageCount = 2,
                                         .pStages = stages,
                                         .pVertexInputState = &vertex_input,
                                         .pInputAssemblyState = &assembly,
                                         .pViewportState = &viewport,
                                         .pRasterizationState = &raster,
                                         .pMultisampleState = &multisample,
                                         .pDepthStencilState = &depth,
                                         .pColorBlendState = &blending,
                                         .pDynamicState = &dynamic,
                                         .layout = desc->layout};
    return RND_VK_OK(vkCreateGraphicsPipelines(ctx->device, VK_NULL_HANDLE, 1, &info, NULL, out), err, err_size);
}

bool rnd_mesh_pipeline_create(rnd_context* ctx, char* err, size_t err_size)
{
    if (!create_set_layouts(ctx, err, err_size) || !create_sampler(ctx, err, err_size))
        return false;
    VkDescriptorSetLayout sets[2];
    sets[TV_SET_SCENE] = ctx->scene_set_layout;
    sets[TV_SET_DRAW] = ctx->draw_set_layout;
    VkPipelineLayoutCreateInfo layout = {
        .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
        .setLayoutCount = 2,
        .pSetLayouts = sets,
        .pushConstantRangeCount = 1,
        .pPushConstantRanges = &(VkPushConstantRange){VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(rnd_mesh_push)},
    };
    if (!RND_VK_OK(vkCreatePipelineLayout(ctx->device, &layout, NULL, &ctx->mesh_layout), err, err_size))
        return false;
    VkShaderModule vert = rnd_shader_module(ctx, tv_spv_mesh_vert, sizeof tv_spv_mesh_vert, err, err_size);
    VkShaderModule frag = rnd_shader_module(ctx, tv_spv_mesh_frag, sizeof tv_spv_mesh_frag, err, err_size);
    /* the id attachment simply has no G, B, A to write */
    VkFormat color_formats[2] = {RND_COLOR_FORMAT, RND_ID_FORMAT};
    rnd_raster_desc mesh = {.vert = vert,
                            .frag = frag,
                            .layout = ctx->mesh_layout,
                            .color_count = 2,
                            .color_formats = color_formats,
                            .color_write = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                           VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT,
                            .depth_format = RND_DEPTH_FORMAT,
                            .depth_test = true};
    /* the three passes of draw.c: opaque, BLEND colour, BLEND depth and ids */
    rnd_raster_desc blend = mesh, blend_depth = mesh;
    blend.blend = RND_BLEND_ALPHA;
    blend.depth_read_only = true;
    blend_depth.blend = RND_BLEND_KEEP;
    bool ok = vert && frag && rnd_raster_pipeline_create(ctx, &mesh, &ctx->mesh_pipeline, err, err_size) &&
              rnd_raster_pipeline_create(ctx, &blend, &ctx->blend_pipeline, err, err_size) &&
              rnd_raster_pipeline_create(ctx, &blend_depth, &ctx->blend_depth_pipeline, err, err_size);
    if (vert)
        vkDestroyShaderModule(ctx->device, vert, NULL);
    if (frag)
        vkDestroyShaderModule(ctx->device, frag, NULL);
    return ok;
}

void rnd_mesh_pipeline_destroy(rnd_context* ctx)
{
    VkPipeline pipelines[3] = {ctx->mesh_pipeline, ctx->blend_pipeline, ctx->blend_depth_pipeline};
    for (uint32_t i = 0; i < 3; i++)
        if (pipelines[i])
            vkDestroyPipeline(ctx->device, pipelines[i], NULL);
    if (ctx->mesh_layout)
        vkDestroyPipelineLayout(ctx->device, ctx->mesh_layout, NULL);
    if (ctx->sampler)
        vkDestroySampler(ctx->device, ctx->sampler, NULL);
    if (ctx->draw_set_layout)
        vkDestroyDescriptorSetLayout(ctx->device, ctx->draw_set_layout, NULL);
    if (ctx->scene_set_layout)
        vkDestroyDescriptorSetLayout(ctx->device, ctx->scene_set_layout, NULL);
}
