/* test_pvs_tiled.c - the PVS computed in tiles (pvs_desc.max_tile_pixels,
 * pvs/tiles.h) equals the untiled one triangle for triangle, pixel figures
 * included, while the per-pixel buffers shrink to a tile; the per-layer
 * statistics add up to the totals, in both k-buffer layouts, which give the
 * same ids. The paged layout's pool: a pool too small grows and the
 * computation runs again, to the same ids; one that may not grow loses
 * entries, which the overflow policy covers (no id is lost). */
#include "pvs.h"
#include "render_fixture.h"
#include "test.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PW 320u
#define PH 180u

static rnd_context* g_rnd;

typedef struct run {
    uint32_t* ids;
    uint32_t count;
    pvs_stats stats;
} run;

/* One PVS of `spec` from (x, y, z) looking along -z with `d` (its size
 * set here; max_tile_pixels 0: one tile at this resolution); checks the
 * per-layer figures against the totals. */
static run compute_desc(const char* spec, const float pos[3], pvs_desc d)
{
    char err[512];
    run out = {0};
    scn_scene scene = {0};
    TV_CHECK(scn_load(spec, &scene, err, sizeof err));
    rnd_gpu_scene* gpu = rnd_scene_create(g_rnd, &scene, err, sizeof err);
    d.width = PW;
    d.height = PH;
    pvs_context* pvs = gpu ? pvs_create(g_rnd, &scene, gpu, &d, err, sizeof err) : NULL;
    pvs_viewcell vc = {.v0 = {pos[0], pos[1], pos[2]}, .forward = {0, 0, -1}, .up = {0, 1, 0}, .delta = 0.1f,
                       .fov_target_deg = 60.0f, .fov_pvs_deg = 90.0f, .far_m = 200.0f};
    pvs_result r;
    if (!pvs || !pvs_compute(pvs, &vc, &r, err, sizeof err)) {
        fprintf(stderr, "%s: %s\n", spec, err);
        TV_CHECK(false);
    } else {
        out.count = r.count;
        out.ids = malloc(sizeof(uint32_t) * (r.count ? r.count : 1));
        memcpy(out.ids, r.ids, sizeof(uint32_t) * r.count);
        out.stats = r.stats;
        const pvs_stats* s = &r.stats;
        uint64_t active = 0, overflow = 0, regions = 0;
        double ms[3] = {0};
        for (uint32_t l = 0; l < s->layers; l++) {
            const pvs_layer_stats* p = &s->per_layer[l];
            TV_CHECK(p->fronts + p->backs <= p->triangles && p->kbuffer_bytes_used <= s->kbuffer_bytes_used);
            /* a pixel whose entries the pool lost resolves an empty sequence */
            TV_CHECK(p->sequence_entries >= p->active_pixels || p->active_pixels == 0 || s->kbuffer_lost > 0);
            active += p->active_pixels;
            overflow += p->overflow_pixels;
            regions += p->silhouettes;
            for (int i = 0; i < 3; i++)
                ms[i] += p->ms[i];
        }
        TV_CHECK(active == s->active_pixels && overflow == s->overflow_pixels && regions == s->silhouettes);
        for (int i = 0; i < 3; i++)
            TV_CHECK_NEAR(ms[i], s->ms[1 + i], 1e-6 * (1.0 + s->ms[1 + i]));
        printf("  %s, %s, tiles of <= %u px, pool %u-%u pages: %u tiles, %u ids, %u layers, %llu active px, "
               "%llu overflowing, k-buffers %.2f MiB, used %.3f MiB, %u regrows, %llu entries lost\n",
               spec, d.kbuffer_layout == PVS_KBUFFER_FLAT ? "flat" : "paged", d.max_tile_pixels, d.kbuffer_pages, d.max_kbuffer_pages, s->tiles, r.count, s->layers,
               (unsigned long long)s->active_pixels, (unsigned long long)s->overflow_pixels,
               s->kbuffer_bytes / 1048576.0, s->kbuffer_bytes_used / 1048576.0, s->kbuffer_regrows,
               (unsigned long long)s->kbuffer_lost);
        out.stats.per_layer = NULL; /* freed with the context */
    }
    pvs_destroy(pvs);
    rnd_scene_destroy(g_rnd, gpu);
    scn_scene_free(&scene);
    return out;
}

static run compute(const char* spec, const float pos[3], pvs_kbuffer_layout layout, uint32_t max_tile_pixels)
{
    return compute_desc(spec, pos, (pvs_desc){.kbuffer_layout = layout, .max_tile_pixels = max_tile_pixels});
}

static bool same_ids(const run* a, const run* b)
{
    return a->count == b->count && memcmp(a->ids, b->ids, sizeof(uint32_t) * a->count) == 0;
}

/* Returns the untiled run (ids to free). */
static run check_tiling(const char* spec, const float pos[3], pvs_kbuffer_layout layout)
{
    /* 7000 px: 3 x 3 tiles of 107 x 60, the last column 106 wide */
    const uint32_t budgets[2] = {7000, PW * 40};
    run whole = compute(spec, pos, layout, 0);
    TV_CHECK(whole.stats.tiles == 1 && whole.count > 0 && whole.stats.active_pixels > 0);
    for (int b = 0; b < 2; b++) {
        run tiled = compute(spec, pos, layout, budgets[b]);
        TV_CHECK(tiled.stats.tiles == (b == 0 ? 9u : 5u));
        TV_CHECK(same_ids(&tiled, &whole));
        TV_CHECK(tiled.stats.active_pixels == whole.stats.active_pixels);
        TV_CHECK(tiled.stats.overflow_pixels == whole.stats.overflow_pixels);
        TV_CHECK(tiled.stats.silhouettes == whole.stats.silhouettes);
        /* paged: the pages of one tile; flat: the entries read, over the image */
        TV_CHECK(layout == PVS_KBUFFER_FLAT ? tiled.stats.kbuffer_bytes_used == whole.stats.kbuffer_bytes_used
                                            : tiled.stats.kbuffer_bytes_used < whole.stats.kbuffer_bytes_used);
        TV_CHECK(tiled.stats.kbuffer_bytes * 4 < whole.stats.kbuffer_bytes);
        TV_CHECK(tiled.stats.kbuffer_lost == 0 && whole.stats.kbuffer_lost == 0);
        free(tiled.ids);
    }
    return whole;
}

/* Both layouts, tiled and not: the flat one is a paged one whose pages are
 * placed in advance, so the lists, and the ids, are the same (k = 16). */
static void check_layouts(const char* spec, const float pos[3])
{
    run flat = check_tiling(spec, pos, PVS_KBUFFER_FLAT);
    run paged = check_tiling(spec, pos, PVS_KBUFFER_PAGED);
    TV_CHECK(flat.count > 0 && same_ids(&flat, &paged));
    TV_CHECK(flat.stats.overflow_pixels == paged.stats.overflow_pixels &&
             flat.stats.active_pixels == paged.stats.active_pixels && paged.stats.kbuffer_lost == 0);
    TV_CHECK(flat.stats.kbuffer_regrows == 0 && flat.stats.kbuffer_bytes > paged.stats.kbuffer_bytes);
    free(flat.ids);
    free(paged.ids);
}

static void test_tiled_city(void)
{
    check_layouts("builtin:city?tris=20000", (const float[3]){0.0f, 1.7f, 30.0f});
}

static void test_tiled_interior(void)
{
    check_layouts("builtin:interior", (const float[3]){-6.0f, 1.7f, 6.5f});
}

/* A pool of 16 pages runs out at once: it grows until the computation
 * fits and gives the ids of a pool that never ran out; a pool capped at 48
 * pages loses entries, which become overflow, and outputs a superset. */
static void test_pool_regrow(void)
{
    const char* spec = "builtin:city?tris=20000";
    const float pos[3] = {0.0f, 1.7f, 30.0f};
    const pvs_kbuffer_layout paged = PVS_KBUFFER_PAGED;
    run big = compute_desc(spec, pos, (pvs_desc){.kbuffer_layout = paged, .kbuffer_pages = 1u << 20});
    run small = compute_desc(spec, pos, (pvs_desc){.kbuffer_layout = paged, .kbuffer_pages = 16});
    TV_CHECK(big.stats.kbuffer_regrows == 0 && big.stats.kbuffer_lost == 0 && big.count > 0);
    TV_CHECK(small.stats.kbuffer_regrows >= 1 && small.stats.kbuffer_lost == 0);
    TV_CHECK(small.stats.kbuffer_bytes < big.stats.kbuffer_bytes);
    TV_CHECK(same_ids(&small, &big));
    TV_CHECK(small.stats.overflow_pixels == big.stats.overflow_pixels &&
             small.stats.active_pixels == big.stats.active_pixels);
    run capped = compute_desc(spec, pos, (pvs_desc){.kbuffer_layout = paged, .kbuffer_pages = 16, .max_kbuffer_pages = 48});
    TV_CHECK(capped.stats.kbuffer_lost > 0 && capped.stats.overflow_pixels > big.stats.overflow_pixels);
    uint32_t missing = 0;
    for (uint32_t i = 0, j = 0; i < big.count; i++) {
        while (j < capped.count && capped.ids[j] < big.ids[i])
            j++;
        missing += j == capped.count || capped.ids[j] != big.ids[i];
    }
    printf("  capped pool: %u ids (%u with room), %u of those missing\n", capped.count, big.count, missing);
    TV_CHECK(missing == 0 && capped.count > big.count);
    free(big.ids);
    free(small.ids);
    free(capped.ids);
}

int main(void)
{
    g_rnd = fx_context();
    TV_TEST_RUN(test_tiled_city);
    TV_TEST_RUN(test_tiled_interior);
    TV_TEST_RUN(test_pool_regrow);
    TV_CHECK(rnd_validation_message_count(g_rnd) == 0);
    rnd_destroy(g_rnd);
    return tv_test_finish();
}
