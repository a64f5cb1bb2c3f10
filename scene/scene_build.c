/* scene_build.c - growable scene arrays, primitive flattening, normal generation. */
#include "scene_build.h"

#include "log.h"
#include "weld.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void scn_builder_init(scn_builder* b, scn_scene* out, bool count_only)
{
    assert(b && out);
    memset(out, 0, sizeof *out);
    memset(b, 0, sizeof *b);
    b->scene = out;
    b->count_only = count_only;
}

/* Grows *array to hold `needed` elements of `elem` bytes, doubling. */
static bool _scn_grow(void** array, uint32_t* capacity, uint64_t needed, size_t elem)
{
    if (needed <= *capacity)
        return true;
    uint64_t cap = *capacity ? *capacity : 1024;
    while (cap < needed)
        cap *= 2;
    if (cap > UINT32_MAX)
        cap = UINT32_MAX;
    if (needed > cap)
        return false;
    void* grown = realloc(*array, (size_t)cap * elem);
    if (!grown)
        return false;
    *array = grown;
    *capacity = (uint32_t)cap;
    return true;
}

uint32_t scn_builder_vertices(scn_builder* b, uint32_t count)
{
    b->vertex_total += count;
    if (b->count_only || b->failed)
        return UINT32_MAX;
    scn_scene* s = b->scene;
    uint64_t needed = (uint64_t)s->vertex_count + count;
    uint32_t cap = b->vertex_capacity, c1 = cap, c2 = cap, c3 = cap, c4 = cap;
    bool ok = needed < UINT32_MAX && _scn_grow((void**)&s->positions, &c1, needed, 3 * sizeof(float)) &&
              _scn_grow((void**)&s->normals, &c2, needed, 3 * sizeof(float)) &&
              _scn_grow((void**)&s->uvs, &c3, needed, 2 * sizeof(float)) &&
              (!b->needs_normal || _scn_grow((void**)&b->needs_normal, &c4, needed, sizeof(bool)));
    if (!ok) {
        b->failed = true;
        return UINT32_MAX;
    }
    b->vertex_capacity = c1;
    if (b->needs_normal)
        memset(b->needs_normal + s->vertex_count, 0, count * sizeof(bool));
    uint32_t first = s->vertex_count;
    s->vertex_count += count;
    return first;
}

void scn_builder_triangle(scn_builder* b, uint32_t i0, uint32_t i1, uint32_t i2, uint32_t material)
{
    b->triangle_total++;
    if (b->count_only || b->failed)
        return;
    scn_scene* s = b->scene;
    assert(i0 < s->vertex_count && i1 < s->vertex_count && i2 < s->vertex_count);
    uint64_t needed = (uint64_t)s->triangle_count + 1;
    uint32_t c1 = b->triangle_capacity, c2 = b->triangle_capacity;
    if (!_scn_grow((void**)&s->indices, &c1, needed, 3 * sizeof(uint32_t)) ||
        !_scn_grow((void**)&s->tri_material, &c2, needed, sizeof(uint32_t))) {
        b->failed = true;
        return;
    }
    b->triangle_capacity = c1;
    uint32_t* idx = s->indices + 3 * (size_t)s->triangle_count;
    idx[0] = i0;
    idx[1] = i1;
    idx[2] = i2;
    s->tri_material[s->triangle_count++] = material;
}

uint32_t scn_builder_material(scn_builder* b, const scn_material* m)
{
    scn_scene* s = b->scene;
    if (b->failed || !_scn_grow((void**)&s->materials, &b->material_capacity, s->material_count + 1ull,
                                sizeof *m)) {
        b->failed = true;
        return 0;
    }
    s->materials[s->material_count] = *m;
    return s->material_count++;
}

uint32_t scn_builder_texture(scn_builder* b, uint32_t width, uint32_t height, uint8_t* rgba8)
{
    scn_scene* s = b->scene;
    if (b->failed || !_scn_grow((void**)&s->textures, &b->texture_capacity, s->texture_count + 1ull,
                                sizeof *s->textures)) {
        free(rgba8);
        b->failed = true;
        return 0;
    }
    s->textures[s->texture_count] = (scn_texture){ .width = width, .height = height, .rgba8 = rgba8 };
    return s->texture_count++;
}

void scn_mat4_trs(float out[16], const double t[3], const double r[4], const double s[3])
{
    double x = r[0], y = r[1], z = r[2], w = r[3];
    double rot[9] = { /* column-major rotation of a unit quaternion */
        1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w),
        2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
        2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y),
    };
    memset(out, 0, 16 * sizeof(float));
    for (int c = 0; c < 3; c++)
        for (int row = 0; row < 3; row++)
            out[4 * c + row] = (float)(rot[3 * c + row] * s[c]);
    for (int row = 0; row < 3; row++)
        out[12 + row] = (float)t[row];
    out[15] = 1.0f;
}

void scn_mat4_mul(float out[16], const float a[16], const float b[16])
{
    assert(out != a && out != b);
    for (int c = 0; c < 4; c++)
        for (int row = 0; row < 4; row++) {
            double sum = 0.0;
            for (int k = 0; k < 4; k++)
                sum += (double)a[4 * k + row] * b[4 * c + k];
            out[4 * c + row] = (float)sum;
        }
}

static void _scn_cross(const float* a, const float* b, const float* c, double n[3])
{
    double e1[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    double e2[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

static void _scn_normalize_or_up(float* n)
{
    double len = sqrt((double)n[0] * n[0] + (double)n[1] * n[1] + (double)n[2] * n[2]);
    if (!(len > 0.0) || !isfinite(len)) {
        n[0] = 0.0f, n[1] = 1.0f, n[2] = 0.0f; /* isolated or all-degenerate corner */
        return;
    }
    for (int i = 0; i < 3; i++)
        n[i] = (float)(n[i] / len);
}

/* Inverse transpose of the upper 3x3 of a column-major mat4 (cofactor matrix
 * scaled by 1/det), so normals stay perpendicular under non-uniform scale. */
static double _scn_normal_matrix(const float m[16], double nm[9])
{
#define M(r, c) ((double)m[4 * (c) + (r)])
    double det = M(0, 0) * (M(1, 1) * M(2, 2) - M(2, 1) * M(1, 2)) -
                 M(0, 1) * (M(1, 0) * M(2, 2) - M(1, 2) * M(2, 0)) +
                 M(0, 2) * (M(1, 0) * M(2, 1) - M(1, 1) * M(2, 0));
    /* cofactor(r, c) stored column-major: nm[3c + r] */
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
            nm[3 * c + r] = (M(r1, c1) * M(r2, c2) - M(r1, c2) * M(r2, c1)) / det;
        }
#undef M
    return det;
}

bool scn_builder_append_mesh(scn_builder* b, const scn_mesh_input* mesh, const char* file, char* err,
                             size_t err_size)
{
    assert(mesh->positions && (mesh->indices || mesh->triangle_count == 0));
    double nm[9];
    double det = _scn_normal_matrix(mesh->world, nm);
    if (!(fabs(det) > 0.0) || !isfinite(det)) {
        snprintf(err, err_size, "%s: node transform is singular or not finite", file);
        return false;
    }
    uint32_t first = scn_builder_vertices(b, mesh->vertex_count);
    if (first == UINT32_MAX) {
        b->triangle_total += mesh->triangle_count;
        return true;
    }
    scn_scene* s = b->scene;
    const float* m = mesh->world;
    for (uint32_t v = 0; v < mesh->vertex_count; v++) {
        const float* p = mesh->positions + 3 * (size_t)v;
        float* out = s->positions + 3 * ((size_t)first + v);
        for (int r = 0; r < 3; r++) {
            out[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
            if (!isfinite(out[r])) {
                snprintf(err, err_size, "%s: vertex %u has a NaN or infinite position", file, v);
                return false;
            }
        }
        float* n = s->normals + 3 * ((size_t)first + v);
        if (mesh->normals) {
            const float* in = mesh->normals + 3 * (size_t)v;
            for (int r = 0; r < 3; r++)
                n[r] = (float)(nm[r] * in[0] + nm[3 + r] * in[1] + nm[6 + r] * in[2]);
            _scn_normalize_or_up(n);
        } else {
            n[0] = n[1] = n[2] = 0.0f;
        }
        float* uv = s->uvs + 2 * ((size_t)first + v);
        uv[0] = mesh->uvs ? mesh->uvs[2 * (size_t)v] : 0.0f;
        uv[1] = mesh->uvs ? mesh->uvs[2 * (size_t)v + 1] : 0.0f;
    }
    if (!mesh->normals) {
        if (!b->needs_normal) {
            uint32_t cap = 0;
            if (!_scn_grow((void**)&b->needs_normal, &cap, b->vertex_capacity, sizeof(bool))) {
                b->failed = true;
                return true;
            }
            memset(b->needs_normal, 0, s->vertex_count * sizeof(bool));
        }
        memset(b->needs_normal + first, 1, mesh->vertex_count * sizeof(bool));
    }
    bool flip = det < 0.0; /* a mirror turns counter-clockwise into clockwise */
    for (uint32_t t = 0; t < mesh->triangle_count; t++) {
        const uint32_t* tri = mesh->indices + 3 * (size_t)t;
        uint32_t a = first + tri[0], c1 = first + tri[1], c2 = first + tri[2];
        double n[3];
        _scn_cross(s->positions + 3 * (size_t)a, s->positions + 3 * (size_t)c1, s->positions + 3 * (size_t)c2, n);
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] ||
            (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0)) {
            b->dropped_degenerate++;
            continue;
        }
        if (flip)
            scn_builder_triangle(b, a, c2, c1, mesh->material);
        else
            scn_builder_triangle(b, a, c1, c2, mesh->material);
    }
    return true;
}

/* Area-weighted smooth normals over welded positions: the cross product's
 * length is twice the area, so summing raw cross products weights by area,
 * and welding makes soups (one vertex per corner) shade smoothly too. */
static bool _scn_generate_normals(scn_builder* b)
{
    scn_scene* s = b->scene;
    uint32_t* remap = malloc((size_t)s->vertex_count * sizeof *remap);
    double* acc = calloc((size_t)s->vertex_count * 3, sizeof *acc);
    if (!remap || !acc) {
        free(remap);
        free(acc);
        return false;
    }
    scn_weld_positions(remap, s->positions, s->vertex_count);
    for (uint32_t t = 0; t < s->triangle_count; t++) {
        const uint32_t* tri = s->indices + 3 * (size_t)t;
        double n[3];
        _scn_cross(s->positions + 3 * (size_t)tri[0], s->positions + 3 * (size_t)tri[1],
                   s->positions + 3 * (size_t)tri[2], n);
        for (int c = 0; c < 3; c++)
            for (int k = 0; k < 3; k++)
                acc[3 * (size_t)remap[tri[c]] + k] += n[k];
    }
    for (uint32_t v = 0; v < s->vertex_count; v++) {
        if (!b->needs_normal[v])
            continue;
        float* n = s->normals + 3 * (size_t)v;
        for (int k = 0; k < 3; k++)
            n[k] = (float)acc[3 * (size_t)remap[v] + k];
        _scn_normalize_or_up(n);
    }
    free(remap);
    free(acc);
    return true;
}

void scn_builder_mover_begin(scn_builder* b)
{
    b->mover_vertex = b->scene->vertex_count;
    b->mover_triangle = b->scene->triangle_count;
}

scn_mover* scn_builder_mover_end(scn_builder* b, const char* name)
{
    scn_scene* s = b->scene;
    if (b->count_only || b->failed)
        return NULL;
    if (!_scn_grow((void**)&s->movers, &b->mover_capacity, (uint64_t)s->mover_count + 1, sizeof *s->movers)) {
        b->failed = true;
        return NULL;
    }
    scn_mover* m = &s->movers[s->mover_count++];
    memset(m, 0, sizeof *m);
    snprintf(m->name, sizeof m->name, "%s", name);
    m->first_vertex = (uint32_t)b->mover_vertex;
    m->vertex_count = (uint32_t)(s->vertex_count - b->mover_vertex);
    m->first_triangle = (uint32_t)b->mover_triangle;
    m->triangle_count = (uint32_t)(s->triangle_count - m->first_triangle);
    for (int i = 0; i < 4; i++)
        m->parent[5 * i] = 1.0f;
    m->base_r[3] = 1.0f;
    m->base_s[0] = m->base_s[1] = m->base_s[2] = 1.0f;
    return m;
}

/* Rest geometry, dynamic range and t = 0 pose of the movers; scene bounds
 * over their whole loops. */
static bool _scn_finish_movers(scn_builder* b, const char* what, char* err, size_t err_size)
{
    scn_scene* s = b->scene;
    if (!s->mover_count)
        return true;
    s->dynamic_triangle_count = s->triangle_count - s->movers[0].first_triangle;
    for (uint32_t i = 0; i < s->mover_count; i++) {
        char problem[256];
        if (!scn_mover_init(&s->movers[i], s, problem, sizeof problem)) {
            snprintf(err, err_size, "%s: %s", what, problem);
            return false;
        }
    }
    scn_scene_pose(s, 0.0);
    scn_scene_update_bounds(s);
    for (uint32_t i = 0; i < s->mover_count; i++) {
        float mn[3], mx[3];
        scn_mover_bounds(s, i, 0.0, s->movers[i].period_s, mn, mx);
        for (int k = 0; k < 3; k++) {
            s->bounds_min[k] = fminf(s->bounds_min[k], mn[k]);
            s->bounds_max[k] = fmaxf(s->bounds_max[k], mx[k]);
        }
    }
    return true;
}

bool scn_builder_finish(scn_builder* b, const char* what, char* err, size_t err_size)
{
    if (!b->failed && b->needs_normal && !_scn_generate_normals(b))
        b->failed = true;
    free(b->needs_normal);
    b->needs_normal = NULL;
    if (b->failed) {
        snprintf(err, err_size, "%s: out of memory (or more than 2^32 vertices) while building the scene", what);
        scn_scene_free(b->scene);
        return false;
    }
    if (b->dropped_degenerate)
        tv_log(TV_LOG_INFO, "%s: dropped %u degenerate triangles (repeated index or zero area)", what,
               b->dropped_degenerate);
    b->scene->degenerate_dropped = b->dropped_degenerate;
    scn_scene_update_bounds(b->scene);
    if (!_scn_finish_movers(b, what, err, err_size)) {
        scn_scene_free(b->scene);
        return false;
    }
    return true;
}

void scn_builder_abort(scn_builder* b)
{
    free(b->needs_normal);
    b->needs_normal = NULL;
    scn_scene_free(b->scene);
}
