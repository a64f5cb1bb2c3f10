#include "patches.h"

#include "pvs_shared.h"

#include <math.h>
#include <stdlib.h>

static uint32_t root(uint32_t* p, uint32_t x)
{
    while (p[x] != x) {
        p[x] = p[p[x]];
        x = p[x];
    }
    return x;
}

/* Whether triangle t faces `apex`, edge-on within 1e-4 of its normal's length counting as facing. */
static bool facing(const float* c, const float apex[3])
{
    double a[3], b[3], nn[3], d = 0.0, l = 0.0;
    for (int j = 0; j < 3; j++) {
        a[j] = (double)c[3 + j] - c[j];
        b[j] = (double)c[6 + j] - c[j];
    }
    nn[0] = a[1] * b[2] - a[2] * b[1];
    nn[1] = a[2] * b[0] - a[0] * b[2];
    nn[2] = a[0] * b[1] - a[1] * b[0];
    for (int j = 0; j < 3; j++) {
        d += nn[j] * ((double)apex[j] - c[j]);
        l += nn[j] * nn[j];
    }
    return d >= -1e-4 * sqrt(l);
}

bool pvs_front_patches(uint32_t* labels, const uint32_t* adjacency, const float* corners, const bool* masked,
                       uint32_t n, const float apex[3])
{
    uint8_t* state = malloc(n ? n : 1); /* 0: away, 1: facing, 2: facing and masked; | 4: a root touching a masked */
    if (!state) {
        for (uint32_t t = 0; t < n; t++)
            labels[t] = TV_PVS_PATCH_NONE;
        return false;
    }
    for (uint32_t t = 0; t < n; t++) {
        state[t] = facing(corners + 9 * (size_t)t, apex) ? (masked && masked[t] ? 2 : 1) : 0;
        labels[t] = t;
    }
    for (uint32_t t = 0; t < n; t++)
        for (uint32_t e = 0; e < 3; e++) {
            uint32_t a = adjacency[3 * (size_t)t + e], u = a & ~TV_ADJ_REST;
            if (a < TV_ADJ_CRACK && u < n && state[t] == 1 && state[u] == 1)
                labels[root(labels, t)] = root(labels, u);
        }
    for (uint32_t t = 0; t < n; t++) /* a masked face the patch runs into: the eyes may see through it */
        for (uint32_t e = 0; e < 3; e++) {
            uint32_t a = adjacency[3 * (size_t)t + e], u = a & ~TV_ADJ_REST;
            if (a < TV_ADJ_CRACK && u < n && (state[t] & 3) == 1 && (state[u] & 3) == 2)
                state[root(labels, t)] |= 4;
        }
    for (uint32_t t = 0; t < n; t++) /* 8: labelled (decided before any label is cleared) */
        state[t] |= (state[t] & 3) == 1 && !(state[root(labels, t)] & 4) ? 8 : 0;
    for (uint32_t t = 0; t < n; t++)
        labels[t] = root(labels, t);
    for (uint32_t t = 0; t < n; t++)
        labels[t] = state[t] & 8 ? labels[t] : TV_PVS_PATCH_NONE;
    free(state);
    return true;
}
