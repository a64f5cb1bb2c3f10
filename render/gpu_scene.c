/* gpu_scene.c - uploads an scn_scene into storage buffers and sampled images
 * and writes the scene descriptor set (layout in shaders/mesh_common.glsl). */
#include "render_vk.h"

#include "mesh_shared.h"

#include <assert.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Mirrors tv_material_gpu in shaders/mesh_common.glsl (std430, 32 bytes). */
typedef struct material_gpu {
    float base_color[4];
    uint32_t texture;
    uint32_t flags;
    float alpha_cutoff;
    uint32_t pad;
} material_gpu;
_Static_assert(offsetof(material_gpu, texture) == 16 && offsetof(material_gpu, flags) == 20 &&
                   offsetof(material_gpu, alpha_cutoff) == 24 && sizeof(material_gpu) == 32,
               "material_gpu must match tv_material_gpu's std430 layout in mesh_common.glsl");

#define ATTRIB_STRIDE 5 /* TV_ATTRIB_STRIDE in mesh_common.glsl */

/* One storage buffer of the scene: its destination and its host data. */
typedef struct scene_array {
    rnd_buffer* buffer;
    const void* data;
    VkDeviceSize size;
} scene_array;

/* Attributes of vertices [first, first + count), interleaved. */
static float* interleave_attribs(const scn_scene* s, uint32_t first, uint32_t count)
{
    float* out = malloc((size_t)(count ? count : 1) * ATTRIB_STRIDE * sizeof(float));
    if (!out)
        return NULL;
    for (uint32_t v = first; v < first + count; v++) {
        float* a = out + (size_t)(v - first) * ATTRIB_STRIDE;
        memcpy(a, s->normals + 3 * (size_t)v, 3 * sizeof(float));
        memcpy(a + 3, s->uvs + 2 * (size_t)v, 2 * sizeof(float));
    }
    return out;
}

static material_gpu* convert_materials(const scn_scene* s)
{
    material_gpu* out = calloc(s->material_count, sizeof *out);
    if (!out)
        return NULL;
    for (uint32_t i = 0; i < s->material_count; i++) {
        const scn_material* m = &s->materials[i];
        memcpy(out[i].base_color, m->base_color, sizeof out[i].base_color);
        if (m->texture >= 0) {
            out[i].texture = (uint32_t)m->texture;
            out[i].flags |= TV_MAT_TEXTURED;
        }
        if (m->alpha_mode == SCN_ALPHA_MASK)
            out[i].flags |= TV_MAT_ALPHA_MASK;
        if (m->double_sided)
            out[i].flags |= TV_MAT_DOUBLE_SIDED;
        if (m->alpha_mode == SCN_ALPHA_BLEND)
            out[i].flags |= TV_MAT_ALPHA_BLEND;
        out[i].alpha_cutoff = m->alpha_cutoff;
    }
    return out;
}

static void blend_centroids(const scn_scene* s, rnd_gpu_scene* g)
{
    for (uint32_t i = 0; i < g->blend_count; i++) {
        const uint32_t* tri = s->indices + 3 * (size_t)g->blend_ids[i];
        for (int axis = 0; axis < 3; axis++) {
            float sum = 0.0f;
            for (int c = 0; c < 3; c++)
                sum += s->positions[3 * (size_t)tri[c] + axis];
            g->blend_centroids[3 * i + axis] = sum / 3.0f;
        }
    }
}

/* Lists the BLEND triangles (draw.c sorts them back to front per draw). */
static bool find_blend(const scn_scene* s, rnd_gpu_scene* g)
{
    for (uint32_t t = 0; t < s->triangle_count; t++)
        g->blend_count += s->materials[s->tri_material[t]].alpha_mode == SCN_ALPHA_BLEND;
    if (g->blend_count == 0)
        return true;
    g->blend_ids = malloc(sizeof(uint32_t) * g->blend_count);
    g->blend_centroids = malloc(sizeof(float) * 3 * g->blend_count);
    if (!g->blend_ids || !g->blend_centroids)
        return false;
    uint32_t n = 0;
    for (uint32_t t = 0; t < s->triangle_count; t++)
        if (s->materials[s->tri_material[t]].alpha_mode == SCN_ALPHA_BLEND)
            g->blend_ids[n++] = t;
    blend_centroids(s, g);
    return true;
}

/* Rejects scenes the renderer cannot bind, before anything is allocated. */
static bool check_scene(rnd_context* ctx, const scn_scene* s, char* err, size_t err_size)
{
    if (s->triangle_count == 0 || s->vertex_count == 0 || s->material_count == 0) {
        snprintf(err, err_size, "scene %s: no triangles, vertices or materials to upload", s->name);
        return false;
    }
    if (s->texture_count > TV_MAX_TEXTURES) {
        snprintf(err, err_size, "scene %s: %u textures, the renderer binds at most TV_MAX_TEXTURES = %u", s->name,
                 s->texture_count, TV_MAX_TEXTURES);
        return false;
    }
    for (uint32_t i = 0; i < s->material_count; i++) {
        if (s->materials[i].texture >= (int32_t)s->texture_count) {
            snprintf(err, err_size, "scene %s: material %u uses texture %d of %u", s->name, i,
                     s->materials[i].texture, s->texture_count);
            return false;
        }
    }
    /* The largest array: per-vertex attributes. The shaders index each array
     * as one binding, so a scene must fit the device's storage range. */
    const VkDeviceSize limit = ctx->props.limits.maxStorageBufferRange;
    const VkDeviceSize attrib_bytes = (VkDeviceSize)s->vertex_count * ATTRIB_STRIDE * sizeof(float);
    const VkDeviceSize index_bytes = (VkDeviceSize)s->triangle_count * 3 * sizeof(uint32_t);
    if (attrib_bytes > limit || index_bytes > limit) {
        snprintf(err, err_size,
                 "scene %s: %u vertices / %u triangles need %llu / %llu byte buffers, over this device's "
                 "maxStorageBufferRange (%llu bytes)",
                 s->name, s->vertex_count, s->triangle_count, (unsigned long long)attrib_bytes,
                 (unsigned long long)index_bytes, (unsigned long long)limit);
        return false;
    }
    return true;
}

/* Records every upload into cmd; staging keeps the sources alive. */
static bool record_uploads(rnd_context* ctx, rnd_gpu_scene* g, const scn_scene* s, const scene_array* arrays,
                           uint32_t count, VkCommandBuffer cmd, rnd_staging* staging, char* err, size_t err_size)
{
    const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    for (uint32_t i = 0; i < count; i++) {
        if (!rnd_buffer_create(ctx, arrays[i].size, usage, false, arrays[i].buffer, err, err_size) ||
            !rnd_upload_buffer(ctx, cmd, staging, arrays[i].data, arrays[i].size, arrays[i].buffer->buffer, err,
                               err_size))
            return false;
    }
    if (!rnd_texture_array_create(ctx, cmd, staging, s, &g->textures, err, err_size))
        return false;
    VkMemoryBarrier2 barrier = {.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                                .srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT,
                                .srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                .dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                                .dstAccessMask = VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
    vkCmdPipelineBarrier2(cmd, &(VkDependencyInfo){.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                                   .memoryBarrierCount = 1,
                                                   .pMemoryBarriers = &barrier});
    return true;
}

static bool write_descriptors(rnd_context* ctx, rnd_gpu_scene* g, char* err, size_t err_size)
{
    VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 5},
                                     {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}};
    if (!rnd_descriptor_set_create(ctx, ctx->scene_set_layout, sizes, 2, &g->pool, &g->set, err, err_size))
        return false;
    const rnd_buffer* buffers[5] = {&g->positions, &g->attribs, &g->indices, &g->tri_material, &g->materials};
    const uint32_t bindings[5] = {TV_BIND_POSITIONS, TV_BIND_ATTRIBS, TV_BIND_INDICES, TV_BIND_TRI_MAT,
                                  TV_BIND_MATERIALS};
    VkDescriptorBufferInfo buffer_info[5];
    VkDescriptorImageInfo image_info = {ctx->sampler, g->textures.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet writes[6];
    for (uint32_t i = 0; i < 5; i++) {
        buffer_info[i] = (VkDescriptorBufferInfo){buffers[i]->buffer, 0, VK_WHOLE_SIZE};
        writes[i] = (VkWriteDescriptorSet){.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                                           .dstSet = g->set,
                                           .dstBinding = bindings[i],
                                           .descriptorCount = 1,
                                           .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                           .pBufferInfo = &buffer_info[i]};
    }
    writes[5] = (VkWriteDescriptorSet){.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                                       .dstSet = g->set,
                                       .dstBinding = TV_BIND_TEXTURES,
                                       .descriptorCount = 1,
                                       .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                       .pImageInfo = &image_info};
    vkUpdateDescriptorSets(ctx->device, 6, writes, 0, NULL);
    return true;
}

rnd_gpu_scene* rnd_scene_create(rnd_context* ctx, const scn_scene* s, char* err, size_t err_size)
{
    if (!check_scene(ctx, s, err, err_size))
        return NULL;
    rnd_gpu_scene* g = calloc(1, sizeof *g);
    float* attribs = interleave_attribs(s, 0, s->vertex_count);
    material_gpu* materials = convert_materials(s);
    if (!g || !attribs || !materials || !find_blend(s, g)) {
        snprintf(err, err_size, "scene %s: out of memory preparing the upload", s->name);
        free(attribs);
        free(materials);
        rnd_scene_destroy(ctx, g);
        return NULL;
    }
    g->triangle_count = s->triangle_count;
    /* positions and indices are at most the attribute size (check_scene) */
    const scene_array arrays[5] = {
        {&g->positions, s->positions, (VkDeviceSize)s->vertex_count * 3 * sizeof(float)},
        {&g->attribs, attribs, (VkDeviceSize)s->vertex_count * ATTRIB_STRIDE * sizeof(float)},
        {&g->indices, s->indices, (VkDeviceSize)s->triangle_count * 3 * sizeof(uint32_t)},
        {&g->tri_material, s->tri_material, (VkDeviceSize)s->triangle_count * sizeof(uint32_t)},
        {&g->materials, materials, (VkDeviceSize)s->material_count * sizeof(material_gpu)},
    };
    rnd_stream stream = {0};
    rnd_staging staging = {0};
    bool ok = rnd_stream_create(ctx, &stream, err, err_size) &&
              rnd_stream_begin(ctx, &stream, err, err_size) &&
              record_uploads(ctx, g, s, arrays, 5, stream.cmd, &staging, err, err_size) &&
              rnd_stream_submit_wait(ctx, &stream, err, err_size) && write_descriptors(ctx, g, err, err_size);
    rnd_staging_release(ctx, &staging);
    rnd_stream_destroy(ctx, &stream);
    free(attribs);
    free(materials);
    if (!ok) {
        vkDeviceWaitIdle(ctx->device); /* a failed submit may leave uploads in flight */
        rnd_scene_destroy(ctx, g);
        return NULL;
    }
    return g;
}

bool rnd_scene_update_vertices(rnd_context* ctx, rnd_gpu_scene* g, const scn_scene* s, uint32_t first,
                               uint32_t count, char* err, size_t err_size)
{
    assert(ctx && g && s && (uint64_t)first + count <= s->vertex_count);
    if (count == 0)
        return true;
    float* attribs = interleave_attribs(s, first, count);
    if (!attribs) {
        snprintf(err, err_size, "scene %s: out of memory preparing a vertex update", s->name);
        return false;
    }
    const VkDeviceSize attrib_bytes = ATTRIB_STRIDE * sizeof(float), position_bytes = 3 * sizeof(float);
    rnd_stream stream = {0};
    rnd_staging staging = {0};
    /* earlier draws' reads finish before the copy writes, the copy before later draws read */
    VkMemoryBarrier2 before = {.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                               .srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                               .srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_READ_BIT,
                               .dstStageMask = VK_PIPELINE_STAGE_2_COPY_BIT,
                               .dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT};
    VkMemoryBarrier2 after = {.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                              .srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT,
                              .srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT,
                              .dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                              .dstAccessMask = VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
    bool ok = rnd_stream_create(ctx, &stream, err, err_size) && rnd_stream_begin(ctx, &stream, err, err_size);
    if (ok) {
        vkCmdPipelineBarrier2(stream.cmd, &(VkDependencyInfo){.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                                              .memoryBarrierCount = 1,
                                                              .pMemoryBarriers = &before});
        ok = rnd_upload_buffer_at(ctx, stream.cmd, &staging, s->positions + 3 * (size_t)first, count * position_bytes,
                                  g->positions.buffer, first * position_bytes, err, err_size) &&
             rnd_upload_buffer_at(ctx, stream.cmd, &staging, attribs, count * attrib_bytes, g->attribs.buffer,
                                  first * attrib_bytes, err, err_size);
    }
    if (ok) {
        vkCmdPipelineBarrier2(stream.cmd, &(VkDependencyInfo){.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                                              .memoryBarrierCount = 1,
                                                              .pMemoryBarriers = &after});
        ok = rnd_stream_submit_wait(ctx, &stream, err, err_size);
    }
    rnd_staging_release(ctx, &staging);
    rnd_stream_destroy(ctx, &stream);
    free(attribs);
    blend_centroids(s, g);
    return ok;
}

uint32_t rnd_scene_triangle_count(const rnd_gpu_scene* scene) { return scene->triangle_count; }

void rnd_scene_destroy(rnd_context* ctx, rnd_gpu_scene* g)
{
    if (!g)
        return;
    if (g->pool)
        vkDestroyDescriptorPool(ctx->device, g->pool, NULL);
    rnd_buffer* buffers[5] = {&g->positions, &g->attribs, &g->indices, &g->tri_material, &g->materials};
    for (uint32_t i = 0; i < 5; i++)
        rnd_buffer_destroy(ctx, buffers[i]);
    rnd_image_destroy(ctx, &g->textures);
    free(g->blend_ids);
    free(g->blend_centroids);
    free(g);
}
