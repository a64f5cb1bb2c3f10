#include "clearance.h"

#include <assert.h>
#include <cglm/cglm.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

struct tv_clearance {
    const scn_scene* scene;
    float radius, cell, origin[3];
    int dim[3];
    uint32_t* start; /* dim[0]*dim[1]*dim[2] + 1 offsets into tris (CSR) */
    uint32_t* tris;
};

/* Closest point by Voronoi region of the triangle (vertex, edge or face),
 * from the signs of the barycentric-like dot products; degenerate triangles
 * fall into a vertex or edge region, never divide by zero. */
float tv_point_triangle_distance(const float p_[3], const float a_[3], const float b_[3], const float c_[3])
{
    /* cglm takes non-const vectors */
    vec3 p = {p_[0], p_[1], p_[2]}, a = {a_[0], a_[1], a_[2]}, b = {b_[0], b_[1], b_[2]}, c = {c_[0], c_[1], c_[2]};
    vec3 ab, ac, ap, bp, cp, q;
    glm_vec3_sub(b, a, ab);
    glm_vec3_sub(c, a, ac);
    glm_vec3_sub(p, a, ap);
    float d1 = glm_vec3_dot(ab, ap), d2 = glm_vec3_dot(ac, ap);
    float* vertex = NULL;
    float s = 0.0f, t = 0.0f; /* q = a + s ab + t ac */
    if (d1 <= 0.0f && d2 <= 0.0f)
        vertex = a;
    glm_vec3_sub(p, b, bp);
    float d3 = glm_vec3_dot(ab, bp), d4 = glm_vec3_dot(ac, bp);
    if (!vertex && d3 >= 0.0f && d4 <= d3)
        vertex = b;
    glm_vec3_sub(p, c, cp);
    float d5 = glm_vec3_dot(ab, cp), d6 = glm_vec3_dot(ac, cp);
    if (!vertex && d6 >= 0.0f && d5 <= d6)
        vertex = c;
    if (vertex)
        return glm_vec3_distance(p, vertex);
    float vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) {
        s = d1 / (d1 - d3); /* edge ab */
    } else if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) {
        t = d2 / (d2 - d6); /* edge ac */
    } else if (va <= 0.0f && d4 - d3 >= 0.0f && d5 - d6 >= 0.0f) {
        float w = (d4 - d3) / ((d4 - d3) + (d5 - d6)); /* edge bc */
        s = 1.0f - w;
        t = w;
    } else {
        float denom = va + vb + vc;
        s = vb / denom;
        t = vc / denom;
    }
    glm_vec3_copy(a, q);
    glm_vec3_muladds(ab, s, q);
    glm_vec3_muladds(ac, t, q);
    return glm_vec3_distance(p, q);
}

static const float* vertex_of(const scn_scene* s, uint32_t tri, int k)
{
    return s->positions + 3 * (size_t)s->indices[3 * (size_t)tri + (size_t)k];
}

static int clamp_cell(float v, float origin, float cell, int dim)
{
    int i = (int)floorf((v - origin) / cell);
    return i < 0 ? 0 : i >= dim ? dim - 1 : i;
}

/* Cell index range [lo, hi] per axis of a triangle's bounding box. */
static void tri_cells(const tv_clearance* c, uint32_t tri, int lo[3], int hi[3])
{
    for (int a = 0; a < 3; a++) {
        float mn = FLT_MAX, mx = -FLT_MAX;
        for (int k = 0; k < 3; k++) {
            float v = vertex_of(c->scene, tri, k)[a];
            mn = fminf(mn, v);
            mx = fmaxf(mx, v);
        }
        lo[a] = clamp_cell(mn, c->origin[a], c->cell, c->dim[a]);
        hi[a] = clamp_cell(mx, c->origin[a], c->cell, c->dim[a]);
    }
}

static size_t cell_index(const tv_clearance* c, int x, int y, int z)
{
    return ((size_t)z * (size_t)c->dim[1] + (size_t)y) * (size_t)c->dim[0] + (size_t)x;
}

/* Every triangle into each cell its bounding box touches: counts per cell
 * into start[i + 1] when cursor is NULL, else appends at cursor[i]. */
static void bin_triangles(tv_clearance* c, uint32_t* cursor)
{
    for (uint32_t t = 0; t < c->scene->triangle_count; t++) {
        int lo[3], hi[3];
        tri_cells(c, t, lo, hi);
        for (int z = lo[2]; z <= hi[2]; z++)
            for (int y = lo[1]; y <= hi[1]; y++)
                for (int x = lo[0]; x <= hi[0]; x++) {
                    size_t i = cell_index(c, x, y, z);
                    if (cursor)
                        c->tris[cursor[i]++] = t;
                    else
                        c->start[i + 1]++;
                }
    }
}

tv_clearance* tv_clearance_create(const scn_scene* scene, const tv_clearance_desc* desc, char* err,
                                  size_t err_size)
{
    assert(scene);
    if (scene->triangle_count == 0) {
        snprintf(err, err_size, "%s: no triangles", scene->name);
        return NULL;
    }
    float radius = desc && desc->radius_m > 0.0f ? desc->radius_m : 1.0f;
    double max_cells = desc && desc->max_cells ? desc->max_cells : 4u << 20;
    tv_clearance* c = calloc(1, sizeof *c);
    if (!c) {
        snprintf(err, err_size, "out of memory");
        return NULL;
    }
    c->scene = scene;
    c->radius = radius;
    /* Cells at least the radius, so the 27 cells around a point hold every
     * triangle within the radius; bigger when the scene would need too many. */
    double ext[3], volume = 1.0;
    for (int a = 0; a < 3; a++) {
        ext[a] = (double)scene->bounds_max[a] - scene->bounds_min[a] + 2.0 * radius;
        volume *= ext[a];
    }
    c->cell = fmaxf(radius, (float)cbrt(volume / max_cells) * 1.01f);
    size_t cells = 1;
    for (int a = 0; a < 3; a++) {
        c->origin[a] = scene->bounds_min[a] - radius;
        c->dim[a] = (int)ceil(ext[a] / c->cell);
        if (c->dim[a] < 1)
            c->dim[a] = 1;
        cells *= (size_t)c->dim[a];
    }
    c->start = calloc(cells + 1, sizeof *c->start);
    uint32_t* cursor = malloc(cells * sizeof *cursor);
    bool ok = c->start && cursor;
    if (ok) {
        bin_triangles(c, NULL);
        for (size_t i = 0; i < cells; i++)
            c->start[i + 1] += c->start[i];
        for (size_t i = 0; i < cells; i++)
            cursor[i] = c->start[i];
        c->tris = malloc((size_t)c->start[cells] * sizeof *c->tris);
        ok = c->tris != NULL;
    }
    if (ok)
        bin_triangles(c, cursor);
    free(cursor);
    if (!ok) {
        snprintf(err, err_size, "%s: out of memory for the clearance grid", scene->name);
        tv_clearance_destroy(c);
        return NULL;
    }
    return c;
}

void tv_clearance_destroy(tv_clearance* c)
{
    if (!c)
        return;
    free(c->start);
    free(c->tris);
    free(c);
}

float tv_clearance_radius(const tv_clearance* c)
{
    assert(c);
    return c->radius;
}

float tv_clearance_query(const tv_clearance* c, const float p[3], uint32_t* tri)
{
    assert(c && p);
    float best = c->radius;
    uint32_t best_tri = UINT32_MAX;
    if (tri)
        *tri = best_tri;
    int centre[3];
    for (int a = 0; a < 3; a++) {
        float f = floorf((p[a] - c->origin[a]) / c->cell);
        /* a point further than one cell outside the grid has nothing within the radius */
        if (!(f >= -1.0f && f <= (float)c->dim[a]))
            return best;
        centre[a] = (int)f;
    }
    for (int z = centre[2] - 1; z <= centre[2] + 1; z++)
        for (int y = centre[1] - 1; y <= centre[1] + 1; y++)
            for (int x = centre[0] - 1; x <= centre[0] + 1; x++) {
                if (x < 0 || y < 0 || z < 0 || x >= c->dim[0] || y >= c->dim[1] || z >= c->dim[2])
                    continue;
                size_t i = cell_index(c, x, y, z);
                for (uint32_t k = c->start[i]; k < c->start[i + 1]; k++) {
                    uint32_t t = c->tris[k];
                    float d = tv_point_triangle_distance(p, vertex_of(c->scene, t, 0), vertex_of(c->scene, t, 1),
                                                         vertex_of(c->scene, t, 2));
                    if (d < best) {
                        best = d;
                        best_tri = t;
                    }
                }
            }
    if (tri)
        *tri = best_tri;
    return best;
}
