/* pvs.h - the trim-region PVS (paper sections 3-5): the public API.
 *
 * pvs_create builds everything that does not depend on the viewcell (welding
 * and triangle adjacency, the octree, GPU buffers and pipelines); pvs_compute
 * then runs, per request, P0 on the CPU (octree layers seen from the apex v*)
 * and P1-P4 on the GPU (docs/pvs-gpu-passes.md), and returns the
 * sorted unique ids of every triangle potentially visible from the
 * double-cone viewcell.
 *
 * Threading: a context records into its own rnd_stream and renders into its
 * own images, so pvs_compute may run on a worker thread while other threads
 * call rnd_draw with the same rnd_context and rnd_gpu_scene. One context must
 * not be used by two threads at once.
 */
#ifndef TRIMVR_PVS_H
#define TRIMVR_PVS_H

#include "pvs_viewcell.h"
#include "render.h"
#include "scene.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pvs_context pvs_context;

/* Where P2 finds page j of a pixel's list (docs/pvs-gpu-passes.md, "k-buffer
 * pages"). FLAT: at a fixed place, k slots per list and pixel (no
 * allocation; the tile is what one buffer holds of those). PAGED: chains of
 * pages taken from a pool as lists fill (memory follows use; the pool grows
 * and the computation runs again when it runs out), which costs P2 its
 * atomics, twice P2's time on lavapipe. */
typedef enum pvs_kbuffer_layout {
    PVS_KBUFFER_DEFAULT = 0, /* PAGED on a GPU, FLAT on a CPU device */
    PVS_KBUFFER_FLAT = 1,
    PVS_KBUFFER_PAGED = 2,
} pvs_kbuffer_layout;

/* The largest k, k_deep and k_regions: the shaders' list capacity (TV_K_* in shaders/pvs_shared.h). */
#define PVS_K_MAX 32u

typedef struct pvs_desc {
    uint32_t width, height;          /* PVS resolution; 0: 512 x 512 */
    uint32_t k;                      /* k-buffer slots per pixel and kind, 1..PVS_K_MAX; 0: 16 */
    uint32_t k_deep;                 /* entries stored per list, k..PVS_K_MAX (below k: k): a pixel with a front
                                        or back list longer than k that fits hides to its umbrae's footprints, not as overflow
                                        (docs/trim-regions.md, "Overflow policy") */
    uint32_t k_regions;              /* entries the region list stores, k_deep..PVS_K_MAX (below: k_deep): one
                                        longer than k alone resolves with all of them, umbrae included, not as
                                        overflow (docs/journal/2026-12-03-regovf.md) */
    pvs_kbuffer_layout kbuffer_layout; /* 0: PAGED on a GPU, FLAT on a CPU device */
    uint32_t kbuffer_pages;          /* PAGED: k-buffer pool's first size, in pages of TV_PVS_PAGE entries (it
                                        grows when a computation runs out, and the context keeps the
                                        grown size); 0: 2 per pixel of a tile */
    uint32_t max_kbuffer_pages;      /* PAGED: most pages the pool grows to; 0: what maxStorageBufferRange
                                        holds. Past it, entries are lost as overflow (conservative) */
    uint32_t octree_cap;             /* triangles per octree leaf; 0: PVS_OCTREE_DEFAULT_CAP */
    uint32_t octree_depth;           /* 0: PVS_OCTREE_DEFAULT_DEPTH */
    uint32_t max_layers;             /* consecutive octree layers are merged into at most this many
                                        (docs/trim-regions.md, "Merging layers"); 0: 14 on a GPU,
                                        the strict order on a CPU device (there merging buys no time
                                        and costs PVS size); UINT32_MAX: the strict order */
    float near_m;                    /* near plane distance from v*; 0: 0.01 */
    uint32_t coop_sort_min;          /* P3 sorts trim sequences of at least this many entries with a
                                        subgroup-wide workgroup per pixel (bitonic), shorter ones per
                                        thread; 0: 8 (the paper's N) on a GPU, never on a CPU device;
                                        UINT32_MAX: never */
    uint32_t max_tile_pixels;        /* the image is computed in tiles of at most this many pixels
                                        (pvs/tiles.h; per-pixel memory follows the tile); 0: 1024 x 1024
                                        (FLAT: 512 x 512);
                                        lowered to what maxStorageBufferRange allows */
    uint32_t max_proxies;            /* most proxies one pvs_compute_dynamic takes; 0: 1024 */
    bool explain;                    /* record which rules output each triangle (pvs_result.reasons);
                                        costs an atomic per output instead of a store */
} pvs_desc;

/* The apex may lie at most pvs_max_apex_offset(near_m) behind v0, that is
 * Δ <= that x tan α. The PVS depth buffer (D32_SFLOAT, standard Z, near
 * plane near_m) resolves depth steps of about 2^-24 d^2 / near_m at distance
 * d from the apex; around the viewcell (d ~ z) the steps must stay within
 * PVS_MAX_DEPTH_STEP_M or the depth tests of the passes merge distinct
 * surfaces and the PVS loses visible triangles (builtin:unit, PVS 512x512,
 * near 0.01 m: conservative at z = 30 m, a 5.4 mm step; misses at z = 40 m,
 * 9.5 mm; nothing at all at z = 1e5 m, where every depth rounds to the far
 * plane's). With the default near plane the limit is z <= 31.7 m. */
#define PVS_MAX_DEPTH_STEP_M 0.006f
#define PVS_DEFAULT_NEAR 0.01f /* pvs_desc.near_m's default */
/* near_m 0: PVS_DEFAULT_NEAR. */
float pvs_max_apex_offset(float near_m);

/* One layer's share of a computation (docs/pvs-gpu-passes.md, "Cost per
 * phase"). Pixel figures are summed over the image's tiles. */
typedef struct pvs_layer_stats {
    uint32_t triangles;          /* in the layer (P1's input) */
    uint32_t fronts, backs;      /* triangles P1 passed to P2's draws (inside the frustum) */
    uint32_t silhouettes;        /* trim regions: one quad each, for up to 3 trim depths and an umbra */
    uint64_t active_pixels;      /* pixels P3 resolved */
    uint64_t sequence_entries;   /* trim-sequence entries at those pixels (P3's sort input) */
    uint64_t overflow_pixels;    /* of those, resolved by the overflow policy */
    uint64_t kbuffer_bytes_used; /* k-buffer pages P2 took, in bytes (the most of one tile) */
    double ms[3];                /* P1, P2, P3 (spill draws included): GPU timestamps summed over tiles */
} pvs_layer_stats;

typedef struct pvs_stats {
    double ms[5];                 /* P0..P4: P0, P4 CPU wall clock; P1-P3 GPU timestamps summed
                                     over layers (wall clock of the whole submission when the
                                     queue has no timestamps, reported in ms[2]) */
    double total_ms;              /* wall clock of pvs_compute */
    uint32_t layers;
    uint32_t layer_triangles;     /* triangles in all layers (frustum-culled leaves dropped) */
    uint32_t silhouettes;         /* trim regions emitted over all layers */
    uint64_t active_pixels;       /* active pixels resolved, summed over layers */
    double mean_sequence;         /* mean trim-sequence length (k-buffer entries) per resolve */
    uint64_t kbuffer_bytes;       /* k-buffers allocated: the page pool with its links, and the list
                                     heads of one tile */
    uint64_t kbuffer_bytes_used;  /* the pages P2 took in the fullest layer of one tile, and the heads */
    uint64_t kbuffer_lost;        /* pages P2 asked for past the pool at its largest, in one layer of
                                     one tile: their entries were lost, as overflow (0: none) */
    uint32_t kbuffer_regrows;     /* times this computation ran out of pages, grew the pool and
                                     started again */
    uint64_t overflow_pixels;     /* pixel resolves handled by the overflow policy */
    uint64_t overflow_fronts;     /* front fragments that found their k-buffer full */
    uint64_t coop_pixels;         /* pixel resolves whose sequences a workgroup sorted */
    uint64_t loop_budget_pixels;  /* pixel resolves of P3 that ran out of llvmpipe's loop budget
                                     (shaders/pvs_common.glsl): their results are unreliable, and
                                     pvs_compute logs a warning. 0 on other devices */
    uint64_t idle_resolves;       /* pixel resolves with trims only at a pixel they cannot change
                                     (pvs_region_activates in resolve.h): 0 unless P2 errs */
    uint32_t tiles;               /* tiles the image was computed in (pvs_desc.max_tile_pixels) */
    uint32_t proxies;             /* proxies given to pvs_compute_dynamic */
    uint32_t proxies_output;      /* of those, the ones whose ids joined the result */
    uint32_t proxies_always;      /* of those, output without drawing: the box meets the viewcell's
                                     bounding sphere or leaves the octree's root cube */
    const pvs_layer_stats* per_layer; /* `layers` entries, owned by the context like pvs_result.ids */
} pvs_stats;

typedef struct pvs_result {
    /* Sorted, unique triangle ids. Owned by the context: valid until the next
     * pvs_compute or pvs_destroy on it (copy them to keep them longer). */
    const uint32_t* ids;
    /* pvs_desc.explain only (else NULL): per id, the OR of the TV_REASON_*
     * bits (shaders/pvs_shared.h) of the rules that output it; owned alike. */
    const uint32_t* reasons;
    uint32_t count;
    pvs_stats stats;
} pvs_result;

/* Builds the viewcell-independent state for `scene` (the same scene `gpu`
 * was uploaded from; neither is referenced for longer than the context
 * lives, and `scene` not after the call). desc may be NULL (all defaults).
 * Fails (NULL, one-line reason in err) on an invalid desc, when a per-pixel
 * buffer of the smallest tile exceeds maxStorageBufferRange, or on a
 * Vulkan/memory failure. */
pvs_context* pvs_create(rnd_context* rnd, const scn_scene* scene, const rnd_gpu_scene* gpu, const pvs_desc* desc,
                        char* err, size_t err_size);

/* Waits for the context's GPU work and releases it. NULL is a no-op. */
void pvs_destroy(pvs_context* ctx);

/* Computes the PVS of `vc` into `out` (see pvs_result for ownership). Blocks
 * until the GPU is done. Returns false with a one-line reason in err on an
 * invalid viewcell (non-finite values, zero forward, up parallel to forward,
 * fov outside (0, 180), far_m <= 0, an apex offset z = Δ / tan α beyond
 * pvs_max_apex_offset) or a Vulkan failure. The scene's dynamic triangles
 * (scn_scene.dynamic_triangle_count) are never in it: pvs_compute_dynamic
 * adds them through proxies. */
bool pvs_compute(pvs_context* ctx, const pvs_viewcell* vc, pvs_result* out, char* err, size_t err_size);

/* A moving object over a PVS's use window: a box holding it over the whole
 * window. A proxy never occludes; when any part of its box may be visible
 * from the viewcell, ids [first_id, first_id+id_count) join the result. */
typedef struct pvs_proxy {
    float box_min[3], box_max[3];
    uint32_t first_id, id_count;
} pvs_proxy;

/* pvs_compute with moving objects: each proxy's box is sorted into the
 * octree leaves it touches for this request (the paper's lazy sorting,
 * section 5) and drawn as 12 see-through triangles (docs/trim-regions.md,
 * "See-through triangles and proxies"). pvs_compute(...) is
 * pvs_compute_dynamic(..., NULL, 0, ...). Returns false with a one-line
 * reason in err, besides pvs_compute's cases, when proxy_count exceeds
 * pvs_desc.max_proxies, a box is not finite or has min > max, or an id range
 * leaves the scene's triangles. */
bool pvs_compute_dynamic(pvs_context* ctx, const pvs_viewcell* vc, const pvs_proxy* proxies, uint32_t proxy_count,
                         pvs_result* out, char* err, size_t err_size);

/* The frustum pvs_compute uses, as an rnd_camera at the apex v* (aspect of
 * the PVS resolution): for tests and visualisation. */
rnd_camera pvs_apex_camera(const pvs_context* ctx, const pvs_viewcell* vc);

#ifdef __cplusplus
}
#endif

#endif
