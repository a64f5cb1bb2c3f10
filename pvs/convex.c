/* convex.c - pvs_convex_patches (convex.h): union-find over the convex and
 * flat manifold edges, then every patch with a concave, rest or masked link
 * is open. */
#include "convex.h"

#include "pvs_shared.h" /* TV_ADJ_CRACK, TV_ADJ_REST */

#include <math.h>
#include <stdlib.h>
#include <string.h>

static uint32_t find(uint32_t* parent, uint32_t x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

static void corners(const uint32_t* indices, const float* positions, uint32_t t, double p[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            p[i][j] = positions[3 * (size_t)indices[3 * (size_t)t + i] + j];
}

/* Unit normal of p; false when degenerate (it faces neither way: not convex). */
static bool unit_normal(double p[3][3], double n[3])
{
    double a[3], b[3];
    for (int j = 0; j < 3; j++) {
        a[j] = p[1][j] - p[0][j];
        b[j] = p[2][j] - p[0][j];
    }
    n[0] = a[1] * b[2] - a[2] * b[1];
    n[1] = a[2] * b[0] - a[0] * b[2];
    n[2] = a[0] * b[1] - a[1] * b[0];
    double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(l > 1e-12))
        return false;
    for (int j = 0; j < 3; j++)
        n[j] /= l;
    return true;
}

/* The signed distances of q's corners to p's plane (normal n): the largest in front, the smallest. */
static void ahead(double n[3], double p[3][3], double q[3][3], double* most, double* least)
{
    *most = -INFINITY;
    *least = INFINITY;
    for (int i = 0; i < 3; i++) {
        double d = n[0] * (q[i][0] - p[0][0]) + n[1] * (q[i][1] - p[0][1]) + n[2] * (q[i][2] - p[0][2]);
        *most = fmax(*most, d);
        *least = fmin(*least, d);
    }
}

/* Whether the manifold edge between t and u is convex or flat: each face's
 * corners on or behind the other's plane up to the rounding of float
 * positions (a few ulps of the largest coordinate). A flat pair must face
 * one way (a flipped neighbour's winding would pass the plane tests); a
 * pair whose normals point apart must have a corner strictly behind. */
static bool convex_link(const uint32_t* indices, const float* positions, uint32_t t, uint32_t u)
{
    double p[3][3], q[3][3], np[3], nq[3], scale = 1e-3, a, a_min, b, b_min;
    corners(indices, positions, t, p);
    corners(indices, positions, u, q);
    if (!unit_normal(p, np) || !unit_normal(q, nq))
        return false;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            scale = fmax(scale, fmax(fabs(p[i][j]), fabs(q[i][j])));
    double tol = 5e-7 * scale;
    ahead(np, p, q, &a, &a_min);
    ahead(nq, q, p, &b, &b_min);
    double facing = np[0] * nq[0] + np[1] * nq[1] + np[2] * nq[2];
    return a <= tol && b <= tol && (facing > 0.0 || (a_min < -tol && b_min < -tol));
}

size_t pvs_convex_patches(uint32_t* bits, const uint32_t* adjacency, const uint32_t* indices, uint32_t count,
                          const float* positions, const bool* masked)
{
    memset(bits, 0, sizeof(uint32_t) * (((size_t)count + 31) / 32));
    uint32_t* parent = malloc(sizeof(uint32_t) * (count ? count : 1));
    bool* open = calloc(count ? count : 1, sizeof(bool));
    if (!parent || !open) {
        free(parent);
        free(open);
        return (size_t)-1;
    }
    for (uint32_t t = 0; t < count; t++)
        parent[t] = t;
    for (uint32_t t = 0; t < count; t++) {
        open[t] = open[t] || (masked && masked[t]);
        for (uint32_t e = 0; e < 3; e++) {
            uint32_t a = adjacency[3 * (size_t)t + e];
            if (a >= TV_ADJ_CRACK)
                continue; /* border, crack, non-manifold: a silhouette from everywhere */
            uint32_t u = a & ~TV_ADJ_REST;
            if (u >= count)
                open[t] = true;
            else if ((a & TV_ADJ_REST) == 0 && convex_link(indices, positions, t, u))
                parent[find(parent, t)] = find(parent, u);
            else
                open[t] = open[u] = true; /* concave, rest (a concave corner by construction) */
        }
    }
    for (uint32_t t = 0; t < count; t++)
        if (open[t])
            open[find(parent, t)] = true;
    size_t set = 0;
    for (uint32_t t = 0; t < count; t++) {
        if (!open[find(parent, t)]) {
            bits[t / 32] |= 1u << (t % 32);
            set++;
        }
    }
    free(parent);
    free(open);
    return set;
}
