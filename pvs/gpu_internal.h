/* gpu_internal.h - the objects behind pvs_context, shared by the files of the
 * GPU half of the PVS (gpu_context.c: creation, gpu_pipelines.c: pipelines,
 * gpu_compute.c: one computation). Not a public header. */
#ifndef TRIMVR_PVS_GPU_INTERNAL_H
#define TRIMVR_PVS_GPU_INTERNAL_H

#include "depth_bound.h"
#include "layers.h"
#include "octree.h"
#include "proxies.h"
#include "pvs.h"
#include "render_vk.h"
#include "tiles.h"

#include "mesh_shared.h"
#include "pvs_shared.h"

#include <stddef.h>

/* Mirrors pvs_view_gpu in shaders/pvs_common.glsl (std430). */
typedef struct pvs_view_gpu {
    float view_proj[16];
    float apex[4], forward[4], right[4], up[4];
    float tan_half_x, tan_half_y, tan_alpha, far_dist; /* far_dist: PVS far plane from v* */
    float near_dist, delta, focal_px, max_width;      /* max_width: clamp of infinite trim widths */
    uint32_t width, height, k, triangle_count; /* k: pvs_context.k_store */
    uint32_t tile_x, tile_y, tile_w, tile_h; /* rewritten per tile by the command buffer */
    uint32_t explain, kb_holes;             /* pvs_desc.explain; kb_holes: pvs_pool_regrow */
    uint32_t list_capacity, k_exact;        /* TV_PVS_BIND_ORDER's cap: pvs_context.list_capacity; k_exact: pvs_context.k */
    uint32_t k_lists, k_regions, pad[2];    /* pvs_context.k_lists, k_regions */
} pvs_view_gpu;
_Static_assert(offsetof(pvs_view_gpu, apex) == 64 && offsetof(pvs_view_gpu, up) == 112 &&
                   offsetof(pvs_view_gpu, tan_half_x) == 128 && offsetof(pvs_view_gpu, near_dist) == 144 &&
                   offsetof(pvs_view_gpu, width) == 160 &&
                   offsetof(pvs_view_gpu, tile_x) == 176 && offsetof(pvs_view_gpu, explain) == 192 &&
                   sizeof(pvs_view_gpu) == 224,
               "pvs_view_gpu must match pvs_view_buf's std430 layout in pvs_common.glsl");

/* Push constants of every PVS pipeline (mirrors pvs_common.glsl). */
typedef struct pvs_push {
    uint32_t layer_offset; /* first triangle of the layer in the layer list */
    uint32_t layer_count;  /* triangles in the layer */
    uint32_t layer;        /* layer index (statistics) */
    uint32_t kind;         /* TV_PVS_KIND_* for the P2 pipelines */
} pvs_push;
_Static_assert(offsetof(pvs_push, kind) == 12 && sizeof(pvs_push) == 16,
               "pvs_push must match pvs_push_block in pvs_common.glsl");

enum { PVS_PIPE_CLASSIFY, PVS_PIPE_ORDER, PVS_PIPE_RESOLVE, PVS_PIPE_RESOLVE_GROUP, PVS_PIPE_GATHER, PVS_PIPE_FF,
       PVS_PIPE_BF, PVS_PIPE_QUAD, PVS_PIPE_COUNT };

/* Buffers indexed by their binding (TV_PVS_BIND_*; VIS_IDS and VIS_WIDE
 * are images). */
struct pvs_context {
    rnd_context* rnd;
    const rnd_gpu_scene* gpu;
    uint32_t width, height, k;
    uint32_t k_store;        /* slots each list has room for: the largest of k, k_deep, k_regions */
    uint32_t k_lists;        /* entries the front and back lists hold: pvs_desc.k_deep, at least k */
    uint32_t k_regions;      /* entries the region list holds: pvs_desc.k_regions, at least k_lists */
    pvs_tile_grid grid;     /* the per-pixel buffers hold one tile */
    uint32_t kb_paged;       /* pvs_desc.kbuffer_layout is PVS_KBUFFER_PAGED (a specialisation constant) */
    uint32_t pool_pages;     /* k-buffer pages the pool holds (pvs_reserve_pool) ... */
    uint32_t max_pool_pages; /* ... and may grow to */
    uint32_t coop_sort_min; /* specialisation constants of P3's per-thread pass ... */
    uint32_t coop_width;    /* ... and of its cooperative pass: workgroup size = subgroup size */
    float near_m;
    uint32_t triangle_count; /* the scene's; proxy faces follow (pvs_geometry.glsl) */
    uint32_t max_proxies;

    pvs_octree octree; /* of the static triangles (scn_scene.dynamic_triangle_count) */
    pvs_layers layers;
    uint32_t max_layers; /* pvs_desc.max_layers */
    pvs_proxy_sort proxy_sort;
    bool* proxy_always; /* max_proxies entries: pvs_proxies_sort's `always` */
    float* tri_corners;        /* 9 floats per scene triangle, for depth_bound and the front patches */
    uint32_t* adjacency;       /* the occluders' welded adjacency and masked flags, for the front patches */
    bool* masked;
    pvs_depth_bound depth_bound; /* per computation; its cells follow pvs_view_gpu in TV_PVS_BIND_VIEW */

    rnd_stream stream;
    VkQueryPool timestamps; /* 2 per phase-step, VK_NULL_HANDLE when unsupported */
    uint32_t timestamp_capacity;
    rnd_buffer buffers[TV_PVS_BINDINGS];
    /* Visibility buffers: [0] exact (pixel centres), [1] wide (triangles
     * dilated by half a pixel); ids and the depth attachment of each. */
    rnd_image vis_ids[2], vis_depth[2];
    uint32_t list_capacity;  /* triangles the FF/BF/silhouette buffers hold (per layer) */
    uint32_t layer_capacity; /* layers the layer-stats buffer holds */

    VkDescriptorSetLayout set_layout;
    VkPipelineLayout layout;
    VkDescriptorPool pool;
    VkDescriptorSet set;
    VkPipeline pipelines[PVS_PIPE_COUNT];

    uint32_t* result;           /* sorted ids of the last computation */
    uint32_t* reasons;          /* explain: their TV_REASON_* masks, parallel to result */
    bool explain;               /* pvs_desc.explain */
    pvs_layer_stats* per_layer; /* its per-layer statistics, layer_capacity entries */
};

#define PVS_NEVER_COOP UINT32_MAX /* coop_sort_min: every sequence sorted per thread */

#define PVS_VIS_ID_FORMAT VK_FORMAT_R32_UINT
#define PVS_VIS_DEPTH_FORMAT VK_FORMAT_D32_SFLOAT

/* gpu_pipelines.c: the set layout, pipeline layout and the nine pipelines. */
bool pvs_pipelines_create(pvs_context* ctx, char* err, size_t err_size);
void pvs_pipelines_destroy(pvs_context* ctx);

/* gpu_compute.c: P3 of the current layer (descriptor sets and push constants
 * bound): the per-thread pass, then the cooperative pass unless sequences are
 * never deferred, each followed by a full memory barrier. */
void pvs_record_resolve(pvs_context* ctx, VkCommandBuffer cmd);
/* Makes every write so far visible to host reads. */
void pvs_host_barrier(VkCommandBuffer cmd);

/* gpu_timestamps.c: timestamps of a computation (one before everything, then
 * per tile one after each of P1, P2, P3 of every layer and one after P4). */
uint32_t pvs_timestamp_count(const pvs_context* ctx);
/* Grows the query pool to `count` (no pool when the device has no timestamps). */
bool pvs_reserve_timestamps(pvs_context* ctx, uint32_t count, char* err, size_t err_size);
/* Records the next timestamp at *index and advances it. */
void pvs_timestamp(pvs_context* ctx, VkCommandBuffer cmd, uint32_t* index);
/* Adds the per-phase GPU milliseconds to st->ms and the per-layer figures. */
void pvs_read_timestamps(pvs_context* ctx, pvs_stats* st);

/* gpu_context.c: (re)writes every descriptor of ctx->set. */
void pvs_write_descriptors(pvs_context* ctx);
/* Grows the per-layer buffers to hold `triangles` layer triangles and
 * `layers` layers (contents not preserved), rewriting the descriptors. */
bool pvs_reserve(pvs_context* ctx, uint32_t triangles, uint32_t layers, char* err, size_t err_size);
/* Grows the k-buffer pool to `pages` (at most max_pool_pages; contents not
 * preserved), rewriting the descriptors. */
bool pvs_reserve_pool(pvs_context* ctx, uint32_t pages, char* err, size_t err_size);
/* After a computation: where the pool ran out, the result would depend on
 * which fragments came first, so it grows (twice, or to what P2 asked for if
 * more) and *again asks the caller to compute again; at max_pool_pages the
 * lost entries stand, as overflow, and the caller computes once more with
 * pvs_view_gpu.kb_holes set, so that P3 can tell the slots they left empty
 * (pvs_kbuffer.glsl). */
bool pvs_pool_regrow(pvs_context* ctx, bool* again, char* err, size_t err_size);
/* Records the copy of the pages P2 took in `layer` of tile `t` (after its
 * P2, before the next layer's reset). */
void pvs_record_pages_taken(pvs_context* ctx, VkCommandBuffer cmd, const pvs_tile* t, uint32_t layer);
/* After a computation: the k-buffer figures of `st` and its per-layer
 * statistics (allocated: pool, links and heads; used: the pages of the
 * fullest layer of one tile and the heads; pages lacking at the cap). */
void pvs_kbuffer_stats(const pvs_context* ctx, pvs_stats* st);

#endif
