/* test_pvs_tiled.c - the PVS computed in tiles (pvs_desc.max_tile_pixels,
 * pvs/tiles.h) equals the untiled one triangle for triangle, pixel figures
 * included, while the per-pixel buffers shrink to a tile; the per-layer
 * statistics add up to the totals. */
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

/* One PVS of `spec` from (x, y, z) looking along -z, in tiles of at most
 * max_tile_pixels (0: one tile at this resolution); checks the per-layer
 * figures against the totals. */
static run compute(const char* spec, const float pos[3], uint32_t max_tile_pixels)
{
    char err[512];
    run out = {0};
    scn_scene scene = {0};
    TV_CHECK(scn_load(spec, &scene, err, sizeof err));
    rnd_gpu_scene* gpu = rnd_scene_create(g_rnd, &scene, err, sizeof err);
    pvs_desc d = {.width = PW, .height = PH, .max_tile_pixels = max_tile_pixels};
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
            TV_CHECK(p->sequence_entries >= p->active_pixels || p->active_pixels == 0);
            active += p->active_pixels;
            overflow += p->overflow_pixels;
            regions += p->silhouettes;
            for (int i = 0; i < 3; i++)
                ms[i] += p->ms[i];
        }
        TV_CHECK(active == s->active_pixels && overflow == s->overflow_pixels && regions == s->silhouettes);
        for (int i = 0; i < 3; i++)
            TV_CHECK_NEAR(ms[i], s->ms[1 + i], 1e-6 * (1.0 + s->ms[1 + i]));
        printf("  %s, tiles of <= %u px: %u tiles, %u ids, %u layers, %llu active px, k-buffers %.2f MiB, "
               "used %.3f MiB\n", spec, max_tile_pixels, s->tiles, r.count, s->layers,
               (unsigned long long)s->active_pixels, s->kbuffer_bytes / 1048576.0, s->kbuffer_bytes_used / 1048576.0);
        out.stats.per_layer = NULL; /* freed with the context */
    }
    pvs_destroy(pvs);
    rnd_scene_destroy(g_rnd, gpu);
    scn_scene_free(&scene);
    return out;
}

static void check_tiling(const char* spec, const float pos[3])
{
    /* 7000 px: 3 x 3 tiles of 107 x 60, the last column 106 wide */
    const uint32_t budgets[2] = {7000, PW * 40};
    run whole = compute(spec, pos, 0);
    TV_CHECK(whole.stats.tiles == 1 && whole.count > 0 && whole.stats.active_pixels > 0);
    for (int b = 0; b < 2; b++) {
        run tiled = compute(spec, pos, budgets[b]);
        TV_CHECK(tiled.stats.tiles == (b == 0 ? 9u : 5u));
        TV_CHECK(tiled.count == whole.count && memcmp(tiled.ids, whole.ids, sizeof(uint32_t) * whole.count) == 0);
        TV_CHECK(tiled.stats.active_pixels == whole.stats.active_pixels);
        TV_CHECK(tiled.stats.overflow_pixels == whole.stats.overflow_pixels);
        TV_CHECK(tiled.stats.silhouettes == whole.stats.silhouettes);
        TV_CHECK(tiled.stats.kbuffer_bytes_used == whole.stats.kbuffer_bytes_used);
        TV_CHECK(tiled.stats.kbuffer_bytes * 4 < whole.stats.kbuffer_bytes);
        free(tiled.ids);
    }
    free(whole.ids);
}

static void test_tiled_city(void)
{
    check_tiling("builtin:city?tris=20000", (const float[3]){0.0f, 1.7f, 30.0f});
}

static void test_tiled_interior(void)
{
    check_tiling("builtin:interior", (const float[3]){-6.0f, 1.7f, 6.5f});
}

int main(void)
{
    g_rnd = fx_context();
    TV_TEST_RUN(test_tiled_city);
    TV_TEST_RUN(test_tiled_interior);
    TV_CHECK(rnd_validation_message_count(g_rnd) == 0);
    rnd_destroy(g_rnd);
    return tv_test_finish();
}
