/* demo_draw.c - bitmap text, panels and lines on RGBA8 canvases. */
#include "demo_draw.h"

#include <assert.h>
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>

static void put(const tv_canvas* c, int x, int y, const uint8_t rgb[3])
{
    if (x < 0 || y < 0 || x >= c->width || y >= c->height)
        return;
    uint8_t* p = c->rgba + ((size_t)y * (size_t)c->width + (size_t)x) * 4;
    p[0] = rgb[0];
    p[1] = rgb[1];
    p[2] = rgb[2];
    p[3] = 255;
}

void tv_text_size(const char* text, int scale, int* width, int* height)
{
    int lines = 1, col = 0, widest = 0;
    for (const char* s = text; *s; s++) {
        if (*s == '\n') {
            lines++;
            col = 0;
            continue;
        }
        if (++col > widest)
            widest = col;
    }
    *width = widest * TV_FONT_CELL_W * scale;
    *height = lines * TV_FONT_CELL_H * scale;
}

void tv_draw_text(const tv_canvas* c, int x, int y, int scale, const char* text, const uint8_t rgb[3])
{
    assert(c && text && scale > 0);
    int cx = x, cy = y;
    for (const char* s = text; *s; s++) {
        if (*s == '\n') {
            cx = x;
            cy += TV_FONT_CELL_H * scale;
            continue;
        }
        unsigned ch = (unsigned char)*s;
        const uint8_t* glyph = tv_font_5x7[(ch >= 32 && ch <= 126 ? ch : '?') - 32];
        for (int row = 0; row < 7; row++)
            for (int col = 0; col < 5; col++)
                if (glyph[row] & (0x10 >> col))
                    for (int dy = 0; dy < scale; dy++)
                        for (int dx = 0; dx < scale; dx++)
                            put(c, cx + col * scale + dx, cy + row * scale + dy, rgb);
        cx += TV_FONT_CELL_W * scale;
    }
}

void tv_draw_panel(const tv_canvas* c, int x, int y, int w, int h, const uint8_t rgb[3], uint8_t alpha)
{
    int x0 = x < 0 ? 0 : x, y0 = y < 0 ? 0 : y;
    int x1 = x + w > c->width ? c->width : x + w, y1 = y + h > c->height ? c->height : y + h;
    for (int py = y0; py < y1; py++)
        for (int px = x0; px < x1; px++) {
            uint8_t* p = c->rgba + ((size_t)py * (size_t)c->width + (size_t)px) * 4;
            for (int k = 0; k < 3; k++)
                p[k] = (uint8_t)((p[k] * (255 - alpha) + rgb[k] * alpha + 127) / 255);
        }
}

/* Liang-Barsky: shrinks [t0, t1] to where p + t*d lies in [lo, hi]. */
static bool clip_axis(float p, float d, float lo, float hi, float* t0, float* t1)
{
    if (d == 0.0f)
        return p >= lo && p <= hi;
    float a = (lo - p) / d, b = (hi - p) / d;
    if (a > b) {
        float t = a;
        a = b;
        b = t;
    }
    *t0 = a > *t0 ? a : *t0;
    *t1 = b < *t1 ? b : *t1;
    return *t0 <= *t1;
}

void tv_draw_line(const tv_canvas* c, float fx0, float fy0, float fx1, float fy1, const uint8_t rgb[3])
{
    float dxf = fx1 - fx0, dyf = fy1 - fy0, t0 = 0.0f, t1 = 1.0f;
    if (!clip_axis(fx0, dxf, 0.0f, (float)c->width - 1.0f, &t0, &t1) ||
        !clip_axis(fy0, dyf, 0.0f, (float)c->height - 1.0f, &t0, &t1))
        return;
    int x0 = (int)lroundf(fx0 + t0 * dxf), y0 = (int)lroundf(fy0 + t0 * dyf);
    int x1 = (int)lroundf(fx0 + t1 * dxf), y1 = (int)lroundf(fy0 + t1 * dyf);
    int dx = abs(x1 - x0), dy = -abs(y1 - y0);
    int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
    int e = dx + dy;
    for (;;) {
        put(c, x0, y0, rgb);
        if (x0 == x1 && y0 == y1)
            break;
        int e2 = 2 * e;
        if (e2 >= dy) {
            e += dy;
            x0 += sx;
        }
        if (e2 <= dx) {
            e += dx;
            y0 += sy;
        }
    }
}
