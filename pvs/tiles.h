/* tiles.h - the PVS image split into tiles that each fit the per-pixel
 * buffers.
 *
 * The GPU passes keep per-pixel state (carry, counters, k-buffer heads) whose size
 * follows the pixel count; at the paper's 1920x1080 it exceeds a storage
 * buffer's range on lavapipe (128 MiB). Every pass is per pixel (nothing
 * reads a neighbour's state), so the image is computed tile by tile, each
 * the whole image's draws under a scissor, and the flagged triangles are
 * unioned: a pixel's result does not depend on the tiling. The per-pixel
 * buffers are sized for the largest tile (the visibility-buffer images,
 * 16 B per pixel and not storage buffers, stay whole).
 */
#ifndef TRIMVR_PVS_TILES_H
#define TRIMVR_PVS_TILES_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pvs_tile_grid {
    uint32_t width, height;       /* the whole image */
    uint32_t cols, rows;          /* tiles across and down */
    uint32_t tile_width, tile_height; /* the largest tile (the first); the last column/row may be smaller */
} pvs_tile_grid;

typedef struct pvs_tile {
    uint32_t x, y, width, height; /* pixels of the image, origin top-left */
} pvs_tile;

/* The fewest tiles of at most `max_pixels` pixels covering width x height
 * (both > 0; max_pixels > 0), of equal size except the last column and row;
 * among grids with as many tiles, the one whose tiles are closest to square.
 * A single tile when the image fits. */
pvs_tile_grid pvs_tile_grid_make(uint32_t width, uint32_t height, uint64_t max_pixels);

static inline uint32_t pvs_tile_count(const pvs_tile_grid* g) { return g->cols * g->rows; }

/* Tile `index` (< pvs_tile_count), row by row. */
pvs_tile pvs_tile_get(const pvs_tile_grid* g, uint32_t index);

#ifdef __cplusplus
}
#endif

#endif
