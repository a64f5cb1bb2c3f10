/* render_vk.h - the interface for GPU modules: the Vulkan objects behind
 * rnd_context and the helpers to record passes with (streams, the shared
 * queue, buffers, images, pipelines from embedded SPIR-V). render.h is what
 * the rest of the program uses; a module that records its own Vulkan passes
 * on the renderer's device (pvs/) includes this header as well.
 *
 * Threading: lavapipe exposes one queue, so every submission goes through
 * rnd_submit (mutex-guarded). Each thread records into its own rnd_stream
 * (command pool + command buffer + fence + timestamp pair); a stream must
 * never be used by two threads at once. */
#ifndef TRIMVR_RENDER_VK_H
#define TRIMVR_RENDER_VK_H

#include "render.h"
#include "vk_check.h"

#include <pthread.h>
#include <stddef.h>
#include <stdatomic.h>
#include <vulkan/vulkan.h>

struct rnd_context {
    VkInstance instance;
    VkDebugUtilsMessengerEXT messenger;
    VkPhysicalDevice physical;
    VkPhysicalDeviceProperties props;
    VkPhysicalDeviceMemoryProperties memory;
    VkDevice device;
    uint32_t queue_family;
    VkQueue queue;
    pthread_mutex_t queue_mutex; /* guards every use of `queue` */
    bool timestamps;             /* the queue family supports timestamp queries */
    uint64_t timestamp_mask;     /* its timestampValidBits as a mask */
    bool int64_atomics; /* shaderInt64 + shaderBufferInt64Atomics enabled: P2's front-patch slots (pvs_face.frag) */
    atomic_uint validation_messages;

    /* mesh pass (pipeline.c) */
    VkDescriptorSetLayout scene_set_layout; /* set TV_SET_SCENE */
    VkDescriptorSetLayout draw_set_layout;  /* set TV_SET_DRAW */
    VkPipelineLayout mesh_layout;
    VkPipeline mesh_pipeline;        /* opaque and MASK triangles */
    VkPipeline blend_pipeline;       /* BLEND colour, back to front, no depth writes */
    VkPipeline blend_depth_pipeline; /* BLEND depth and ids, colour kept */
    VkSampler sampler;
};

/* ---- submission (device.c) ---- */

/* Submits one command buffer to the shared queue under the queue mutex,
 * signalling fence (may be VK_NULL_HANDLE). Thread-safe. */
bool rnd_submit(rnd_context* ctx, VkCommandBuffer cmd, VkFence fence, char* err, size_t err_size);

/* ---- per-thread recording (stream.c) ---- */

typedef struct rnd_stream {
    VkCommandPool pool;
    VkCommandBuffer cmd;
    VkFence fence;
    VkQueryPool timestamps; /* two queries, VK_NULL_HANDLE when unsupported */
} rnd_stream;

bool rnd_stream_create(rnd_context* ctx, rnd_stream* stream, char* err, size_t err_size);
void rnd_stream_destroy(rnd_context* ctx, rnd_stream* stream);
/* Resets the pool and begins a one-time-submit recording. */
bool rnd_stream_begin(rnd_context* ctx, rnd_stream* stream, char* err, size_t err_size);
/* Ends the recording, submits it through rnd_submit and waits for the fence. */
bool rnd_stream_submit_wait(rnd_context* ctx, rnd_stream* stream, char* err, size_t err_size);
/* Writes timestamp `index` (0 or 1) after all previous work; no-op without
 * timestamp support. */
void rnd_stream_timestamp(rnd_context* ctx, rnd_stream* stream, uint32_t index);
/* Milliseconds between timestamps 0 and 1 of the last submitted recording,
 * -1 when unsupported or unavailable. */
double rnd_stream_gpu_ms(rnd_context* ctx, rnd_stream* stream);

/* ---- resources (resources.c) ---- */

typedef struct rnd_buffer {
    VkBuffer buffer;
    VkDeviceMemory memory;
    VkDeviceSize size;
    void* mapped; /* non-NULL for host-visible buffers */
} rnd_buffer;

typedef struct rnd_image {
    VkImage image;
    VkDeviceMemory memory;
    VkImageView view;
    VkFormat format;
    uint32_t width, height, layers;
} rnd_image;

/* host_visible: HOST_VISIBLE|HOST_COHERENT memory, persistently mapped;
 * otherwise DEVICE_LOCAL. size must be > 0. */
bool rnd_buffer_create(rnd_context* ctx, VkDeviceSize size, VkBufferUsageFlags usage, bool host_visible,
                       rnd_buffer* out, char* err, size_t err_size);
void rnd_buffer_destroy(rnd_context* ctx, rnd_buffer* buffer);

/* Makes a host-visible buffer at least `size` bytes, recreating it (grown by
 * half again) only when too small; the contents are not preserved. */
bool rnd_buffer_reserve(rnd_context* ctx, rnd_buffer* buffer, VkDeviceSize size, VkBufferUsageFlags usage,
                        char* err, size_t err_size);

/* 2D image with one mip level and `layers` layers, with one view of type
 * view_type (2D or 2D_ARRAY) and the aspect implied by format. */
bool rnd_image_create(rnd_context* ctx, uint32_t width, uint32_t height, uint32_t layers, VkImageViewType view_type,
                      VkFormat format, VkImageUsageFlags usage, rnd_image* out, char* err, size_t err_size);
void rnd_image_destroy(rnd_context* ctx, rnd_image* image);

VkImageAspectFlags rnd_format_aspect(VkFormat format);

/* One image layout transition (synchronization2). */
void rnd_image_barrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout old_layout,
                       VkImageLayout new_layout, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                       VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access);

/* Host-visible staging buffers kept alive until a batch of uploads has been
 * submitted and waited for. */
typedef struct rnd_staging {
    rnd_buffer* buffers;
    uint32_t count, capacity;
} rnd_staging;

/* Records a copy of `size` bytes into dst (offset 0) through a new staging
 * buffer added to staging. */
bool rnd_upload_buffer(rnd_context* ctx, VkCommandBuffer cmd, rnd_staging* staging, const void* data,
                       VkDeviceSize size, VkBuffer dst, char* err, size_t err_size);
/* The same into dst at byte `offset`. */
bool rnd_upload_buffer_at(rnd_context* ctx, VkCommandBuffer cmd, rnd_staging* staging, const void* data,
                          VkDeviceSize size, VkBuffer dst, VkDeviceSize offset, char* err, size_t err_size);
/* Records a copy of tightly packed texels (layer after layer) into every
 * pixel of every layer of dst, leaving it
 * in SHADER_READ_ONLY_OPTIMAL for fragment and compute shaders. */
bool rnd_upload_image(rnd_context* ctx, VkCommandBuffer cmd, rnd_staging* staging, const void* texels,
                      VkDeviceSize size, const rnd_image* dst, char* err, size_t err_size);
void rnd_staging_release(rnd_context* ctx, rnd_staging* staging);

/* ---- pipelines (pipeline.c) ---- */

/* A pool holding exactly one set of `layout` (pool sizes as given) and that
 * set. Destroying the pool frees the set. */
bool rnd_descriptor_set_create(rnd_context* ctx, VkDescriptorSetLayout layout, const VkDescriptorPoolSize* sizes,
                               uint32_t size_count, VkDescriptorPool* pool, VkDescriptorSet* set, char* err,
                               size_t err_size);

VkShaderModule rnd_shader_module(rnd_context* ctx, const uint32_t* code, size_t code_size, char* err,
                                 size_t err_size);
/* A triangle-list pipeline for dynamic rendering, shared by the mesh pass and
 * the PVS passes: no vertex input (vertex pulling), no culling, one sample,
 * dynamic viewport and scissor. */
typedef enum rnd_blend {
    RND_BLEND_NONE = 0, /* fragments replace */
    RND_BLEND_ALPHA,    /* src-alpha over dst; alpha = max(src, dst) */
    RND_BLEND_KEEP,     /* dst kept: a pass that writes only the other attachments and depth */
} rnd_blend;
typedef struct rnd_raster_desc {
    VkShaderModule vert, frag;
    const VkSpecializationInfo* frag_spec; /* the fragment shader's specialisation constants; NULL: none */
    VkPipelineLayout layout;
    uint32_t color_count;              /* colour attachments, at most 2 */
    const VkFormat* color_formats;
    VkColorComponentFlags color_write; /* the same write mask for each of them */
    VkFormat depth_format;
    bool depth_test;                   /* LESS test with depth writes; off: neither */
    bool depth_read_only;              /* with depth_test: no depth writes */
    rnd_blend blend;                   /* of colour attachment 0; needs independentBlend */
} rnd_raster_desc;
bool rnd_raster_pipeline_create(rnd_context* ctx, const rnd_raster_desc* desc, VkPipeline* out, char* err,
                                size_t err_size);
/* Creates the descriptor set layouts, pipeline layout, sampler and the mesh
 * pipeline stored in ctx; rnd_mesh_pipeline_destroy releases them. */
bool rnd_mesh_pipeline_create(rnd_context* ctx, char* err, size_t err_size);
void rnd_mesh_pipeline_destroy(rnd_context* ctx);

/* Attachment formats of the mesh pass (target.c creates images of these). */
#define RND_COLOR_FORMAT VK_FORMAT_R8G8B8A8_SRGB
#define RND_ID_FORMAT VK_FORMAT_R32_UINT
#define RND_DEPTH_FORMAT VK_FORMAT_D32_SFLOAT

/* Push constants of the mesh pass; layout mirrors mesh_push.glsl. */
typedef struct rnd_mesh_push {
    float view_proj[16];
    uint32_t use_draw_ids; /* 0: triangle = draw slot, 1: triangle = draw_ids[slot] */
    uint32_t skip_blend;   /* 1: BLEND triangles are clipped away (the opaque pass) */
} rnd_mesh_push;
_Static_assert(offsetof(rnd_mesh_push, use_draw_ids) == 64 && offsetof(rnd_mesh_push, skip_blend) == 68 &&
                   sizeof(rnd_mesh_push) == 72,
               "rnd_mesh_push must match tv_mesh_push in mesh_push.glsl");

/* Records the upload of every scene texture as one layer of a 2D array
 * image (a single white layer when there are none); see textures.c. */
bool rnd_texture_array_create(rnd_context* ctx, VkCommandBuffer cmd, rnd_staging* staging, const scn_scene* scene,
                              rnd_image* out, char* err, size_t err_size);

/* ---- scene and target internals (gpu_scene.c, target.c) ---- */

struct rnd_gpu_scene {
    uint32_t triangle_count;
    /* BLEND triangles, ascending, and their world centroids for the
     * back-to-front sort (kept posed by rnd_scene_update_vertices) */
    uint32_t blend_count;
    uint32_t* blend_ids;
    float* blend_centroids;
    rnd_buffer positions, attribs, indices, tri_material, materials;
    rnd_image textures; /* one layer per scene texture (textures.c) */
    VkDescriptorPool pool;
    VkDescriptorSet set;
};

struct rnd_target {
    uint32_t width, height;
    rnd_image color, ids, depth;
    rnd_stream stream;
    rnd_buffer readback;  /* width*height*4 bytes, host-visible */
    rnd_buffer draw_ids;  /* grow-only subset id list, host-visible */
    uint32_t* sort_scratch; /* grow-only copy for unsorted id lists */
    uint32_t sort_capacity;
    struct rnd_blend_key* blend_keys; /* grow-only back-to-front sort scratch */
    uint32_t blend_key_capacity;
    VkDescriptorPool pool;
    VkDescriptorSet draw_set; /* binds draw_ids; rewritten when it grows */
    bool drawn;             /* images hold a finished draw in TRANSFER_SRC layout */
};

/* Grows the subset id buffer to hold count ids (contents not preserved),
 * rebinding it when it was recreated. Logs and returns false on failure. */
bool rnd_target_reserve_draw_ids(rnd_context* ctx, rnd_target* target, uint32_t count);

#endif
