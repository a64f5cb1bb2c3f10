#include "depth_bound.h"

#include "proxies.h"
#include "pvs_shared.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Relative slack on stored depths: P1 recomputes the edge depths in its own
 * float arithmetic, which must not land above the bound by rounding. */
#define PVS_DEPTH_BOUND_SLACK 1e-4f

/* Cells of all levels; fills b's level table when b is not NULL. */
static uint32_t levels_of(uint32_t width, uint32_t height, pvs_depth_bound* b)
{
    uint32_t cw = (width + TV_PVS_DEPTH_CELL_PX - 1) / TV_PVS_DEPTH_CELL_PX;
    uint32_t ch = (height + TV_PVS_DEPTH_CELL_PX - 1) / TV_PVS_DEPTH_CELL_PX;
    uint32_t n = 0, total = 0;
    for (;;) {
        assert(n < PVS_DEPTH_BOUND_MAX_LEVELS);
        if (b) {
            b->level_width[n] = cw;
            b->level_height[n] = ch;
            b->level_offset[n] = total;
            b->levels = n + 1;
        }
        total += cw * ch;
        n++;
        if (cw == 1 && ch == 1)
            return total;
        cw = (cw + 1) / 2;
        ch = (ch + 1) / 2;
    }
}

uint32_t pvs_depth_bound_cell_count(uint32_t width, uint32_t height)
{
    assert(width > 0 && height > 0);
    return levels_of(width, height, NULL);
}

bool pvs_depth_bound_init(pvs_depth_bound* b, uint32_t width, uint32_t height)
{
    assert(b && width > 0 && height > 0);
    *b = (pvs_depth_bound){.width = width, .height = height};
    b->cell_count = levels_of(width, height, b);
    b->cells = calloc(b->cell_count, sizeof(float));
    if (!b->cells) {
        *b = (pvs_depth_bound){0};
        return false;
    }
    return true;
}

void pvs_depth_bound_free(pvs_depth_bound* b)
{
    if (!b)
        return;
    free(b->cells);
    *b = (pvs_depth_bound){0};
}

void pvs_depth_bound_begin(pvs_depth_bound* b, const pvs_view* view)
{
    assert(b && b->cells && view);
    b->view = *view;
    b->frame = pvs_view_frame_make(view);
    b->focal_px = 0.5f * (float)b->height / b->frame.tan_half_y;
    memset(b->cells, 0, sizeof(float) * b->cell_count);
}

void pvs_depth_bound_pixel(const pvs_depth_bound* b, const float image[2], float px[2])
{
    px[0] = 0.5f * (float)b->width + image[0] * b->focal_px;
    px[1] = 0.5f * (float)b->height + image[1] * b->focal_px;
}

/* Level-0 cell of pixel coordinate v along an axis of `cells` cells. */
static uint32_t cell_of(float v, uint32_t cells)
{
    float c = floorf(v / (float)TV_PVS_DEPTH_CELL_PX);
    return c <= 0.0f ? 0u : c >= (float)(cells - 1) ? cells - 1 : (uint32_t)c;
}

/* Grows the box lo/hi and the maximum depth by point `p` at `depth` >= near. */
static void grow(const pvs_depth_bound* b, const float p[3], float depth, float lo[2], float hi[2])
{
    float rel[3], image[2], px[2];
    for (int a = 0; a < 3; a++)
        rel[a] = p[a] - b->view.apex[a];
    for (int c = 0; c < 2; c++) {
        const float* axis = c ? b->frame.up : b->frame.right;
        image[c] = (rel[0] * axis[0] + rel[1] * axis[1] + rel[2] * axis[2]) / depth;
    }
    pvs_depth_bound_pixel(b, image, px);
    for (int c = 0; c < 2; c++) {
        lo[c] = fminf(lo[c], px[c]);
        hi[c] = fmaxf(hi[c], px[c]);
    }
}

void pvs_depth_bound_add(pvs_depth_bound* b, const float (*points)[3], uint32_t count)
{
    assert(b && b->cells && points && count > 0 && count <= 8);
    const float* f = b->frame.forward;
    const float near = b->view.near_dist;
    float depth[8], deepest = -INFINITY, lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (uint32_t i = 0; i < count; i++) {
        depth[i] = (points[i][0] - b->view.apex[0]) * f[0] + (points[i][1] - b->view.apex[1]) * f[1] +
                   (points[i][2] - b->view.apex[2]) * f[2];
        if (depth[i] >= near) {
            grow(b, points[i], depth[i], lo, hi);
            deepest = fmaxf(deepest, depth[i]);
        }
    }
    if (deepest == -INFINITY)
        return; /* wholly behind the near plane */
    /* The hull's part in front of the near plane is the hull of the points
     * in front and of where the segments between them and those behind
     * cross the plane (every pair: the hull's edges are among them). */
    for (uint32_t i = 0; i < count; i++) {
        for (uint32_t j = 0; j < count; j++) {
            if (!(depth[i] >= near && depth[j] < near))
                continue;
            float t = (depth[i] - near) / (depth[i] - depth[j]), q[3];
            for (int a = 0; a < 3; a++)
                q[a] = points[i][a] + t * (points[j][a] - points[i][a]);
            grow(b, q, near, lo, hi);
        }
    }
    uint32_t x0 = cell_of(lo[0] - 1.0f, b->level_width[0]), x1 = cell_of(hi[0] + 1.0f, b->level_width[0]);
    uint32_t y0 = cell_of(lo[1] - 1.0f, b->level_height[0]), y1 = cell_of(hi[1] + 1.0f, b->level_height[0]);
    /* A triangle's depth over one cell: on its plane n.X = k, the inverse
     * depth is affine in the image, 1/D = (n.f + x n.r + y n.u) / (k - n.apex),
     * so its smallest value over the cell's rectangle (at the corner the
     * gradient picks) bounds the depth of every point of the triangle seen
     * in the cell. Large receding floors and walls get the depth they have
     * there, not their farthest corner's. Where that minimum is not
     * positive (the plane reaches the horizon) the farthest corner bounds. */
    double plane[3] = {0.0, 0.0, 0.0};
    if (count == 3) {
        const float* p0 = points[0];
        float e1[3], e2[3], n[3];
        for (int a = 0; a < 3; a++) {
            e1[a] = points[1][a] - p0[a];
            e2[a] = points[2][a] - p0[a];
        }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        double c = 0.0, nf = 0.0, nr = 0.0, nu = 0.0;
        for (int a = 0; a < 3; a++) {
            c += (double)n[a] * ((double)p0[a] - (double)b->view.apex[a]);
            nf += (double)n[a] * b->frame.forward[a];
            nr += (double)n[a] * b->frame.right[a];
            nu += (double)n[a] * b->frame.up[a];
        }
        if (c != 0.0) { /* per pixel: x = (px - W/2) / focal */
            plane[1] = nr / (c * b->focal_px);
            plane[2] = nu / (c * b->focal_px);
            plane[0] = nf / c - plane[1] * 0.5 * b->width - plane[2] * 0.5 * b->height;
        }
    }
    /* A border cell also holds what lies beyond the image on its side: its
     * rectangle is open there. */
    const uint32_t last_x = b->level_width[0] - 1, last_y = b->level_height[0] - 1;
    const float cell = (float)TV_PVS_DEPTH_CELL_PX;
    for (uint32_t y = y0; y <= y1; y++) {
        float* row = b->cells + (size_t)y * b->level_width[0];
        uint32_t cy = y + (plane[2] > 0.0 ? 0u : 1u);
        bool open_y = plane[2] != 0.0 && (plane[2] > 0.0 ? y == 0 : y == last_y);
        for (uint32_t x = x0; x <= x1; x++) {
            uint32_t cx = x + (plane[1] > 0.0 ? 0u : 1u);
            bool open = open_y || (plane[1] != 0.0 && (plane[1] > 0.0 ? x == 0 : x == last_x));
            double inv = plane[0] + plane[1] * cell * cx + plane[2] * cell * cy, depth = deepest;
            if (!open && inv > 0.0 && 1.0 / inv < depth)
                depth = 1.0 / inv;
            row[x] = fmaxf(row[x], fminf(b->view.far_dist, (float)depth * (1.0f + PVS_DEPTH_BOUND_SLACK)));
        }
    }
}

void pvs_depth_bound_add_ids(pvs_depth_bound* b, const uint32_t* ids, uint32_t count, const float* corners,
                             uint32_t first_proxy_face, const float* boxes)
{
    assert(b && (ids || count == 0) && corners);
    for (uint32_t i = 0; i < count; i++) {
        if (ids[i] < first_proxy_face) {
            pvs_depth_bound_add(b, (const float(*)[3])(corners + 9 * (size_t)ids[i]), 3);
            continue;
        }
        assert(boxes);
        const float* box = boxes + PVS_PROXY_FLOATS * ((ids[i] - first_proxy_face) / 12u);
        float p[8][3];
        for (int c = 0; c < 8; c++) {
            for (int a = 0; a < 3; a++)
                p[c][a] = box[(c >> a & 1) ? 4 + a : a];
        }
        pvs_depth_bound_add(b, (const float(*)[3])p, 8);
    }
}

void pvs_depth_bound_finish(pvs_depth_bound* b)
{
    assert(b && b->cells);
    for (uint32_t l = 1; l < b->levels; l++) {
        const float* child = b->cells + b->level_offset[l - 1];
        float* cell = b->cells + b->level_offset[l];
        uint32_t cw = b->level_width[l - 1], ch = b->level_height[l - 1];
        for (uint32_t y = 0; y < b->level_height[l]; y++) {
            for (uint32_t x = 0; x < b->level_width[l]; x++) {
                float m = 0.0f;
                for (uint32_t dy = 0; dy < 2 && 2 * y + dy < ch; dy++) {
                    for (uint32_t dx = 0; dx < 2 && 2 * x + dx < cw; dx++)
                        m = fmaxf(m, child[(2 * y + dy) * cw + 2 * x + dx]);
                }
                cell[y * b->level_width[l] + x] = m;
            }
        }
    }
}

float pvs_depth_bound_query(const pvs_depth_bound* b, float x0, float y0, float x1, float y1)
{
    assert(b && b->cells && x0 <= x1 && y0 <= y1);
    uint32_t cx0 = cell_of(x0, b->level_width[0]), cx1 = cell_of(x1, b->level_width[0]);
    uint32_t cy0 = cell_of(y0, b->level_height[0]), cy1 = cell_of(y1, b->level_height[0]);
    uint32_t l = 0;
    while ((cx1 >> l) - (cx0 >> l) > 1 || (cy1 >> l) - (cy0 >> l) > 1)
        l++;
    const float* cell = b->cells + b->level_offset[l];
    float m = 0.0f;
    for (uint32_t y = cy0 >> l; y <= cy1 >> l; y++) {
        for (uint32_t x = cx0 >> l; x <= cx1 >> l; x++)
            m = fmaxf(m, cell[y * b->level_width[l] + x]);
    }
    return m;
}
