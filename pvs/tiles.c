#include "tiles.h"

#include <assert.h>

static uint32_t ceil_div(uint32_t a, uint32_t b) { return (a + b - 1) / b; }

pvs_tile_grid pvs_tile_grid_make(uint32_t width, uint32_t height, uint64_t max_pixels)
{
    assert(width > 0 && height > 0 && max_pixels > 0);
    pvs_tile_grid best = {0};
    /* No fewer than the pixel count allows; width * height one-pixel tiles
     * always fit, so the loop ends. */
    uint64_t pixels = (uint64_t)width * height;
    for (uint64_t n = (pixels + max_pixels - 1) / max_pixels; best.cols == 0; n++) {
        uint64_t best_skew = UINT64_MAX;
        for (uint64_t cols = 1; cols <= n && cols <= width; cols++) {
            uint64_t rows = n / cols;
            if (cols * rows != n || rows > height)
                continue;
            uint32_t tw = ceil_div(width, (uint32_t)cols), th = ceil_div(height, (uint32_t)rows);
            /* ceil_div may leave trailing tiles empty (e.g. 5 columns of 3 pixels): skip such grids */
            if ((uint64_t)tw * th > max_pixels || ceil_div(width, tw) != cols || ceil_div(height, th) != rows)
                continue;
            uint64_t skew = tw > th ? tw - th : th - tw;
            if (skew < best_skew) {
                best_skew = skew;
                best = (pvs_tile_grid){width, height, (uint32_t)cols, (uint32_t)rows, tw, th};
            }
        }
    }
    return best;
}

pvs_tile pvs_tile_get(const pvs_tile_grid* g, uint32_t index)
{
    assert(index < pvs_tile_count(g));
    uint32_t cx = index % g->cols, cy = index / g->cols;
    pvs_tile t = {cx * g->tile_width, cy * g->tile_height, g->tile_width, g->tile_height};
    if (t.x + t.width > g->width)
        t.width = g->width - t.x;
    if (t.y + t.height > g->height)
        t.height = g->height - t.y;
    return t;
}
