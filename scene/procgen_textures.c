/* procgen_textures.c - deterministic 256x256 surface textures.
 *
 * Texture detail exists so that a missing triangle changes pixels in the
 * PVS-versus-full comparison: a flat colour would hide a hole behind an
 * identically coloured surface.
 */
#include "procgen.h"

#include <math.h>
#include <stdlib.h>

#define TEX_SIZE 256

/* Hash noise in [0, 1) on an integer lattice, tiled every `period` cells. */
static float _scn_lattice(uint32_t x, uint32_t y, uint32_t period, uint32_t salt)
{
    uint32_t h = (x % period) * 73856093u ^ (y % period) * 19349663u ^ salt * 83492791u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return (float)(h & 0xFFFFFF) / 16777216.0f;
}

/* Tileable value noise with 4 octaves, in [0, 1). */
static float _scn_noise(float x, float y, uint32_t salt)
{
    float sum = 0.0f, amp = 0.5f;
    for (uint32_t octave = 0, cells = 8; octave < 4; octave++, cells *= 2, amp *= 0.5f) {
        float fx = x * cells / TEX_SIZE, fy = y * cells / TEX_SIZE;
        uint32_t ix = (uint32_t)fx, iy = (uint32_t)fy;
        float tx = fx - ix, ty = fy - iy;
        float a = _scn_lattice(ix, iy, cells, salt + octave), b = _scn_lattice(ix + 1, iy, cells, salt + octave);
        float c = _scn_lattice(ix, iy + 1, cells, salt + octave), d = _scn_lattice(ix + 1, iy + 1, cells, salt + octave);
        sum += amp * ((a + (b - a) * tx) * (1 - ty) + (c + (d - c) * tx) * ty);
    }
    return sum / 0.9375f;
}

static void _scn_texel(scn_gen_texture kind, uint32_t x, uint32_t y, float rgb[3])
{
    float n = _scn_noise((float)x, (float)y, (uint32_t)kind);
    switch (kind) {
    case SCN_GEN_TEX_BRICKS: {
        uint32_t row = y / 32, shift = (row & 1) * 32, col = ((x + shift) % TEX_SIZE) / 64;
        bool mortar = y % 32 < 3 || (x + shift) % 64 < 3;
        float tone = 0.75f + 0.25f * _scn_lattice(col, row, 1u << 30, 7);
        float m = mortar ? 0.8f : 1.0f;
        rgb[0] = mortar ? m * 0.75f : tone * (0.62f + 0.2f * n);
        rgb[1] = mortar ? m * 0.72f : tone * (0.30f + 0.1f * n);
        rgb[2] = mortar ? m * 0.68f : tone * (0.22f + 0.08f * n);
        break;
    }
    case SCN_GEN_TEX_FACADE: {
        bool frame = x % 64 < 10 || y % 64 < 12 || x % 64 > 56;
        float v = frame ? 0.70f + 0.2f * n : 0.25f + 0.3f * n * (float)(y % 64) / 64.0f;
        rgb[0] = v, rgb[1] = v * (frame ? 0.95f : 1.05f), rgb[2] = v * (frame ? 0.85f : 1.3f);
        break;
    }
    case SCN_GEN_TEX_CONCRETE:
        rgb[0] = rgb[1] = rgb[2] = 0.45f + 0.35f * n;
        break;
    case SCN_GEN_TEX_TILES: {
        bool grout = x % 32 < 2 || y % 32 < 2;
        float tone = ((x / 32 + y / 32) & 1) ? 0.85f : 0.65f;
        float v = grout ? 0.35f : tone + 0.1f * n;
        rgb[0] = v, rgb[1] = v, rgb[2] = v * 0.95f;
        break;
    }
    default: { /* wood: planks along x with grain rings */
        float grain = 0.5f + 0.5f * sinf((float)y * 0.35f + 12.0f * n);
        bool seam = y % 42 < 2;
        float v = seam ? 0.25f : 0.45f + 0.25f * grain;
        rgb[0] = v * 0.95f, rgb[1] = v * 0.65f, rgb[2] = v * 0.38f;
        break;
    }
    }
}

void scn_gen_add_textures(scn_builder* b)
{
    if (b->count_only)
        return;
    for (int kind = 0; kind < SCN_GEN_TEX_COUNT; kind++) {
        uint8_t* px = malloc((size_t)TEX_SIZE * TEX_SIZE * 4);
        if (!px) {
            b->failed = true;
            return;
        }
        for (uint32_t y = 0; y < TEX_SIZE; y++)
            for (uint32_t x = 0; x < TEX_SIZE; x++) {
                float rgb[3];
                _scn_texel((scn_gen_texture)kind, x, y, rgb);
                uint8_t* p = px + 4 * ((size_t)y * TEX_SIZE + x);
                for (int c = 0; c < 3; c++)
                    p[c] = (uint8_t)lrintf(fminf(fmaxf(rgb[c], 0.0f), 1.0f) * 255.0f);
                p[3] = 255;
            }
        scn_builder_texture(b, TEX_SIZE, TEX_SIZE, px);
    }
}
