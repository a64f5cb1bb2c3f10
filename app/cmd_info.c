/* trimvr info: load a scene and print what the PVS and renderer will see:
 * triangle/vertex/material counts, bounds, and the edge classes that decide
 * silhouettes (manifold, border, non-manifold). */
#include "app_scene.h"
#include "args.h"
#include "clock.h"
#include "commands.h"
#include "auto_place.h"
#include "weld.h"
#include "log.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static bool print_edge_classes(const scn_scene* sc)
{
    uint32_t* remap = malloc(sizeof(uint32_t) * (sc->vertex_count ? sc->vertex_count : 1));
    uint32_t* adj = malloc(sizeof(uint32_t) * 3 * (sc->triangle_count ? sc->triangle_count : 1));
    if (!remap || !adj) {
        free(remap);
        free(adj);
        tv_log(TV_LOG_ERROR, "out of memory");
        return false;
    }
    double t0 = tv_now_ms();
    size_t unique = scn_weld_positions(remap, sc->positions, sc->vertex_count);
    scn_build_adjacency(adj, sc->indices, sc->triangle_count, remap);
    double ms = tv_now_ms() - t0;
    size_t manifold = 0, border = 0, nonmanifold = 0;
    for (size_t i = 0; i < 3 * (size_t)sc->triangle_count; i++) {
        if (adj[i] == SCN_EDGE_BORDER)
            border++;
        else if (adj[i] == SCN_EDGE_NONMANIFOLD)
            nonmanifold++;
        else
            manifold++;
    }
    printf("welded positions  %zu of %u vertices\n", unique, sc->vertex_count);
    printf("triangle edges    %zu manifold, %zu border, %zu non-manifold (weld + adjacency %.1f ms)\n",
           manifold, border, nonmanifold, ms);
    free(remap);
    free(adj);
    return true;
}

/* The viewcells trimvr bench places in a scene without a bundled walk
 * (app/auto_place.h), then the same as one --pos list to reuse. */
static bool print_floor_points(const char* spec, const scn_scene* sc, int max_points)
{
    char err[512];
    const char* rule = "";
    float* pos = malloc((size_t)max_points * 3 * sizeof *pos);
    float* dir = malloc((size_t)max_points * 3 * sizeof *dir);
    int n = pos && dir ? tv_auto_viewcells(spec, sc, max_points, pos, dir, &rule, err, sizeof err) : -1;
    if (n < 0)
        tv_log(TV_LOG_ERROR, "%s", pos && dir ? err : "out of memory for floor points");
    for (int i = 0; i < n; i++)
        printf("floor point %-4d  eye %.4f,%.4f,%.4f  facing %.4f,%.4f,%.4f  (%s)\n", i, pos[3 * i], pos[3 * i + 1],
               pos[3 * i + 2], dir[3 * i], dir[3 * i + 1], dir[3 * i + 2], rule);
    for (int i = 0; i < n; i++)
        printf("%s%.2f,%.2f,%.2f%s", i ? ";" : "--pos '", pos[3 * i], pos[3 * i + 1], pos[3 * i + 2],
               i + 1 < n ? "" : "'\n");
    free(pos);
    free(dir);
    return n >= 0;
}

int tv_cmd_info(int argc, char** argv)
{
    const char* spec = NULL;
    bool edges = false;
    int floor_points = 0;
    const tv_arg args[] = {
        {"scene", TV_ARG_STRING, &spec, "S", "scene: .gltf/.glb, builtin:NAME, sponza or oa:LEVEL (required)"},
        {"edges", TV_ARG_FLAG, &edges, NULL, "also weld vertices and classify triangle edges"},
        {"floor-points", TV_ARG_INT, &floor_points, "N",
         "print up to N eye positions above open floor, trimvr bench's viewcells (oa: levels: 1.4 m, by their "
         "vis data; other scenes: the automatic rule of docs/scenes.md) and a --pos list"},
    };
    tv_args_result r = tv_args_parse("info", "Loads a scene (no GPU needed) and prints its statistics.", args,
                                     (int)(sizeof args / sizeof args[0]), argc, argv);
    if (r != TV_ARGS_OK)
        return r == TV_ARGS_HELP ? 0 : 2;
    if (!spec) {
        tv_log(TV_LOG_ERROR, "--scene is required (see trimvr info --help)");
        return 2;
    }
    if (floor_points < 0) {
        tv_log(TV_LOG_ERROR, "--floor-points: expected a count >= 0, got %d", floor_points);
        return 2;
    }
    char resolved[4096], err[512];
    if (!tv_resolve_scene_spec(spec, resolved, sizeof resolved)) {
        tv_log(TV_LOG_ERROR, "scene name too long: %s", spec);
        return 2;
    }
    scn_scene sc;
    double t0 = tv_now_ms();
    if (!scn_load(resolved, &sc, err, sizeof err)) {
        tv_log(TV_LOG_ERROR, "%s", err);
        return 1;
    }
    double ms = tv_now_ms() - t0;
    printf("scene             %s\n", sc.name);
    printf("triangles         %u\n", sc.triangle_count);
    printf("vertices          %u\n", sc.vertex_count);
    printf("materials         %u (%u textures)\n", sc.material_count, sc.texture_count);
    printf("bounds            [%.2f %.2f %.2f] .. [%.2f %.2f %.2f] m\n", sc.bounds_min[0], sc.bounds_min[1],
           sc.bounds_min[2], sc.bounds_max[0], sc.bounds_max[1], sc.bounds_max[2]);
    printf("load time         %.1f ms\n", ms);
    bool ok = !edges || print_edge_classes(&sc);
    if (ok && floor_points > 0)
        ok = print_floor_points(spec, &sc, floor_points);
    scn_scene_free(&sc);
    return ok ? 0 : 1;
}
