/* Loads every scene under $TRIMVR_SHARED/scenes; skips (77) without it. */
#define _DEFAULT_SOURCE /* strdup */
#include "clock.h"
#include "scene.h"
#include "test.h"
#include "weld.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static const char* shared;

/* Triangle counts from ../shared/scenes/README.md. */
static const struct { const char* path; uint32_t readme_tris; } scenes[] = {
    { "scenes/sponza_lod4/sponza_s_lod4.glb", 187364 },
    { "scenes/openarena/oasago2/oasago2.gltf", 41167 },
    { "scenes/openarena/oa_dm5/oa_dm5.gltf", 40542 },
    { "scenes/openarena/czest2ctf/czest2ctf.gltf", 37156 },
    { "scenes/openarena/ctf_inyard/ctf_inyard.gltf", 29348 },
    { "scenes/openarena/oacmpdm9/oacmpdm9.gltf", 29941 },
    { "scenes/openarena/pul1ctf/pul1ctf.gltf", 28004 },
};

static void check_normals(const scn_scene* s)
{
    uint32_t bad = 0;
    for (uint32_t v = 0; v < s->vertex_count; v++) {
        const float* n = s->normals + 3 * (size_t)v;
        if (fabs(sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1.0) > 1e-4)
            bad++;
    }
    TV_CHECK(bad == 0);
}

static void test_all_scenes(void)
{
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++) {
        char path[1024], err[1024];
        snprintf(path, sizeof path, "%s/%s", shared, scenes[i].path);
        scn_scene s;
        double t0 = tv_now_ms();
        bool ok = scn_load(path, &s, err, sizeof err);
        double load_ms = tv_now_ms() - t0;
        TV_CHECK(ok);
        if (!ok) {
            fprintf(stderr, "%s\n", err);
            continue;
        }
        uint32_t sky = 0;
        for (uint32_t m = 0; m < s.material_count; m++)
            sky += strstr(s.materials[m].name, "sky") != NULL;
        uint32_t* remap = malloc(sizeof(uint32_t) * s.vertex_count);
        uint32_t* adj = malloc(sizeof(uint32_t) * 3 * (size_t)s.triangle_count);
        t0 = tv_now_ms();
        size_t unique = scn_weld_positions(remap, s.positions, s.vertex_count);
        scn_build_adjacency(adj, s.indices, s.triangle_count, remap);
        double adj_ms = tv_now_ms() - t0;
        uint32_t border = 0, nonmanifold = 0;
        for (size_t h = 0; h < 3 * (size_t)s.triangle_count; h++)
            border += adj[h] == SCN_EDGE_BORDER, nonmanifold += adj[h] == SCN_EDGE_NONMANIFOLD;
        printf("     %-45s %7u tris (README %7u, %4u degenerate dropped) %7u verts %3u materials (%u sky) load %6.1f ms, "
               "weld+adjacency %5.1f ms (%zu unique positions, %u border, %u non-manifold half-edges)\n",
               scenes[i].path, s.triangle_count, scenes[i].readme_tris,
               s.degenerate_dropped, s.vertex_count, s.material_count, sky, load_ms,
               adj_ms, unique, border, nonmanifold);
        /* the only difference from the file's count is dropped degenerates */
        TV_CHECK(s.triangle_count + s.degenerate_dropped == scenes[i].readme_tris);
        if (i == 0) /* Sponza holds one triangle with a repeated index (90789, 90767, 90767) */
            TV_CHECK(s.triangle_count == 187363 && s.degenerate_dropped == 1);
        check_normals(&s);
        for (uint32_t t = 0; t < s.triangle_count; t++)
            TV_CHECK(s.tri_material[t] < s.material_count);
        free(remap);
        free(adj);
        scn_scene_free(&s);
    }
}

int main(void)
{
    shared = getenv("TRIMVR_SHARED");
    struct stat st;
    char probe[1024];
    snprintf(probe, sizeof probe, "%s/scenes", shared ? shared : "");
    if (!shared || stat(probe, &st) != 0) {
        printf("skip: $TRIMVR_SHARED/scenes not found (set TRIMVR_SHARED to the shared data folder)\n");
        return 77;
    }
    TV_TEST_RUN(test_all_scenes);
    return tv_test_finish();
}
