/* gpu_context.c - pvs_create / pvs_destroy: welding and adjacency, the
 * octree, the per-pixel GPU buffers (sized once from the tile), the
 * k-buffer page pool (grown on demand by pvs_pool_regrow) and the per-layer
 * buffers (grown on demand by pvs_reserve). */
#include "gpu_internal.h"

#include "clock.h"
#include "log.h"
#include "weld.h"

#include <assert.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PVS_DEFAULT_WIDTH 512u
#define PVS_DEFAULT_HEIGHT 512u
/* k = 32 overflows far less (docs/results.md) but exposes false negatives
 * that overflow hid: quality_interior_walk, _interior_run_fixed and
 * _sponza_walk lose pixels at k = 32 with the old layout too. */
#define PVS_DEFAULT_K 16u
/* Larger images are tiled; the largest per-pixel buffer, the carry, then
 * takes at most 256 MiB (lavapipe's maxStorageBufferRange allows half). */
#define PVS_DEFAULT_TILE_PIXELS (1024u * 1024u)
/* The flat k-buffer layout keeps every list's k slots: 128 MiB at k = 16, in two buffers
 * of 64 MiB (flat_pages_per_pixel), so k = 32 still fits one tile. */
#define PVS_DEFAULT_FLAT_TILE_PIXELS (512u * 512u)
/* The k-buffer pool starts at this many pages per tile pixel, whatever k
 * (most lists hold 0-2 entries; docs/pvs-gpu-passes.md, "k-buffer pages"),
 * and grows when a computation runs out (pvs_pool_regrow). */
#define PVS_DEFAULT_POOL_PAGES_PER_PIXEL 2u
#define PVS_DEFAULT_MAX_PROXIES 1024u
/* The paper's N. On a CPU device (lavapipe) the cooperative pass only
 * costs: a workgroup resolves one pixel where a SIMD batch of the per-thread
 * pass resolves eight (Sponza, 90k of 481k resolves deferred: P3 640 ->
 * 1890 ms), so there sequences are never deferred unless the caller asks. */
#define PVS_DEFAULT_COOP_SORT_MIN 8u

static const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

/* Bindings the CPU writes or reads back live in host-visible memory. */
static bool host_visible(uint32_t binding)
{
    return binding == TV_PVS_BIND_VIEW || binding == TV_PVS_BIND_LAYER_TRIS || binding == TV_PVS_BIND_COUNTERS ||
           binding == TV_PVS_BIND_TRI_FLAGS || binding == TV_PVS_BIND_LAYER_STATS || binding == TV_PVS_BIND_PROXIES ||
           binding == TV_PVS_BIND_KALLOC || binding == TV_PVS_BIND_PATCH;
}

static bool create_buffer(pvs_context* ctx, uint32_t binding, VkDeviceSize size, char* err, size_t err_size)
{
    if (size > ctx->rnd->props.limits.maxStorageBufferRange) {
        snprintf(err, err_size, "pvs: buffer %u needs %llu bytes, over maxStorageBufferRange %u (lower the PVS resolution)",
                 binding, (unsigned long long)size, ctx->rnd->props.limits.maxStorageBufferRange);
        return false;
    }
    VkBufferUsageFlags usage = storage;
    if (binding == TV_PVS_BIND_COUNTERS) /* indirect commands; the draw counts are copied into the layer stats */
        usage |= VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    if (binding == TV_PVS_BIND_KALLOC) /* each layer's page count is copied within it */
        usage |= VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    rnd_buffer_destroy(ctx->rnd, &ctx->buffers[binding]);
    return rnd_buffer_create(ctx->rnd, size, usage, host_visible(binding), &ctx->buffers[binding], err, err_size);
}

void pvs_write_descriptors(pvs_context* ctx)
{
    VkDescriptorBufferInfo infos[TV_PVS_BINDINGS];
    VkWriteDescriptorSet writes[TV_PVS_BINDINGS];
    VkDescriptorImageInfo images[2] = {{.imageView = ctx->vis_ids[0].view, .imageLayout = VK_IMAGE_LAYOUT_GENERAL},
                                       {.imageView = ctx->vis_ids[1].view, .imageLayout = VK_IMAGE_LAYOUT_GENERAL}};
    for (uint32_t i = 0; i < TV_PVS_BINDINGS; i++) {
        infos[i] = (VkDescriptorBufferInfo){ctx->buffers[i].buffer, 0, VK_WHOLE_SIZE};
        bool is_image = i == TV_PVS_BIND_VIS_IDS || i == TV_PVS_BIND_VIS_WIDE;
        writes[i] = (VkWriteDescriptorSet){
            .sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
            .dstSet = ctx->set,
            .dstBinding = i,
            .descriptorCount = 1,
            .descriptorType = is_image ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
            .pBufferInfo = is_image ? NULL : &infos[i],
            .pImageInfo = is_image ? &images[i == TV_PVS_BIND_VIS_WIDE] : NULL,
        };
    }
    vkUpdateDescriptorSets(ctx->rnd->device, TV_PVS_BINDINGS, writes, 0, NULL);
}

bool pvs_reserve(pvs_context* ctx, uint32_t triangles, uint32_t layers, char* err, size_t err_size)
{
    triangles = triangles ? triangles : 1;
    layers = layers ? layers : 1;
    bool grow_tris = triangles > ctx->list_capacity, grow_layers = layers > ctx->layer_capacity;
    if (!grow_tris && !grow_layers)
        return true;
    if (grow_tris) {
        VkDeviceSize n = triangles + triangles / 2;
        if (!create_buffer(ctx, TV_PVS_BIND_FF, n * 4, err, err_size) ||
            !create_buffer(ctx, TV_PVS_BIND_BF, n * 4, err, err_size) ||
            !create_buffer(ctx, TV_PVS_BIND_SIL, n * 3 * TV_PVS_SIL_VEC4 * 16, err, err_size) ||
            !create_buffer(ctx, TV_PVS_BIND_ORDER, TV_PVS_ORDER_GROUP(n, (n + TV_WG_SIZE - 1) / TV_WG_SIZE) * 4, err,
                           err_size))
            return false;
        ctx->list_capacity = (uint32_t)n;
    }
    if (grow_layers) {
        uint32_t n = layers + layers / 2;
        if (!create_buffer(ctx, TV_PVS_BIND_LAYER_STATS, (VkDeviceSize)n * 16 * TV_PVS_LAYER_STATS_STRIDE, err,
                           err_size) ||
            !create_buffer(ctx, TV_PVS_BIND_KALLOC, (TV_PVS_A_LAYERS + (VkDeviceSize)pvs_tile_count(&ctx->grid) * n) * 4,
                           err, err_size))
            return false;
        pvs_layer_stats* per_layer = realloc(ctx->per_layer, sizeof *per_layer * n);
        if (!per_layer) {
            snprintf(err, err_size, "pvs: out of memory for the statistics of %u layers", n);
            return false;
        }
        ctx->per_layer = per_layer;
        ctx->layer_capacity = n;
    }
    pvs_write_descriptors(ctx);
    return true;
}

void pvs_record_pages_taken(pvs_context* ctx, VkCommandBuffer cmd, const pvs_tile* t, uint32_t layer)
{
    if (!ctx->kb_paged)
        return;
    uint32_t tile = t->y / ctx->grid.tile_height * ctx->grid.cols + t->x / ctx->grid.tile_width;
    VkBuffer b = ctx->buffers[TV_PVS_BIND_KALLOC].buffer;
    vkCmdCopyBuffer(cmd, b, b, 1,
                    &(VkBufferCopy){TV_PVS_A_TAKEN * 4, (TV_PVS_A_LAYERS + tile * ctx->layer_capacity + layer) * 4, 4});
}

/* The most pages P2 asked for in `layer` of one tile (past pool_pages where
 * the pool ran out). */
static uint32_t pages_asked(const pvs_context* ctx, uint32_t layer)
{
    const uint32_t* taken = (const uint32_t*)ctx->buffers[TV_PVS_BIND_KALLOC].mapped + TV_PVS_A_LAYERS;
    uint32_t most = 0;
    for (uint32_t t = 0; t < pvs_tile_count(&ctx->grid); t++) {
        uint32_t n = taken[t * ctx->layer_capacity + layer];
        most = n > most ? n : most;
    }
    return most;
}

static uint64_t kbuffer_bytes(const pvs_context* ctx)
{
    return ctx->buffers[TV_PVS_BIND_KPOOL].size + ctx->buffers[TV_PVS_BIND_KREGIONS].size +
           ctx->buffers[TV_PVS_BIND_KLINKS].size + ctx->buffers[TV_PVS_BIND_KHEADS].size;
}

void pvs_kbuffer_stats(const pvs_context* ctx, pvs_stats* st)
{
    st->kbuffer_bytes = kbuffer_bytes(ctx);
    if (!ctx->kb_paged) { /* the bytes of the entries P3 read (pvs_resolve.glsl, finish_pixel) */
        const uint32_t* s = ctx->buffers[TV_PVS_BIND_LAYER_STATS].mapped;
        for (uint32_t l = 0; l < ctx->layers.layer_count; l++) {
            ctx->per_layer[l].kbuffer_bytes_used = s[4 * TV_PVS_LAYER_STATS_STRIDE * l];
            if (ctx->per_layer[l].kbuffer_bytes_used > st->kbuffer_bytes_used)
                st->kbuffer_bytes_used = ctx->per_layer[l].kbuffer_bytes_used;
        }
        return;
    }
    const uint64_t page_bytes = TV_PVS_PAGE * 8 + 4; /* slots and link */
    for (uint32_t l = 0; l < ctx->layers.layer_count; l++) {
        uint32_t asked = pages_asked(ctx, l), have = ctx->pool_pages;
        ctx->per_layer[l].kbuffer_bytes_used = (asked < have ? asked : have) * page_bytes;
        if (ctx->per_layer[l].kbuffer_bytes_used > st->kbuffer_bytes_used)
            st->kbuffer_bytes_used = ctx->per_layer[l].kbuffer_bytes_used;
        if (asked > have && asked - have > st->kbuffer_lost)
            st->kbuffer_lost = asked - have;
    }
    st->kbuffer_bytes_used += ctx->buffers[TV_PVS_BIND_KHEADS].size;
}

bool pvs_reserve_pool(pvs_context* ctx, uint32_t pages, char* err, size_t err_size)
{
    pages = pages < ctx->max_pool_pages ? pages : ctx->max_pool_pages;
    if (pages <= ctx->pool_pages)
        return true;
    if (!create_buffer(ctx, TV_PVS_BIND_KPOOL, (VkDeviceSize)pages * TV_PVS_PAGE * 8, err, err_size) ||
        !create_buffer(ctx, TV_PVS_BIND_KLINKS, (VkDeviceSize)pages * 4, err, err_size))
        return false;
    ctx->pool_pages = pages;
    pvs_write_descriptors(ctx);
    return true;
}

bool pvs_pool_regrow(pvs_context* ctx, bool* again, char* err, size_t err_size)
{
    *again = false;
    if (!ctx->kb_paged) /* the flat layout cannot run out */
        return true;
    uint32_t need = 0, have = ctx->pool_pages;
    for (uint32_t l = 0; l < ctx->layers.layer_count; l++) {
        uint32_t asked = pages_asked(ctx, l);
        need = asked > need ? asked : need;
    }
    pvs_view_gpu* view = ctx->buffers[TV_PVS_BIND_VIEW].mapped;
    *again = need > have && (have < ctx->max_pool_pages || !view->kb_holes);
    if (!*again)
        return true;
    if (have >= ctx->max_pool_pages) { /* at the largest pool: once more, with the lost slots marked */
        view->kb_holes = 1;
        tv_log(TV_LOG_INFO, "pvs: the k-buffer pool of %u pages, the most allowed, ran out (%u asked for): "
               "entries are lost as overflow", have, need);
        return true;
    }
    uint32_t twice = have > UINT32_MAX / 2 ? UINT32_MAX : 2 * have;
    if (!pvs_reserve_pool(ctx, need > twice ? need : twice, err, err_size))
        return false;
    tv_log(TV_LOG_INFO, "pvs: the k-buffer pool of %u pages ran out (%u asked for): %u pages, computing again", have,
           need, ctx->pool_pages);
    return true;
}

/* Buffers sized by the scene or the tile, created once. */
static bool create_fixed_buffers(pvs_context* ctx, char* err, size_t err_size)
{
    const VkDeviceSize pixels = (VkDeviceSize)ctx->grid.tile_width * ctx->grid.tile_height;
    const VkDeviceSize tris = ctx->triangle_count ? ctx->triangle_count : 1;
    const VkDeviceSize drawn = tris + 12 * (VkDeviceSize)ctx->max_proxies; /* proxy faces follow the scene's */
    struct {
        uint32_t binding;
        VkDeviceSize size;
    } fixed[] = {
        {TV_PVS_BIND_VIEW, sizeof(pvs_view_gpu) + sizeof(float) * (VkDeviceSize)ctx->depth_bound.cell_count},
        {TV_PVS_BIND_ADJ, tris * 12},
        {TV_PVS_BIND_LAYER_TRIS, drawn * 4},
        {TV_PVS_BIND_COUNTERS, TV_PVS_C_COUNT * 4},
        {TV_PVS_BIND_KPOOL, (VkDeviceSize)ctx->pool_pages * TV_PVS_PAGE * 8},
        {TV_PVS_BIND_KREGIONS, ctx->kb_paged ? 8 : (VkDeviceSize)ctx->pool_pages * TV_PVS_PAGE * 8}, /* paged: unused */
        {TV_PVS_BIND_KHEADS, ctx->kb_paged ? pixels * TV_PVS_LISTS * 4 : 4}, /* flat: unused */
        {TV_PVS_BIND_KLINKS, ctx->kb_paged ? (VkDeviceSize)ctx->pool_pages * 4 : 4},
        {TV_PVS_BIND_PIXCOUNT, pixels * 16},
        {TV_PVS_BIND_PIXSTATE, pixels * 16},
        {TV_PVS_BIND_CARRY, pixels * TV_K_CARRY * 16},
        {TV_PVS_BIND_ACTIVE, pixels * 4},
        {TV_PVS_BIND_ACTIVE_LIST, pixels * 4},
        {TV_PVS_BIND_TRI_FLAGS, drawn * 4},
        {TV_PVS_BIND_CENTRE_DEPTH, pixels * 4 * TV_PVS_CENTRE_STRIDE},
        {TV_PVS_BIND_LOST, pixels * TV_PVS_LOST_STRIDE * 4},
        {TV_PVS_BIND_COOP_LIST, pixels * 4},
        {TV_PVS_BIND_PROXIES, (VkDeviceSize)ctx->max_proxies * PVS_PROXY_FLOATS * 4},
        {TV_PVS_BIND_SPILL, (1 + 2 * drawn) * 4},
        {TV_PVS_BIND_PATCH, 4 * drawn * 4}, /* labels, then 3 region labels per drawn triangle */
    };
    for (size_t i = 0; i < sizeof fixed / sizeof fixed[0]; i++) {
        if (!create_buffer(ctx, fixed[i].binding, fixed[i].size, err, err_size))
            return false;
    }
    for (int i = 0; i < 2; i++) {
        if (!rnd_image_create(ctx->rnd, ctx->width, ctx->height, 1, VK_IMAGE_VIEW_TYPE_2D, PVS_VIS_ID_FORMAT,
                              VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT, &ctx->vis_ids[i],
                              err, err_size) ||
            !rnd_image_create(ctx->rnd, ctx->width, ctx->height, 1, VK_IMAGE_VIEW_TYPE_2D, PVS_VIS_DEPTH_FORMAT,
                              VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, &ctx->vis_depth[i], err, err_size))
            return false;
    }
    return true;
}

/* Crack edges become TV_ADJ_CRACK in the GPU's copy of the adjacency. */
static bool mark_cracks(const scn_scene* scene, const uint32_t* indices, uint32_t count, uint32_t* adjacency,
                        char* err, size_t err_size)
{
    uint8_t* crack = malloc(3 * (size_t)count);
    if (!crack) {
        snprintf(err, err_size, "pvs: out of memory for the cracks of %s", scene->name);
        return false;
    }
    double t0 = tv_now_ms();
    size_t n = scn_mark_cracks(crack, adjacency, indices, count, scene->positions, TV_PVS_CRACK_GAP_M);
    for (size_t i = 0; i < 3 * (size_t)count; i++)
        if (crack[i])
            adjacency[i] = TV_ADJ_CRACK;
    tv_log(TV_LOG_INFO, "pvs: %s: %zu border edges run along another across a crack (%.0f ms)", scene->name, n,
           tv_now_ms() - t0);
    free(crack);
    return true;
}

_Static_assert(PVS_K_MAX <= TV_K_FRONT && PVS_K_MAX <= TV_K_BACK && PVS_K_MAX <= TV_K_TRIM && PVS_K_MAX <= TV_K_UMBRA,
               "pvs.h promises k up to PVS_K_MAX");
_Static_assert(TV_ADJ_REST == SCN_EDGE_REST, "the shaders read scn_join_rest_edges' flag");

/* Border edges resting on an opaque face become TV_ADJ_REST | face, after
 * the cracks (which stay always-silhouettes); then glued edges, never silhouettes. */
static bool join_rest_edges(const scn_scene* scene, const uint32_t* ids, const uint32_t* indices, uint32_t count,
                            uint32_t* adjacency, char* err, size_t err_size)
{
    uint8_t* solid = malloc(count ? count : 1);
    if (!solid) {
        snprintf(err, err_size, "pvs: out of memory for the rest edges of %s", scene->name);
        return false;
    }
    for (uint32_t c = 0; c < count; c++)
        solid[c] = scene->materials[scene->tri_material[ids[c]]].alpha_mode == SCN_ALPHA_OPAQUE;
    double t0 = tv_now_ms();
    size_t n = scn_join_rest_edges(adjacency, indices, count, scene->positions, solid);
    size_t g = scn_join_glued_edges(adjacency, indices, count, scene->positions, solid);
    tv_log(TV_LOG_INFO, "pvs: %s: %zu border edges rest on an opaque face, %zu edges glued (%.0f ms)", scene->name, n,
           g, tv_now_ms() - t0);
    free(solid);
    return true;
}

/* Whether triangle t can occlude: static and opaque. Moving and
 * SCN_ALPHA_BLEND triangles are see-through (pvs_geometry.glsl). */
static bool occluder(const scn_scene* scene, uint32_t t)
{
    return t < scene->triangle_count - scene->dynamic_triangle_count &&
           scene->materials[scene->tri_material[t]].alpha_mode != SCN_ALPHA_BLEND;
}

/* The adjacency among the occluders only, so that an occluder's edge next
 * to a see-through triangle is a border (a silhouette from everywhere):
 * built over the occluders' indices (`ids`: theirs in the scene), then
 * scattered back; a see-through triangle's own edges stay borders (P1
 * never reads them). */
static bool occluder_adjacency(const scn_scene* scene, const uint32_t* remap, uint32_t* adjacency, char* err,
                               size_t err_size)
{
    uint32_t* ids = malloc(sizeof(uint32_t) * scene->triangle_count);
    uint32_t* indices = malloc(sizeof(uint32_t) * 3 * (size_t)scene->triangle_count);
    uint32_t* compact = malloc(sizeof(uint32_t) * 3 * (size_t)scene->triangle_count);
    bool ok = ids && indices && compact;
    if (!ok)
        snprintf(err, err_size, "pvs: out of memory for the adjacency of %s", scene->name);
    uint32_t n = 0;
    for (uint32_t t = 0; ok && t < scene->triangle_count; t++) {
        if (occluder(scene, t)) {
            memcpy(indices + 3 * (size_t)n, scene->indices + 3 * (size_t)t, 3 * sizeof(uint32_t));
            ids[n++] = t;
        }
    }
    if (ok) {
        scn_build_adjacency(compact, indices, n, remap);
        size_t sheets = scn_pair_sheets(compact, indices, n, remap, scene->positions);
        tv_log(TV_LOG_INFO, "pvs: %s: %zu edges of four triangles are two flat sheets (not silhouettes)", scene->name,
               sheets);
        size_t joined = scn_join_tjunctions(compact, indices, n, scene->positions);
        tv_log(TV_LOG_INFO, "pvs: %s: %zu border edges continue flat past a T-junction (not silhouettes)",
               scene->name, joined);
        ok = mark_cracks(scene, indices, n, compact, err, err_size);
    }
    if (ok)
        ok = join_rest_edges(scene, ids, indices, n, compact, err, err_size);
    for (size_t i = 0; ok && i < 3 * (size_t)scene->triangle_count; i++)
        adjacency[i] = SCN_EDGE_BORDER;
    for (uint32_t c = 0; ok && c < n; c++) {
        for (uint32_t e = 0; e < 3; e++) {
            uint32_t other = compact[3 * (size_t)c + e];
            adjacency[3 * (size_t)ids[c] + e] = other >= TV_ADJ_CRACK ? other
                                                : (other & TV_ADJ_REST) | ids[other & ~TV_ADJ_REST];
        }
    }
    free(ids);
    free(indices);
    free(compact);
    return ok;
}

/* The occluders' adjacency and masked flags, kept for the front patches labelled per view (pvs/patches.h). */
static bool keep_patch_inputs(pvs_context* ctx, const scn_scene* scene, const uint32_t* adjacency)
{
    ctx->adjacency = malloc(sizeof(uint32_t) * 3 * (size_t)scene->triangle_count);
    ctx->masked = malloc(scene->triangle_count);
    if (!ctx->adjacency || !ctx->masked)
        return false;
    memcpy(ctx->adjacency, adjacency, sizeof(uint32_t) * 3 * (size_t)scene->triangle_count);
    for (uint32_t t = 0; t < scene->triangle_count; t++)
        ctx->masked[t] = scene->materials[scene->tri_material[t]].alpha_mode == SCN_ALPHA_MASK;
    return true;
}

/* Welded adjacency, uploaded once: P1 finds silhouettes with it. */
static bool upload_adjacency(pvs_context* ctx, const scn_scene* scene, char* err, size_t err_size)
{
    if (scene->triangle_count == 0)
        return true;
    uint32_t* remap = malloc(sizeof(uint32_t) * (scene->vertex_count ? scene->vertex_count : 1));
    uint32_t* adjacency = malloc(sizeof(uint32_t) * 3 * (size_t)scene->triangle_count);
    bool ok = remap && adjacency;
    if (!ok)
        snprintf(err, err_size, "pvs: out of memory for the adjacency of %s", scene->name);
    if (ok) {
        scn_weld_positions(remap, scene->positions, scene->vertex_count);
        ok = occluder_adjacency(scene, remap, adjacency, err, err_size);
        rnd_staging staging = {0};
        if (ok && !keep_patch_inputs(ctx, scene, adjacency))
            ok = (snprintf(err, err_size, "pvs: out of memory for the front patches of %s", scene->name), false);
        ok = ok && rnd_stream_begin(ctx->rnd, &ctx->stream, err, err_size) &&
             rnd_upload_buffer(ctx->rnd, ctx->stream.cmd, &staging, adjacency,
                               sizeof(uint32_t) * 3 * (VkDeviceSize)scene->triangle_count,
                               ctx->buffers[TV_PVS_BIND_ADJ].buffer, err, err_size)  &&
             rnd_stream_submit_wait(ctx->rnd, &ctx->stream, err, err_size);
        rnd_staging_release(ctx->rnd, &staging);
    }
    free(remap);
    free(adjacency);
    return ok;
}

/* The cooperative pass runs one subgroup per pixel; 4..128 threads (128 is
 * Vulkan's minimum maxComputeWorkGroupSize[0]). */
static uint32_t coop_width(const rnd_context* rnd)
{
    VkPhysicalDeviceSubgroupProperties sub = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
    VkPhysicalDeviceProperties2 props = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, .pNext = &sub};
    vkGetPhysicalDeviceProperties2(rnd->physical, &props);
    return sub.subgroupSize < 4 ? 4 : sub.subgroupSize > 128 ? 128 : sub.subgroupSize;
}

/* The flat layout's pages per pixel in each of its two buffers (kb_flat_page): every list
 * holds k_store slots, as the layout before the pool had it; the front and back lists in
 * the pool, the trim and umbra lists (the region list) in TV_PVS_BIND_KREGIONS. */
static uint32_t flat_pages_per_pixel(const pvs_context* ctx)
{
    return TV_PVS_LISTS / 2 * ((ctx->k_store + TV_PVS_PAGE - 1) / TV_PVS_PAGE);
}

/* The paged pool's first and largest size (its slots fit one storage
 * buffer); the flat layout's fixed one (pvs_common.glsl, kb_flat_page). */
static void size_pool(pvs_context* ctx, const pvs_desc* d)
{
    const uint64_t tile_pixels = (uint64_t)ctx->grid.tile_width * ctx->grid.tile_height;
    if (!ctx->kb_paged) {
        ctx->pool_pages = ctx->max_pool_pages = (uint32_t)(tile_pixels * flat_pages_per_pixel(ctx));
        return;
    }
    uint64_t cap = ctx->rnd->props.limits.maxStorageBufferRange / (TV_PVS_PAGE * 8);
    cap = d->max_kbuffer_pages && d->max_kbuffer_pages < cap ? d->max_kbuffer_pages : cap;
    uint64_t start = d->kbuffer_pages ? d->kbuffer_pages : tile_pixels * PVS_DEFAULT_POOL_PAGES_PER_PIXEL;
    ctx->max_pool_pages = (uint32_t)cap;
    ctx->pool_pages = (uint32_t)(start < cap ? start : cap);
}

/* The tile grid: at most `max_tile_pixels` pixels (0: the default) per tile
 * and no per-pixel buffer over maxStorageBufferRange (the largest per pixel
 * is the carry, or each of the flat layout's two buffers: 256 B at k = 16). */
static pvs_tile_grid tile_grid(const pvs_context* ctx, uint32_t max_tile_pixels)
{
    uint64_t per_pixel = (uint64_t)TV_K_CARRY * 16;
    uint64_t flat = ctx->kb_paged ? 0 : (uint64_t)flat_pages_per_pixel(ctx) * TV_PVS_PAGE * 8;
    uint64_t fit = ctx->rnd->props.limits.maxStorageBufferRange / (flat > per_pixel ? flat : per_pixel);
    uint64_t budget = max_tile_pixels      ? max_tile_pixels
                      : ctx->kb_paged      ? PVS_DEFAULT_TILE_PIXELS
                                           : PVS_DEFAULT_FLAT_TILE_PIXELS;
    return pvs_tile_grid_make(ctx->width, ctx->height, budget < fit ? budget : fit);
}

static bool check_desc(const pvs_desc* d, char* err, size_t err_size)
{
    const char* names[3] = {"k", "k_deep", "k_regions"};
    const uint32_t ks[3] = {d->k, d->k_deep, d->k_regions};
    for (int i = 0; i < 3; i++) {
        if (ks[i] > PVS_K_MAX) {
            snprintf(err, err_size, "pvs: %s = %u exceeds the shader capacity TV_K_* = %u", names[i], ks[i], PVS_K_MAX);
            return false;
        }
    }
    if (!(d->near_m >= 0.0f)) {
        snprintf(err, err_size, "pvs: near_m must be >= 0 (0 = default)");
        return false;
    }
    return true;
}

/* The triangles' corners and the depth bound's cells P0 fills per
 * computation for P1 (pvs/depth_bound.h); before create_fixed_buffers. */
static bool create_depth_bound(pvs_context* ctx, const scn_scene* scene, char* err, size_t err_size)
{
    ctx->tri_corners = malloc(sizeof(float) * 9 * ((size_t)scene->triangle_count + 1));
    if (!ctx->tri_corners || !pvs_depth_bound_init(&ctx->depth_bound, ctx->width, ctx->height)) {
        snprintf(err, err_size, "pvs: out of memory for the corners of %u triangles", scene->triangle_count);
        return false;
    }
    for (size_t t = 0; t < scene->triangle_count; t++) {
        for (int c = 0; c < 3; c++)
            memcpy(ctx->tri_corners + 9 * t + 3 * c, scene->positions + 3 * (size_t)scene->indices[3 * t + c],
                   3 * sizeof(float));
    }
    return true;
}

pvs_context* pvs_create(rnd_context* rnd, const scn_scene* scene, const rnd_gpu_scene* gpu, const pvs_desc* desc,
                        char* err, size_t err_size)
{
    assert(rnd && scene && gpu);
    pvs_desc d = desc ? *desc : (pvs_desc){0};
    if (!check_desc(&d, err, err_size))
        return NULL;
    uint32_t max_proxies = d.max_proxies ? d.max_proxies : PVS_DEFAULT_MAX_PROXIES;
    /* the id flags sit above the ids, proxy faces included */
    if ((uint64_t)scene->triangle_count + 12ull * max_proxies >= TV_ID_STRADDLED) {
        snprintf(err, err_size, "pvs: %s has %u triangles and room for %u proxies, the PVS handles fewer than %u ids",
                 scene->name, scene->triangle_count, max_proxies, TV_ID_STRADDLED);
        return NULL;
    }
    if (scene->dynamic_triangle_count > scene->triangle_count) {
        snprintf(err, err_size, "pvs: %s has %u dynamic triangles of %u", scene->name,
                 scene->dynamic_triangle_count, scene->triangle_count);
        return NULL;
    }
    if (rnd_scene_triangle_count(gpu) != scene->triangle_count) {
        snprintf(err, err_size, "pvs: %s has %u triangles but the GPU scene %u", scene->name,
                 scene->triangle_count, rnd_scene_triangle_count(gpu));
        return NULL;
    }
    pvs_context* ctx = calloc(1, sizeof *ctx);
    if (!ctx) {
        snprintf(err, err_size, "pvs: out of memory");
        return NULL;
    }
    ctx->rnd = rnd;
    ctx->gpu = gpu;
    ctx->width = d.width ? d.width : PVS_DEFAULT_WIDTH;
    ctx->height = d.height ? d.height : PVS_DEFAULT_HEIGHT;
    ctx->k = d.k ? d.k : PVS_DEFAULT_K;
    bool cpu = rnd->props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    pvs_kbuffer_layout layout = d.kbuffer_layout ? d.kbuffer_layout : cpu ? PVS_KBUFFER_FLAT : PVS_KBUFFER_PAGED;
    assert(layout == PVS_KBUFFER_FLAT || layout == PVS_KBUFFER_PAGED);
    ctx->kb_paged = layout == PVS_KBUFFER_PAGED;
    ctx->k_lists = d.k_deep > ctx->k ? d.k_deep : ctx->k;
    ctx->k_regions = d.k_regions > ctx->k_lists ? d.k_regions : ctx->k_lists;
    ctx->k_store = ctx->k_regions;
    ctx->grid = tile_grid(ctx, d.max_tile_pixels);
    size_pool(ctx, &d);
    ctx->explain = d.explain;
    ctx->coop_sort_min = d.coop_sort_min ? d.coop_sort_min : cpu ? PVS_NEVER_COOP : PVS_DEFAULT_COOP_SORT_MIN;
    ctx->coop_width = coop_width(rnd);
    ctx->near_m = d.near_m > 0.0f ? d.near_m : PVS_DEFAULT_NEAR;
    ctx->max_layers = d.max_layers ? d.max_layers : cpu ? PVS_LAYERS_UNMERGED : PVS_LAYERS_DEFAULT_MAX;
    ctx->triangle_count = scene->triangle_count;
    ctx->max_proxies = max_proxies;
    scn_scene statics = *scene; /* the octree holds the static triangles only */
    statics.triangle_count -= scene->dynamic_triangle_count;
    const VkDescriptorPoolSize pool_sizes[2] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, TV_PVS_BINDINGS - 2},
                                                {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 2}};
    pvs_octree_desc od = {.max_triangles_per_leaf = d.octree_cap, .max_depth = d.octree_depth};
    ctx->proxy_always = malloc(sizeof(bool) * max_proxies);
    if (!ctx->proxy_always) {
        snprintf(err, err_size, "pvs: out of memory for %u proxies", max_proxies);
        pvs_destroy(ctx);
        return NULL;
    }
    bool ok = pvs_octree_build(&od, &statics, &ctx->octree, err, err_size) &&
              rnd_stream_create(rnd, &ctx->stream, err, err_size) && pvs_pipelines_create(ctx, err, err_size) &&
              create_depth_bound(ctx, scene, err, err_size) && create_fixed_buffers(ctx, err, err_size) &&
              rnd_descriptor_set_create(rnd, ctx->set_layout, pool_sizes, 2, &ctx->pool, &ctx->set, err, err_size) &&
              pvs_reserve(ctx, 1, 1, err, err_size) && upload_adjacency(ctx, scene, err, err_size);
    if (!ok) {
        pvs_destroy(ctx);
        return NULL;
    }
    tv_log(TV_LOG_INFO, "pvs: %s: %u octree leaves, %ux%u in %u tiles of %ux%u, k = %u (lists store %u), %s k-buffers of %u pages (%.1f MiB)",
           scene->name, ctx->octree.leaf_count, ctx->width, ctx->height, pvs_tile_count(&ctx->grid),
           ctx->grid.tile_width, ctx->grid.tile_height, ctx->k, ctx->k_store, ctx->kb_paged ? "paged" : "flat", ctx->pool_pages,
           (double)kbuffer_bytes(ctx) / (1024.0 * 1024.0));
    return ctx;
}

void pvs_destroy(pvs_context* ctx)
{
    if (!ctx)
        return;
    rnd_context* r = ctx->rnd;
    vkDeviceWaitIdle(r->device);
    pvs_pipelines_destroy(ctx);
    if (ctx->pool)
        vkDestroyDescriptorPool(r->device, ctx->pool, NULL);
    if (ctx->timestamps)
        vkDestroyQueryPool(r->device, ctx->timestamps, NULL);
    for (uint32_t i = 0; i < TV_PVS_BINDINGS; i++)
        rnd_buffer_destroy(r, &ctx->buffers[i]);
    for (int i = 0; i < 2; i++) {
        rnd_image_destroy(r, &ctx->vis_ids[i]);
        rnd_image_destroy(r, &ctx->vis_depth[i]);
    }
    rnd_stream_destroy(r, &ctx->stream);
    pvs_layers_free(&ctx->layers);
    pvs_proxy_sort_free(&ctx->proxy_sort);
    pvs_octree_free(&ctx->octree);
    free(ctx->result);
    free(ctx->reasons);
    free(ctx->per_layer);
    free(ctx->proxy_always);
    free(ctx->tri_corners);
    free(ctx->adjacency);
    free(ctx->masked);
    pvs_depth_bound_free(&ctx->depth_bound);
    free(ctx);
}
