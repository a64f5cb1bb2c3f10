/* textures.c - packs a scene's textures into the layers of one sRGB 2D array
 * image. lavapipe supports neither descriptor indexing nor dynamic indexing
 * of sampler arrays, so the layer index (a texture coordinate) is what lets
 * one draw use any number of textures. Layers share one size: the largest
 * texture's, capped at TV_MAX_TEXTURE_SIZE; smaller or larger textures are
 * resampled bilinearly (on the sRGB-encoded values, a small error accepted
 * for simplicity), so repeat wrapping still works per layer. */
#include "render_vk.h"

#include "mesh_shared.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint32_t min_u32(uint32_t a, uint32_t b) { return a < b ? a : b; }

/* Bilinear resample of src (sw x sh) into dst (dw x dh), texel centres
 * aligned, edges clamped. */
static void resample(const uint8_t* src, uint32_t sw, uint32_t sh, uint8_t* dst, uint32_t dw, uint32_t dh)
{
    for (uint32_t y = 0; y < dh; y++) {
        float fy = ((float)y + 0.5f) * (float)sh / (float)dh - 0.5f;
        int y0 = fy < 0 ? 0 : (int)fy;
        int y1 = min_u32((uint32_t)y0 + 1, sh - 1);
        float ty = fy < 0 ? 0.0f : fy - (float)y0;
        for (uint32_t x = 0; x < dw; x++) {
            float fx = ((float)x + 0.5f) * (float)sw / (float)dw - 0.5f;
            int x0 = fx < 0 ? 0 : (int)fx;
            int x1 = min_u32((uint32_t)x0 + 1, sw - 1);
            float tx = fx < 0 ? 0.0f : fx - (float)x0;
            for (int c = 0; c < 4; c++) {
                float a = src[4 * ((size_t)y0 * sw + x0) + c], b = src[4 * ((size_t)y0 * sw + x1) + c];
                float d = src[4 * ((size_t)y1 * sw + x0) + c], e = src[4 * ((size_t)y1 * sw + x1) + c];
                float top = a + (b - a) * tx, bottom = d + (e - d) * tx;
                dst[4 * ((size_t)y * dw + x) + c] = (uint8_t)(top + (bottom - top) * ty + 0.5f);
            }
        }
    }
}

bool rnd_texture_array_create(rnd_context* ctx, VkCommandBuffer cmd, rnd_staging* staging, const scn_scene* s,
                              rnd_image* out, char* err, size_t err_size)
{
    uint32_t w = 1, h = 1;
    for (uint32_t i = 0; i < s->texture_count; i++) {
        w = s->textures[i].width > w ? s->textures[i].width : w;
        h = s->textures[i].height > h ? s->textures[i].height : h;
    }
    w = min_u32(w, TV_MAX_TEXTURE_SIZE);
    h = min_u32(h, TV_MAX_TEXTURE_SIZE);
    /* a scene without textures still binds one white layer */
    uint32_t layers = s->texture_count ? s->texture_count : 1;
    if (layers > ctx->props.limits.maxImageArrayLayers) {
        snprintf(err, err_size, "scene %s: %u textures, over this device's maxImageArrayLayers (%u)", s->name,
                 layers, ctx->props.limits.maxImageArrayLayers);
        return false;
    }
    const size_t layer_bytes = (size_t)w * h * 4;
    uint8_t* texels = malloc(layer_bytes * layers);
    if (!texels) {
        snprintf(err, err_size, "scene %s: out of memory packing %u textures of %ux%u", s->name, layers, w, h);
        return false;
    }
    if (s->texture_count == 0)
        memset(texels, 255, layer_bytes);
    for (uint32_t i = 0; i < s->texture_count; i++) {
        const scn_texture* t = &s->textures[i];
        if (t->width == w && t->height == h)
            memcpy(texels + i * layer_bytes, t->rgba8, layer_bytes);
        else
            resample(t->rgba8, t->width, t->height, texels + i * layer_bytes, w, h);
    }
    bool ok = rnd_image_create(ctx, w, h, layers, VK_IMAGE_VIEW_TYPE_2D_ARRAY, VK_FORMAT_R8G8B8A8_SRGB,
                               VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, out, err, err_size) &&
              rnd_upload_image(ctx, cmd, staging, texels, layer_bytes * layers, out, err, err_size);
    free(texels);
    return ok;
}
