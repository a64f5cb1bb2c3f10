/* demo_draw.h - CPU drawing into RGBA8 images for the demo's HUD and
 * overlays: bitmap text, translucent panels and clipped lines. The eye
 * images are read back anyway (for the checks and the colour modes), so
 * drawing on the CPU costs one pass over a few thousand pixels and needs no
 * extra pipeline. */
#ifndef TRIMVR_APP_DEMO_DRAW_H
#define TRIMVR_APP_DEMO_DRAW_H

#include <stdint.h>

/* A caller-owned RGBA8 image, rows top to bottom, `width` pixels per row. */
typedef struct tv_canvas {
    uint8_t* rgba;
    int width, height;
} tv_canvas;

/* Printable ASCII 32..126, 7 rows of 5 bits (bit 4 = leftmost). */
extern const uint8_t tv_font_5x7[95][7];

#define TV_FONT_CELL_W 6 /* glyph plus one column of spacing */
#define TV_FONT_CELL_H 9 /* glyph plus two rows of line spacing */

/* Size in pixels of text drawn at `scale` (lines split at '\n'). */
void tv_text_size(const char* text, int scale, int* width, int* height);

/* Draws text with its top-left corner at (x, y), each font pixel a
 * scale x scale block; characters outside 32..126 draw as '?'; anything
 * outside the canvas is clipped. */
void tv_draw_text(const tv_canvas* c, int x, int y, int scale, const char* text, const uint8_t rgb[3]);

/* Blends rgb over the rectangle with opacity alpha (0..255), clipped. */
void tv_draw_panel(const tv_canvas* c, int x, int y, int w, int h, const uint8_t rgb[3], uint8_t alpha);

/* A one-pixel line between two points in pixel coordinates (any finite
 * values: the segment is clipped to the canvas first, then drawn with
 * Bresenham). */
void tv_draw_line(const tv_canvas* c, float x0, float y0, float x1, float y1, const uint8_t rgb[3]);

#endif
