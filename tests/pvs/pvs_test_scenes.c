#include "pvs_test_scenes.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

float pvs_test_rand(uint32_t* state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *state = x;
    return (float)(x >> 8) / 16777216.0f;
}

static void alloc_scene(scn_scene* out, uint32_t vertices, uint32_t triangles, const char* name)
{
    memset(out, 0, sizeof *out);
    snprintf(out->name, sizeof out->name, "%s", name);
    out->vertex_count = vertices;
    out->triangle_count = triangles;
    out->positions = calloc(3u * vertices + 1, sizeof(float));
    out->indices = calloc(3u * triangles + 1, sizeof(uint32_t));
}

void pvs_test_box_grid(scn_scene* out, uint32_t nx, uint32_t nz, uint32_t s)
{
    uint32_t verts_per_face = (s + 1) * (s + 1), boxes = nx * nz;
    alloc_scene(out, boxes * 6 * verts_per_face, boxes * 12 * s * s, "test:box-grid");
    uint32_t v = 0, t = 0;
    for (uint32_t bx = 0; bx < nx; bx++) {
        for (uint32_t bz = 0; bz < nz; bz++) {
            float origin[3] = {2.0f * (float)bx, 0.0f, 2.0f * (float)bz};
            for (int axis = 0; axis < 3; axis++) {
                for (int side = 0; side < 2; side++) {
                    int u = (axis + 1) % 3, w = (axis + 2) % 3;
                    uint32_t base = v;
                    for (uint32_t i = 0; i <= s; i++) {
                        for (uint32_t j = 0; j <= s; j++) {
                            float* p = out->positions + 3u * v++;
                            p[axis] = origin[axis] + (float)side;
                            p[u] = origin[u] + (float)i / (float)s;
                            p[w] = origin[w] + (float)j / (float)s;
                        }
                    }
                    for (uint32_t i = 0; i < s; i++) {
                        for (uint32_t j = 0; j < s; j++) {
                            uint32_t a = base + i * (s + 1) + j, b = a + (s + 1), c = b + 1, d = a + 1;
                            /* (u, w) is right-handed with +axis: CCW seen from +axis. */
                            uint32_t q[6] = {a, b, c, a, c, d};
                            if (side == 0) {
                                q[1] = c, q[2] = b, q[4] = d, q[5] = c;
                            }
                            memcpy(out->indices + 3u * t, q, sizeof q);
                            t += 2;
                        }
                    }
                }
            }
        }
    }
}

void pvs_test_soup(scn_scene* out, uint32_t count, float extent, float small, uint32_t seed)
{
    alloc_scene(out, 3 * count, count, "test:soup");
    uint32_t rng = seed * 2654435761u + 1u;
    for (uint32_t t = 0; t < count; t++) {
        bool big = t % 16 == 0;
        float c[3], size = big ? 0.5f * extent : small;
        for (int a = 0; a < 3; a++) {
            float r = pvs_test_rand(&rng);
            c[a] = extent * r * r * r; /* clustered towards 0 */
        }
        for (int k = 0; k < 3; k++) {
            for (int a = 0; a < 3; a++) {
                float p = c[a] + size * (pvs_test_rand(&rng) - 0.5f);
                out->positions[9u * t + 3u * (uint32_t)k + (uint32_t)a] = p < 0.0f ? 0.0f : (p > extent ? extent : p);
            }
            out->indices[3u * t + (uint32_t)k] = 3u * t + (uint32_t)k;
        }
    }
}

void pvs_test_scene_free(scn_scene* scene)
{
    free(scene->positions);
    free(scene->indices);
    memset(scene, 0, sizeof *scene);
}
