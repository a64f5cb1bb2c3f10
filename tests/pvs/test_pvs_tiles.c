/* The PVS tile grid: tiles cover the image exactly once, each within the
 * pixel budget, with as few tiles as the budget allows. */
#include <stdint.h>

#include "test.h"
#include "tiles.h"

/* Coverage count of every pixel and the budget, for one grid. */
static void check_grid(uint32_t w, uint32_t h, uint64_t max_pixels)
{
    pvs_tile_grid g = pvs_tile_grid_make(w, h, max_pixels);
    TV_CHECK(g.width == w && g.height == h && g.cols > 0 && g.rows > 0);
    TV_CHECK((uint64_t)g.tile_width * g.tile_height <= max_pixels);
    uint64_t fewest = ((uint64_t)w * h + max_pixels - 1) / max_pixels;
    TV_CHECK(pvs_tile_count(&g) >= fewest);
    uint8_t* cover = calloc((size_t)w * h, 1);
    for (uint32_t i = 0; i < pvs_tile_count(&g); i++) {
        pvs_tile t = pvs_tile_get(&g, i);
        TV_CHECK(t.width > 0 && t.height > 0 && t.width <= g.tile_width && t.height <= g.tile_height);
        TV_CHECK(t.x + t.width <= w && t.y + t.height <= h);
        for (uint32_t y = t.y; y < t.y + t.height && y < h; y++)
            for (uint32_t x = t.x; x < t.x + t.width && x < w; x++)
                cover[(size_t)y * w + x]++;
    }
    size_t once = 0;
    for (size_t p = 0; p < (size_t)w * h; p++)
        once += cover[p] == 1;
    TV_CHECK(once == (size_t)w * h);
    free(cover);
}

static void test_tiles_cover_once_within_budget(void)
{
    const uint32_t sizes[][2] = {{512, 512}, {1280, 720}, {1920, 1080}, {640, 360}, {7, 13}, {1, 1}, {1000, 3}};
    const uint64_t budgets[] = {262144, 65536, 4096, 100, 7, 1};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
        for (size_t b = 0; b < sizeof budgets / sizeof budgets[0]; b++)
            if ((uint64_t)sizes[s][0] * sizes[s][1] / budgets[b] < 5000) /* keep the search short */
                check_grid(sizes[s][0], sizes[s][1], budgets[b]);
}

/* The grids the default budget (512 x 512 pixels) gives at the paper's
 * resolutions, and a single tile when the image fits. */
static void test_tiles_paper_resolutions(void)
{
    pvs_tile_grid g = pvs_tile_grid_make(512, 512, 512 * 512);
    TV_CHECK(pvs_tile_count(&g) == 1 && g.tile_width == 512 && g.tile_height == 512);
    g = pvs_tile_grid_make(1280, 720, 512 * 512);
    TV_CHECK(g.cols == 2 && g.rows == 2 && g.tile_width == 640 && g.tile_height == 360);
    g = pvs_tile_grid_make(1920, 1080, 512 * 512);
    TV_CHECK(g.cols == 4 && g.rows == 2 && g.tile_width == 480 && g.tile_height == 540);
    pvs_tile last = pvs_tile_get(&g, 7);
    TV_CHECK(last.x == 1440 && last.y == 540 && last.width == 480 && last.height == 540);
    g = pvs_tile_grid_make(1000, 3, 1002); /* 3 tiles: 334 + 334 + 332 columns */
    TV_CHECK(g.cols == 3 && g.rows == 1 && pvs_tile_get(&g, 2).width == 332);
}

int main(void)
{
    TV_TEST_RUN(test_tiles_cover_once_within_budget);
    TV_TEST_RUN(test_tiles_paper_resolutions);
    return tv_test_finish();
}
