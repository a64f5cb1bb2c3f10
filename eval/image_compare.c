#include "image_compare.h"

#include "mesh_shared.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>

double rnd_psnr_rgb8(const uint8_t* a, const uint8_t* b, size_t pixel_count, size_t stride)
{
    assert(a && b && pixel_count > 0 && stride >= 3);
    /* exact integer sum: 1280x720x3 channels x 255^2 fits easily in 64 bits */
    uint64_t sum = 0;
    for (size_t p = 0; p < pixel_count; p++) {
        for (size_t c = 0; c < 3; c++) {
            int d = (int)a[p * stride + c] - (int)b[p * stride + c];
            sum += (uint64_t)(d * d);
        }
    }
    if (sum == 0)
        return INFINITY;
    double mse = (double)sum / (double)(pixel_count * 3);
    return 10.0 * log10(255.0 * 255.0 / mse);
}

size_t rnd_count_diff_pixels(const uint8_t* a, const uint8_t* b, size_t pixel_count, size_t stride,
                             uint8_t tolerance)
{
    assert(a && b && stride >= 3);
    size_t count = 0;
    for (size_t p = 0; p < pixel_count; p++) {
        const uint8_t* x = a + p * stride;
        const uint8_t* y = b + p * stride;
        int differs = 0;
        for (size_t c = 0; c < 3; c++)
            differs |= abs((int)x[c] - (int)y[c]) > tolerance;
        count += (size_t)differs;
    }
    return count;
}

size_t rnd_count_fn_pixels_from(const uint32_t* full_ids, size_t pixel_count, const uint8_t* tri_in_set,
                                size_t triangle_count, uint32_t first_id)
{
    assert(full_ids && tri_in_set);
    size_t count = 0;
    if (first_id >= triangle_count) /* no triangle from first_id on (a scene without movers): skip the image */
        return 0;
    for (size_t p = 0; p < pixel_count; p++) {
        uint32_t id = full_ids[p];
        if (id == TV_NO_TRIANGLE || id < first_id)
            continue;
        assert(id < triangle_count);
        count += tri_in_set[id] == 0;
    }
    return count;
}

size_t rnd_count_fn_pixels(const uint32_t* full_ids, size_t pixel_count, const uint8_t* tri_in_set,
                           size_t triangle_count)
{
    return rnd_count_fn_pixels_from(full_ids, pixel_count, tri_in_set, triangle_count, 0);
}

typedef enum colour_class { CLASS_KEEP, CLASS_BLUE, CLASS_GREY, CLASS_RED } colour_class;

/* Recolours one pixel; reads all of c before writing o, so c == o is fine. */
static void paint(const uint8_t* c, colour_class k, uint8_t* o)
{
    int lum = (c[0] * 3 + c[1] * 6 + c[2]) / 10;
    uint8_t r = c[0], g = c[1], b = c[2];
    switch (k) {
    case CLASS_KEEP: break;
    case CLASS_BLUE: r = (uint8_t)(lum / 4), g = (uint8_t)(lum / 3 + 40), b = (uint8_t)(lum / 2 + 127); break;
    case CLASS_GREY: r = g = b = (uint8_t)(lum / 4 + 40); break;
    case CLASS_RED: r = (uint8_t)(200 + r / 5), g = (uint8_t)(g / 4), b = (uint8_t)(b / 4); break;
    }
    o[0] = r, o[1] = g, o[2] = b;
}

void rnd_colour_figure1(const uint8_t* rgba, const uint32_t* ids, size_t pixel_count, const uint8_t* visible,
                        const uint8_t* pvs, size_t triangle_count, uint8_t* out, size_t out_stride)
{
    assert(rgba && ids && visible && pvs && out && (out_stride == 3 || out_stride == 4));
    for (size_t p = 0; p < pixel_count; p++) {
        uint32_t id = ids[p];
        assert(id == TV_NO_TRIANGLE || id < triangle_count);
        colour_class k = id == TV_NO_TRIANGLE ? CLASS_KEEP : visible[id] ? CLASS_KEEP : pvs[id] ? CLASS_BLUE : CLASS_GREY;
        paint(rgba + 4 * p, k, out + out_stride * p);
    }
}

void rnd_colour_false_negatives(const uint8_t* rgba, const uint32_t* ids, size_t pixel_count, const uint8_t* pvs,
                                size_t triangle_count, uint8_t* out, size_t out_stride)
{
    assert(rgba && ids && pvs && out && (out_stride == 3 || out_stride == 4));
    for (size_t p = 0; p < pixel_count; p++) {
        uint32_t id = ids[p];
        assert(id == TV_NO_TRIANGLE || id < triangle_count);
        paint(rgba + 4 * p, id != TV_NO_TRIANGLE && !pvs[id] ? CLASS_RED : CLASS_KEEP, out + out_stride * p);
    }
}
