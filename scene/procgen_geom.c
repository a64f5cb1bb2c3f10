/* procgen_geom.c - random floats and the quad/box emitters of the built-in scenes. */
#include "procgen.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>

float scn_rng_range(tv_rng* rng, float lo, float hi)
{
    return lo + (hi - lo) * (float)(tv_rng_u32(rng) >> 8) * (1.0f / 16777216.0f);
}

uint32_t scn_gen_material(scn_builder* b, const char* name, int32_t texture, float r, float g, float bl,
                          bool double_sided)
{
    scn_material m = { .base_color = { r, g, bl, 1.0f }, .texture = texture, .alpha_mode = SCN_ALPHA_OPAQUE,
                       .alpha_cutoff = 0.5f, .double_sided = double_sided };
    snprintf(m.name, sizeof m.name, "%s", name);
    return scn_builder_material(b, &m);
}

uint32_t scn_gen_cells(float length, float max_cell)
{
    if (max_cell <= 0.0f)
        return 1;
    float cells = ceilf(length / max_cell - 1e-4f);
    return cells < 1.0f ? 1u : (uint32_t)cells;
}

/* Box mapping: project on the plane of the normal's dominant axis. */
static void _scn_box_uv(const float p[3], const float n[3], float uv[2])
{
    float ax = fabsf(n[0]), ay = fabsf(n[1]), az = fabsf(n[2]);
    float s = 1.0f / SCN_GEN_UV_METRES;
    if (ax >= ay && ax >= az) {
        uv[0] = p[2] * s, uv[1] = -p[1] * s;
    } else if (ay >= az) {
        uv[0] = p[0] * s, uv[1] = p[2] * s;
    } else {
        uv[0] = p[0] * s, uv[1] = -p[1] * s;
    }
}

void scn_gen_quad(scn_builder* b, const float origin[3], const float u[3], const float v[3], uint32_t cells_u,
                  uint32_t cells_v, uint32_t material)
{
    assert(cells_u > 0 && cells_v > 0);
    uint32_t nu = cells_u + 1, nv = cells_v + 1;
    if (b->count_only) {
        b->vertex_total += (uint64_t)nu * nv;
        b->triangle_total += 2ull * cells_u * cells_v;
        return;
    }
    float n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
    float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    assert(len > 0.0f);
    uint32_t first = scn_builder_vertices(b, nu * nv);
    if (first == UINT32_MAX)
        return;
    scn_scene* s = b->scene;
    for (uint32_t j = 0; j < nv; j++)
        for (uint32_t i = 0; i < nu; i++) {
            size_t vi = (size_t)first + (size_t)j * nu + i;
            float fs = (float)i / (float)cells_u, ft = (float)j / (float)cells_v;
            float* p = s->positions + 3 * vi;
            for (int k = 0; k < 3; k++) {
                p[k] = origin[k] + fs * u[k] + ft * v[k];
                s->normals[3 * vi + k] = n[k] / len;
            }
            _scn_box_uv(p, n, s->uvs + 2 * vi);
        }
    for (uint32_t j = 0; j < cells_v; j++)
        for (uint32_t i = 0; i < cells_u; i++) {
            uint32_t a = first + j * nu + i;
            scn_builder_triangle(b, a, a + 1, a + nu + 1, material);
            scn_builder_triangle(b, a, a + nu + 1, a + nu, material);
        }
}

void scn_gen_box(scn_builder* b, const float lo[3], const float hi[3], unsigned faces, float max_cell,
                 uint32_t material)
{
    assert(lo[0] < hi[0] && lo[1] < hi[1] && lo[2] < hi[2]);
    float d[3] = { hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] };
    for (int axis = 0; axis < 3; axis++) {
        int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3; /* e[a1] x e[a2] = +e[axis] */
        for (int side = 0; side < 2; side++) {
            if (!(faces & (1u << (2 * axis + side))))
                continue;
            float origin[3] = { lo[0], lo[1], lo[2] }, u[3] = { 0, 0, 0 }, v[3] = { 0, 0, 0 };
            if (side == 1) { /* +axis face: u = a1, v = a2 */
                origin[axis] = hi[axis];
                u[a1] = d[a1];
                v[a2] = d[a2];
                scn_gen_quad(b, origin, u, v, scn_gen_cells(d[a1], max_cell), scn_gen_cells(d[a2], max_cell), material);
            } else { /* -axis face: swapped edges flip the facing */
                u[a2] = d[a2];
                v[a1] = d[a1];
                scn_gen_quad(b, origin, u, v, scn_gen_cells(d[a2], max_cell), scn_gen_cells(d[a1], max_cell), material);
            }
        }
    }
}
