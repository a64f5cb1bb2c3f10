#include "gt_seethrough.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

bool gt_seethrough_init(gt_seethrough* g, const scn_scene* scene, size_t pixels)
{
    memset(g, 0, sizeof *g);
    for (uint32_t t = 0; t < scene->triangle_count; t++)
        g->blend_count += scene->materials[scene->tri_material[t]].alpha_mode == SCN_ALPHA_BLEND;
    if (g->blend_count == 0)
        return true;
    g->opaque_count = scene->triangle_count - g->blend_count;
    g->blend = malloc(sizeof(uint32_t) * g->blend_count);
    g->opaque = malloc(sizeof(uint32_t) * (g->opaque_count ? g->opaque_count : 1));
    g->ids = malloc(sizeof(uint32_t) * pixels);
    g->depth = malloc(sizeof(float) * pixels);
    g->opaque_depth = malloc(sizeof(float) * pixels);
    if (!g->blend || !g->opaque || !g->ids || !g->depth || !g->opaque_depth) {
        gt_seethrough_free(g);
        return false;
    }
    uint32_t b = 0, o = 0;
    for (uint32_t t = 0; t < scene->triangle_count; t++) {
        if (scene->materials[scene->tri_material[t]].alpha_mode == SCN_ALPHA_BLEND)
            g->blend[b++] = t;
        else
            g->opaque[o++] = t;
    }
    return true;
}

void gt_seethrough_free(gt_seethrough* g)
{
    free(g->blend);
    free(g->opaque);
    free(g->ids);
    free(g->depth);
    free(g->opaque_depth);
    memset(g, 0, sizeof *g);
}

bool gt_seethrough_sample(gt_seethrough* g, rnd_context* ctx, rnd_target* target, const rnd_gpu_scene* gpu,
                          const rnd_camera* cam, size_t pixels, const uint8_t* pvs_mask, const uint8_t* unreliable,
                          uint32_t triangle_count, uint32_t* ids, uint8_t* gt, size_t* fn, size_t* fn_rel)
{
    assert(g->blend_count > 0);
    if (!rnd_draw(ctx, target, gpu, cam, g->opaque, g->opaque_count, NULL) || !rnd_target_read_ids(ctx, target, ids) ||
        !rnd_target_read_depth(ctx, target, g->opaque_depth))
        return false;
    uint32_t left = g->blend_count, peel = 0;
    while (left > 0 && peel < GT_SEETHROUGH_MAX_PEELS) {
        peel++;
        if (!rnd_draw(ctx, target, gpu, cam, g->blend, left, NULL) || !rnd_target_read_ids(ctx, target, g->ids) ||
            !rnd_target_read_depth(ctx, target, g->depth))
            return false;
        bool found = false;
        for (size_t px = 0; px < pixels; px++) {
            uint32_t t = g->ids[px];
            if (t >= triangle_count || !(g->depth[px] < g->opaque_depth[px]))
                continue;
            found = true;
            gt[t] |= 2; /* seen in this sample: dropped below */
            bool opaque_ok = ids[px] >= triangle_count || pvs_mask[ids[px]];
            if (!pvs_mask[t] && opaque_ok) {
                (*fn)++;
                *fn_rel += !unreliable[t];
            }
        }
        if (!found)
            break;
        for (uint32_t i = 0; i < left;) { /* the dropped ones swap behind the ones left */
            uint32_t t = g->blend[i];
            if (gt[t] & 2) {
                gt[t] = 1;
                g->blend[i] = g->blend[--left];
                g->blend[left] = t;
            } else {
                i++;
            }
        }
    }
    g->peels = peel > g->peels ? peel : g->peels;
    return true;
}
