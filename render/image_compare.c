#include "image_compare.h"

#include "config.h"

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

size_t rnd_count_fn_pixels(const uint32_t* full_ids, size_t pixel_count, const uint8_t* tri_in_set,
                           size_t triangle_count)
{
    assert(full_ids && tri_in_set);
    size_t count = 0;
    for (size_t p = 0; p < pixel_count; p++) {
        uint32_t id = full_ids[p];
        if (id == TV_NO_TRIANGLE)
            continue;
        assert(id < triangle_count);
        count += tri_in_set[id] == 0;
    }
    return count;
}
