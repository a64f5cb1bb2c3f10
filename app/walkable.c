#include "walkable.h"

#include "clearance.h"

#include <assert.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define KNEE_M 0.5f
#define MAX_FLOORS 16 /* floors found in one column; more are ignored */

typedef struct walk_point {
    float eye[3];
    uint32_t col;
    uint32_t region; /* UINT32_MAX: not walkable */
    bool covered;    /* some triangle lies above */
} walk_point;

struct tv_walkable {
    const scn_scene* scene;
    tv_walk_desc d;
    tv_clearance* cl;
    float cell, origin[2];
    int dim[2];
    uint32_t *col_start, *col_tris; /* triangles per column (CSR) */
    walk_point* pts;                /* column-major order, so pt_start indexes them */
    uint32_t npts, *pt_start;
    uint32_t* kept; /* indices of the walkable points */
    uint32_t nkept, largest;
};

static const float* vtx(const scn_scene* s, uint32_t tri, int k)
{
    return s->positions + 3 * (size_t)s->indices[3 * (size_t)tri + (size_t)k];
}

static bool double_sided(const scn_scene* s, uint32_t tri)
{
    return s->tri_material && s->materials && s->tri_material[tri] < s->material_count &&
           s->materials[s->tri_material[tri]].double_sided;
}

/* Unit normal's y component of a triangle (0 for a degenerate one). */
static float normal_y(const scn_scene* s, uint32_t tri)
{
    const float *a = vtx(s, tri, 0), *b = vtx(s, tri, 1), *c = vtx(s, tri, 2);
    float e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    float n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    return len > 0.0f ? n[1] / len : 0.0f;
}

/* Height of the triangle above (x, z), false when its x-z projection does
 * not hold the point or is degenerate (a wall). */
static bool height_at(const scn_scene* s, uint32_t tri, float x, float z, float* y)
{
    const float *a = vtx(s, tri, 0), *b = vtx(s, tri, 1), *c = vtx(s, tri, 2);
    float det = (b[0] - a[0]) * (c[2] - a[2]) - (c[0] - a[0]) * (b[2] - a[2]);
    if (fabsf(det) < 1e-9f)
        return false;
    float u = ((x - a[0]) * (c[2] - a[2]) - (c[0] - a[0]) * (z - a[2])) / det;
    float v = ((b[0] - a[0]) * (z - a[2]) - (x - a[0]) * (b[2] - a[2])) / det;
    const float eps = -1e-5f;
    if (u < eps || v < eps || u + v > 1.0f - eps)
        return false;
    *y = a[1] + u * (b[1] - a[1]) + v * (c[1] - a[1]);
    return true;
}

static int col_of(const tv_walkable* w, float v, int axis)
{
    int i = (int)floorf((v - w->origin[axis]) / w->cell);
    return i < 0 ? 0 : i >= w->dim[axis] ? w->dim[axis] - 1 : i;
}

static uint32_t column_at(const tv_walkable* w, float x, float z)
{
    return (uint32_t)col_of(w, z, 1) * (uint32_t)w->dim[0] + (uint32_t)col_of(w, x, 0);
}

/* Every triangle into the columns of its x-z bounding box: counts into
 * col_start[i + 1] when cursor is NULL, else appends at cursor[i]. */
static void bin_columns(tv_walkable* w, uint32_t* cursor)
{
    const scn_scene* s = w->scene;
    for (uint32_t t = 0; t < s->triangle_count; t++) {
        float lo[2] = {FLT_MAX, FLT_MAX}, hi[2] = {-FLT_MAX, -FLT_MAX};
        for (int k = 0; k < 3; k++)
            for (int a = 0; a < 2; a++) {
                lo[a] = fminf(lo[a], vtx(s, t, k)[2 * a]);
                hi[a] = fmaxf(hi[a], vtx(s, t, k)[2 * a]);
            }
        for (int z = col_of(w, lo[1], 1); z <= col_of(w, hi[1], 1); z++)
            for (int x = col_of(w, lo[0], 0); x <= col_of(w, hi[0], 0); x++) {
                size_t i = (size_t)z * (size_t)w->dim[0] + (size_t)x;
                if (cursor)
                    w->col_tris[cursor[i]++] = t;
                else
                    w->col_start[i + 1]++;
            }
    }
}

static bool build_columns(tv_walkable* w)
{
    const scn_scene* s = w->scene;
    float ext[2] = {s->bounds_max[0] - s->bounds_min[0], s->bounds_max[2] - s->bounds_min[2]};
    w->cell = w->d.cell_m > 0.0f ? w->d.cell_m : fmaxf(0.5f, sqrtf(ext[0] * ext[1] / 65536.0f));
    size_t cols = 1;
    for (int a = 0; a < 2; a++) {
        w->origin[a] = s->bounds_min[2 * a];
        w->dim[a] = (int)ceilf(ext[a] / w->cell) + 1;
        cols *= (size_t)w->dim[a];
    }
    w->col_start = calloc(cols + 1, sizeof *w->col_start);
    uint32_t* cursor = malloc(cols * sizeof *cursor);
    bool ok = w->col_start && cursor;
    if (ok) {
        bin_columns(w, NULL);
        for (size_t i = 0; i < cols; i++)
            w->col_start[i + 1] += w->col_start[i];
        memcpy(cursor, w->col_start, cols * sizeof *cursor);
        w->col_tris = malloc(((size_t)w->col_start[cols] + 1) * sizeof *w->col_tris);
        ok = w->col_tris != NULL;
    }
    if (ok)
        bin_columns(w, cursor);
    free(cursor);
    return ok;
}

static bool inside_solid(const tv_walkable* w, const float p[3]);

/* Rule 2 for a floor at height h below (x, z) of column col; *covered: a
 * triangle lies above. */
static bool standing_ok(const tv_walkable* w, uint32_t col, float x, float z, float h, bool* covered)
{
    const scn_scene* s = w->scene;
    float eye_top = h + w->d.eye_height_m + w->d.clearance_m, first = FLT_MAX;
    uint32_t first_tri = UINT32_MAX;
    for (uint32_t k = w->col_start[col]; k < w->col_start[col + 1]; k++) {
        uint32_t t = w->col_tris[k];
        float y;
        if (height_at(s, t, x, z, &y) && y > h + 0.02f && y < first) {
            first = y;
            first_tri = t;
        }
    }
    *covered = first_tri != UINT32_MAX;
    if (first < eye_top)
        return false;
    float eye[3] = {x, h + w->d.eye_height_m, z};
    if (tv_clearance_query(w->cl, eye, NULL) < w->d.clearance_m)
        return false;
    /* a roof seen from below is either the inside of a solid or a one-sided
     * roof (a decimated model's cap): the walls around tell them apart */
    return first_tri == UINT32_MAX || normal_y(s, first_tri) <= 0.0f || double_sided(s, first_tri) ||
           !inside_solid(w, eye);
}

static int by_height(const void* a, const void* b)
{
    float x = *(const float*)a, y = *(const float*)b;
    return (x > y) - (x < y);
}

/* Rules 1 and 2 over every column: points in column order. */
static bool find_points(tv_walkable* w)
{
    const scn_scene* s = w->scene;
    size_t cols = (size_t)w->dim[0] * (size_t)w->dim[1], cap = 1024;
    float cos_slope = cosf(w->d.max_slope_deg * 3.14159265f / 180.0f);
    w->pts = malloc(cap * sizeof *w->pts);
    w->pt_start = calloc(cols + 1, sizeof *w->pt_start);
    if (!w->pts || !w->pt_start)
        return false;
    for (size_t c = 0; c < cols; c++) {
        float x = w->origin[0] + ((float)(c % (size_t)w->dim[0]) + 0.5f) * w->cell;
        float z = w->origin[1] + ((float)(c / (size_t)w->dim[0]) + 0.5f) * w->cell;
        float floors[MAX_FLOORS];
        int nf = 0;
        for (uint32_t k = w->col_start[c]; k < w->col_start[c + 1] && nf < MAX_FLOORS; k++) {
            uint32_t t = w->col_tris[k];
            float ny = normal_y(s, t), y;
            if (fabsf(ny) >= cos_slope && height_at(s, t, x, z, &y))
                floors[nf++] = y;
        }
        qsort(floors, (size_t)nf, sizeof *floors, by_height);
        for (int i = 0; i < nf; i++) {
            bool covered = false;
            if ((i > 0 && floors[i] - floors[i - 1] < 0.05f) ||
                !standing_ok(w, (uint32_t)c, x, z, floors[i], &covered) ||
                (w->d.accept && !w->d.accept((const float[3]){x, floors[i] + w->d.eye_height_m, z}, w->d.user)))
                continue; /* the same floor split into triangles, or no room to stand */
            if (w->npts == cap) {
                walk_point* grown = realloc(w->pts, 2 * cap * sizeof *grown);
                if (!grown)
                    return false;
                w->pts = grown;
                cap *= 2;
            }
            w->pts[w->npts++] = (walk_point){{x, floors[i] + w->d.eye_height_m, z}, (uint32_t)c, UINT32_MAX, covered};
        }
        w->pt_start[c + 1] = w->npts;
    }
    return true;
}

float tv_walkable_clearance(const tv_walkable* w, const float p[3])
{
    return tv_clearance_query(w->cl, p, NULL);
}

/* A walkable point over (x, z) whose floor is within step of y, or UINT32_MAX. */
static uint32_t point_near(const tv_walkable* w, float x, float y, float z, float step)
{
    uint32_t col = column_at(w, x, z), best = UINT32_MAX;
    float best_d = step;
    for (uint32_t i = w->pt_start[col]; i < w->pt_start[col + 1]; i++) {
        float d = fabsf(w->pts[i].eye[1] - w->d.eye_height_m - y);
        if (d <= best_d) {
            best_d = d;
            best = i;
        }
    }
    return best;
}

bool tv_walkable_segment(const tv_walkable* w, const float a[3], const float b[3])
{
    if (fabsf(a[1] - b[1]) > w->d.step_m * fmaxf(1.0f, hypotf(b[0] - a[0], b[2] - a[2]) / w->cell))
        return false;
    float len = hypotf(b[0] - a[0], b[2] - a[2]);
    int n = (int)ceilf(len / (0.5f * w->cell));
    for (int k = 1; k < n; k++) {
        float f = (float)k / (float)n, p[3];
        for (int i = 0; i < 3; i++)
            p[i] = a[i] + f * (b[i] - a[i]);
        float eye[3] = {p[0], p[1] + w->d.eye_height_m, p[2]}, knee[3] = {p[0], p[1] + KNEE_M, p[2]};
        if (tv_clearance_query(w->cl, eye, NULL) < w->d.clearance_m ||
            tv_clearance_query(w->cl, knee, NULL) < w->d.clearance_m / 1.5f ||
            point_near(w, p[0], p[1], p[2], w->d.step_m) == UINT32_MAX)
            return false;
    }
    return true;
}

static void floor_of(const tv_walkable* w, uint32_t i, float out[3])
{
    out[0] = w->pts[i].eye[0];
    out[1] = w->pts[i].eye[1] - w->d.eye_height_m;
    out[2] = w->pts[i].eye[2];
}

/* Calls visit(w, i, j, ctx) for each point j joined to point i (rule 3). */
static void for_neighbours(const tv_walkable* w, uint32_t i, void (*visit)(const tv_walkable*, uint32_t, uint32_t, void*),
                           void* ctx)
{
    int cx = (int)(w->pts[i].col % (uint32_t)w->dim[0]), cz = (int)(w->pts[i].col / (uint32_t)w->dim[0]);
    float a[3], b[3];
    floor_of(w, i, a);
    for (int dz = -1; dz <= 1; dz++)
        for (int dx = -1; dx <= 1; dx++) {
            int x = cx + dx, z = cz + dz;
            if ((dx == 0 && dz == 0) || x < 0 || z < 0 || x >= w->dim[0] || z >= w->dim[1])
                continue;
            size_t col = (size_t)z * (size_t)w->dim[0] + (size_t)x;
            for (uint32_t j = w->pt_start[col]; j < w->pt_start[col + 1]; j++) {
                floor_of(w, j, b);
                if (fabsf(a[1] - b[1]) <= w->d.step_m && tv_walkable_segment(w, a, b))
                    visit(w, i, j, ctx);
            }
        }
}

static uint32_t find_root(uint32_t* parent, uint32_t i)
{
    while (parent[i] != i)
        i = parent[i] = parent[parent[i]];
    return i;
}

static void unite(const tv_walkable* w, uint32_t i, uint32_t j, void* ctx)
{
    uint32_t* parent = ctx;
    uint32_t a = find_root(parent, i), b = find_root(parent, j);
    if (a != b)
        parent[a > b ? a : b] = a > b ? b : a; /* the lower index is the root: deterministic */
}

/* Rule 3: regions, and the walkable points of the big ones. */
static bool find_regions(tv_walkable* w)
{
    uint32_t* parent = malloc(((size_t)w->npts + 1) * sizeof *parent);
    uint32_t* size = calloc((size_t)w->npts + 1, sizeof *size);
    w->kept = malloc(((size_t)w->npts + 1) * sizeof *w->kept);
    bool ok = parent && size && w->kept;
    for (uint32_t i = 0; ok && i < w->npts; i++)
        parent[i] = i;
    for (uint32_t i = 0; ok && i < w->npts; i++)
        for_neighbours(w, i, unite, parent);
    uint32_t biggest = 0;
    for (uint32_t i = 0; ok && i < w->npts; i++) {
        uint32_t r = find_root(parent, i);
        size[r]++;
        if (size[r] > size[biggest] || (size[r] == size[biggest] && r < biggest))
            biggest = r;
    }
    /* per region: big enough, covered anywhere, mean eye height */
    double* mean_y = calloc((size_t)w->npts + 1, sizeof *mean_y);
    uint8_t* covered = calloc((size_t)w->npts + 1, 1);
    ok = ok && mean_y && covered;
    float lowest = FLT_MAX;
    for (uint32_t i = 0; ok && i < w->npts; i++) {
        uint32_t r = find_root(parent, i);
        mean_y[r] += w->pts[i].eye[1] / size[r];
        covered[r] |= w->pts[i].covered;
    }
    for (uint32_t r = 0; ok && r < w->npts; r++)
        if (size[r] && (float)size[r] >= w->d.region_fraction * (float)size[biggest])
            lowest = fminf(lowest, (float)mean_y[r]);
    w->largest = UINT32_MAX;
    uint32_t largest_size = 0;
    for (uint32_t i = 0; ok && i < w->npts; i++) {
        uint32_t r = find_root(parent, i);
        bool roof = !covered[r] && mean_y[r] > lowest + 1.0f;
        if ((float)size[r] >= w->d.region_fraction * (float)size[biggest] && !roof) {
            w->pts[i].region = r;
            w->kept[w->nkept++] = i;
            if (size[r] > largest_size || (size[r] == largest_size && r < w->largest)) {
                largest_size = size[r];
                w->largest = r;
            }
        }
    }
    free(mean_y);
    free(covered);
    free(parent);
    free(size);
    return ok;
}

tv_walkable* tv_walkable_create(const scn_scene* scene, const tv_walk_desc* desc, char* err, size_t err_size)
{
    assert(scene);
    tv_walkable* w = calloc(1, sizeof *w);
    if (!w) {
        snprintf(err, err_size, "out of memory");
        return NULL;
    }
    w->scene = scene;
    w->d = desc ? *desc : (tv_walk_desc){0};
    w->d.eye_height_m = w->d.eye_height_m > 0.0f ? w->d.eye_height_m : 1.6f;
    w->d.clearance_m = w->d.clearance_m > 0.0f ? w->d.clearance_m : 0.3f;
    w->d.max_slope_deg = w->d.max_slope_deg > 0.0f ? w->d.max_slope_deg : 30.0f;
    w->d.step_m = w->d.step_m > 0.0f ? w->d.step_m : 0.5f;
    w->d.region_fraction = w->d.region_fraction > 0.0f ? w->d.region_fraction : 0.25f;
    w->cl = tv_clearance_create(scene, &(tv_clearance_desc){.radius_m = w->d.clearance_m}, err, err_size);
    if (!w->cl) {
        free(w);
        return NULL;
    }
    if (!build_columns(w) || !find_points(w) || !find_regions(w)) {
        snprintf(err, err_size, "%s: out of memory for the walkable points", scene->name);
        tv_walkable_destroy(w);
        return NULL;
    }
    w->d.cell_m = w->cell;
    return w;
}

void tv_walkable_destroy(tv_walkable* w)
{
    if (!w)
        return;
    tv_clearance_destroy(w->cl);
    free(w->col_start);
    free(w->col_tris);
    free(w->pts);
    free(w->pt_start);
    free(w->kept);
    free(w);
}

tv_walk_desc tv_walkable_desc(const tv_walkable* w)
{
    return w->d;
}

uint32_t tv_walkable_count(const tv_walkable* w)
{
    return w->nkept;
}

uint32_t tv_walkable_largest_region(const tv_walkable* w)
{
    return w->largest;
}

void tv_walkable_point(const tv_walkable* w, uint32_t i, float eye[3], uint32_t* region)
{
    assert(i < w->nkept);
    const walk_point* p = &w->pts[w->kept[i]];
    memcpy(eye, p->eye, sizeof p->eye);
    if (region)
        *region = p->region;
}

/* Möller-Trumbore; the distance along dir, or -1. */
static float ray_triangle(const float o[3], const float d[3], const float* a, const float* b, const float* c)
{
    float e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    float p[3] = {d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0]};
    float det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (fabsf(det) < 1e-12f)
        return -1.0f;
    float s[3] = {o[0] - a[0], o[1] - a[1], o[2] - a[2]};
    float u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
    if (u < 0.0f || u > 1.0f)
        return -1.0f;
    float q[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]};
    float v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
    if (v < 0.0f || u + v > 1.0f)
        return -1.0f;
    return (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
}

/* Distance along the ray to its first triangle, capped at max_m; *hit gets
 * that triangle or UINT32_MAX. */
static float cast(const tv_walkable* w, const float eye[3], const float dir[3], float max_m, uint32_t* hit)
{
    float best = max_m;
    uint32_t last = UINT32_MAX;
    *hit = UINT32_MAX;
    /* march the columns the ray crosses; a column's triangles can only hit
     * beyond the column's entry, so once the best hit is behind us it is final */
    for (float s = 0.0f; s <= best + w->cell; s += 0.5f * w->cell) {
        uint32_t col = column_at(w, eye[0] + s * dir[0], eye[2] + s * dir[2]);
        if (col == last)
            continue;
        last = col;
        for (uint32_t k = w->col_start[col]; k < w->col_start[col + 1]; k++) {
            uint32_t t = w->col_tris[k];
            float h = ray_triangle(eye, dir, vtx(w->scene, t, 0), vtx(w->scene, t, 1), vtx(w->scene, t, 2));
            if (h > 0.0f && h < best) {
                best = h;
                *hit = t;
            }
        }
    }
    return best;
}

/* Inside a solid: of 8 horizontal rays from p that meet a single-sided
 * triangle, more meet its back than its front. */
static bool inside_solid(const tv_walkable* w, const float p[3])
{
    int back = 0, front = 0;
    for (int k = 0; k < 8; k++) {
        float a = (float)k * 3.14159265f / 4.0f, d[3] = {sinf(a), 0.0f, cosf(a)};
        uint32_t t;
        cast(w, p, d, 50.0f, &t);
        if (t == UINT32_MAX || double_sided(w->scene, t))
            continue;
        const float *v0 = vtx(w->scene, t, 0), *v1 = vtx(w->scene, t, 1), *v2 = vtx(w->scene, t, 2);
        float e1[3] = {v1[0] - v0[0], v1[1] - v0[1], v1[2] - v0[2]}, e2[3] = {v2[0] - v0[0], v2[1] - v0[1], v2[2] - v0[2]};
        float nx = e1[1] * e2[2] - e1[2] * e2[1], nz = e1[0] * e2[1] - e1[1] * e2[0];
        if (nx * d[0] + nz * d[2] > 0.0f)
            back++;
        else
            front++;
    }
    return back > front;
}

static float dist2(const float a[3], const float b[3])
{
    float dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return dx * dx + dy * dy + dz * dz;
}

int tv_walkable_viewcells(const tv_walkable* w, uint32_t region, int max, float* pos, float* dir,
                          uint32_t* indices)
{
    assert(w && pos && dir);
    float* nearest = malloc(((size_t)w->nkept + 1) * sizeof *nearest);
    double centre[3] = {0, 0, 0};
    uint32_t n = 0;
    for (uint32_t i = 0; nearest && i < w->nkept; i++) {
        const walk_point* p = &w->pts[w->kept[i]];
        bool in = region == UINT32_MAX || p->region == region;
        nearest[i] = in ? FLT_MAX : -1.0f; /* -1: never chosen */
        for (int k = 0; in && k < 3; k++)
            centre[k] += p->eye[k];
        n += in;
    }
    int count = 0;
    if (nearest && n > 0) {
        float c[3] = {(float)(centre[0] / n), (float)(centre[1] / n), (float)(centre[2] / n)};
        uint32_t next = UINT32_MAX;
        float best = FLT_MAX;
        for (uint32_t i = 0; i < w->nkept; i++)
            if (nearest[i] >= 0.0f && dist2(w->pts[w->kept[i]].eye, c) < best) {
                best = dist2(w->pts[w->kept[i]].eye, c);
                next = i;
            }
        while (count < max && next != UINT32_MAX && nearest[next] > 0.0f) {
            const float* eye = w->pts[w->kept[next]].eye;
            memcpy(&pos[3 * count], eye, 3 * sizeof *eye);
            if (indices)
                indices[count] = next;
            float far = -1.0f;
            for (int k = 0; k < 16; k++) { /* the longest line of sight */
                float a = (float)k * 3.14159265f / 8.0f, d[3] = {-sinf(a), 0.0f, -cosf(a)};
                uint32_t hit;
                float len = cast(w, eye, d, 50.0f, &hit);
                if (len > far + 1e-3f) {
                    far = len;
                    memcpy(&dir[3 * count], d, sizeof d);
                }
            }
            count++;
            next = UINT32_MAX;
            float farthest = 0.0f;
            for (uint32_t i = 0; i < w->nkept; i++) {
                if (nearest[i] < 0.0f)
                    continue;
                nearest[i] = fminf(nearest[i], dist2(w->pts[w->kept[i]].eye, eye));
                if (nearest[i] > farthest) {
                    farthest = nearest[i];
                    next = i;
                }
            }
        }
    }
    free(nearest);
    return count;
}

typedef struct bfs {
    uint32_t *prev, *queue;
    uint32_t tail;
} bfs;

static void enqueue(const tv_walkable* w, uint32_t i, uint32_t j, void* ctx)
{
    bfs* q = ctx;
    if (q->prev[j] == UINT32_MAX) {
        q->prev[j] = i;
        q->queue[q->tail++] = j;
    }
}

int tv_walkable_route(const tv_walkable* w, uint32_t from, uint32_t to, uint32_t* route, int max)
{
    assert(from < w->nkept && to < w->nkept && max > 0);
    uint32_t src = w->kept[from], dst = w->kept[to];
    bfs q = {malloc(((size_t)w->npts + 1) * sizeof *q.prev), malloc(((size_t)w->npts + 1) * sizeof *q.queue), 0};
    int n = 0;
    if (q.prev && q.queue) {
        for (uint32_t i = 0; i < w->npts; i++)
            q.prev[i] = UINT32_MAX;
        q.prev[src] = src;
        q.queue[q.tail++] = src;
        for (uint32_t head = 0; head < q.tail && q.prev[dst] == UINT32_MAX; head++)
            for_neighbours(w, q.queue[head], enqueue, &q);
        if (q.prev[dst] != UINT32_MAX) {
            for (uint32_t i = dst; n <= max; i = q.prev[i]) {
                n++;
                if (i == src)
                    break;
            }
            n = n > max ? 0 : n;
            uint32_t i = dst;
            for (int k = n - 1; k >= 0; k--, i = q.prev[i])
                route[k] = i;
        }
    }
    free(q.prev);
    free(q.queue);
    /* point indices into kept order: kept is sorted, so a binary search maps them back */
    for (int k = 0; k < n; k++) {
        uint32_t lo = 0, hi = w->nkept;
        while (lo + 1 < hi) {
            uint32_t mid = (lo + hi) / 2;
            if (w->kept[mid] <= route[k])
                lo = mid;
            else
                hi = mid;
        }
        route[k] = lo;
    }
    return n;
}
