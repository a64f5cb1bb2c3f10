/* scene.c - scn_load dispatch and scene lifetime. */
#define _DEFAULT_SOURCE /* strcasecmp */
#include "scene.h"

#include "gltf_loader.h"
#include "procedural.h"

#include <assert.h>
#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

static bool _scn_has_suffix(const char* s, const char* suffix)
{
    size_t n = strlen(s), m = strlen(suffix);
    return n >= m && strcasecmp(s + n - m, suffix) == 0;
}

bool scn_load(const char* spec, scn_scene* out, char* err, size_t err_size)
{
    assert(spec && out && err && err_size > 0);
    memset(out, 0, sizeof *out);
    err[0] = '\0';
    if (strncmp(spec, "builtin:", 8) == 0)
        return scn_load_builtin(spec, out, err, err_size);
    if (_scn_has_suffix(spec, ".gltf") || _scn_has_suffix(spec, ".glb"))
        return scn_load_gltf(spec, out, err, err_size);
    snprintf(err, err_size, "%s: unknown scene type (expected .gltf, .glb or builtin:<name>)", spec);
    return false;
}

void scn_scene_free(scn_scene* scene)
{
    if (!scene)
        return;
    free(scene->positions);
    free(scene->normals);
    free(scene->uvs);
    free(scene->indices);
    free(scene->tri_material);
    free(scene->materials);
    for (uint32_t i = 0; i < scene->texture_count; i++)
        free(scene->textures[i].rgba8);
    free(scene->textures);
    for (uint32_t i = 0; i < scene->mover_count; i++)
        scn_mover_free(&scene->movers[i]);
    free(scene->movers);
    memset(scene, 0, sizeof *scene);
}

void scn_scene_update_bounds(scn_scene* scene)
{
    assert(scene);
    for (int k = 0; k < 3; k++) {
        scene->bounds_min[k] = scene->vertex_count ? FLT_MAX : 0.0f;
        scene->bounds_max[k] = scene->vertex_count ? -FLT_MAX : 0.0f;
    }
    for (uint32_t v = 0; v < scene->vertex_count; v++)
        for (int k = 0; k < 3; k++) {
            float p = scene->positions[3 * (size_t)v + k];
            if (p < scene->bounds_min[k])
                scene->bounds_min[k] = p;
            if (p > scene->bounds_max[k])
                scene->bounds_max[k] = p;
        }
}

void scn_scene_summary(const scn_scene* scene, char* buf, size_t buf_size)
{
    assert(scene && buf && buf_size > 0);
    char movers[64] = "";
    if (scene->mover_count)
        snprintf(movers, sizeof movers, " (%u moving in %u movers)", scene->dynamic_triangle_count, scene->mover_count);
    snprintf(buf, buf_size, "%s: %u triangles%s, %u vertices, %u materials, %u textures, bounds (%.2f %.2f %.2f)-(%.2f %.2f %.2f)",
             scene->name, scene->triangle_count, movers, scene->vertex_count, scene->material_count,
             scene->texture_count, scene->bounds_min[0], scene->bounds_min[1], scene->bounds_min[2],
             scene->bounds_max[0], scene->bounds_max[1], scene->bounds_max[2]);
}
