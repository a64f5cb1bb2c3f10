#include "render_fixture.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

rnd_context* fx_context(void)
{
    char err[512];
    rnd_context* ctx = rnd_create(&(rnd_desc){.validation = 1}, err, sizeof err);
    if (!ctx) {
        fprintf(stderr, "rnd_create: %s\n", err);
        exit(1);
    }
    return ctx;
}

void fx_scene_init(scn_scene* s, uint32_t max_quads, uint32_t max_materials)
{
    memset(s, 0, sizeof *s);
    snprintf(s->name, sizeof s->name, "test:quads");
    s->positions = calloc((size_t)max_quads * 12, sizeof(float));
    s->normals = calloc((size_t)max_quads * 12, sizeof(float));
    s->uvs = calloc((size_t)max_quads * 8, sizeof(float));
    s->indices = calloc((size_t)max_quads * 6, sizeof(uint32_t));
    s->tri_material = calloc((size_t)max_quads * 2, sizeof(uint32_t));
    s->materials = calloc(max_materials, sizeof(scn_material));
}

uint32_t fx_material(scn_scene* s, float r, float g, float b, scn_alpha_mode mode, bool double_sided,
                     int32_t texture)
{
    scn_material* m = &s->materials[s->material_count];
    snprintf(m->name, sizeof m->name, "m%u", s->material_count);
    m->base_color[0] = r;
    m->base_color[1] = g;
    m->base_color[2] = b;
    m->base_color[3] = 1.0f;
    m->texture = texture;
    m->alpha_mode = mode;
    m->alpha_cutoff = 0.5f;
    m->double_sided = double_sided;
    return s->material_count++;
}

uint32_t fx_quad(scn_scene* s, const float c[4][3], uint32_t material)
{
    static const float uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    float e1[3], e2[3], n[3];
    for (int i = 0; i < 3; i++) {
        e1[i] = c[1][i] - c[0][i];
        e2[i] = c[2][i] - c[0][i];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    uint32_t v0 = s->vertex_count;
    for (int k = 0; k < 4; k++) {
        for (int i = 0; i < 3; i++) {
            s->positions[3 * (v0 + k) + i] = c[k][i];
            s->normals[3 * (v0 + k) + i] = n[i] / len;
        }
        s->uvs[2 * (v0 + k)] = uv[k][0];
        s->uvs[2 * (v0 + k) + 1] = uv[k][1];
    }
    s->vertex_count += 4;
    const uint32_t corners[6] = {0, 1, 2, 0, 2, 3};
    uint32_t t0 = s->triangle_count;
    for (int i = 0; i < 6; i++)
        s->indices[3 * t0 + i] = v0 + corners[i];
    s->tri_material[t0] = s->tri_material[t0 + 1] = material;
    s->triangle_count += 2;
    return t0;
}

uint32_t fx_quad_z(scn_scene* s, float x0, float y0, float x1, float y1, float z, uint32_t material)
{
    const float c[4][3] = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
    return fx_quad(s, c, material);
}

rnd_camera fx_camera(void)
{
    return (rnd_camera){.orientation = {0, 0, 0, 1}, .fov_y_deg = 60.0f, .near_m = 0.1f, .far_m = 100.0f};
}

int fx_srgb8(float x)
{
    float e = x <= 0.0031308f ? 12.92f * x : 1.055f * powf(x, 1.0f / 2.4f) - 0.055f;
    return (int)lroundf(e * 255.0f);
}
