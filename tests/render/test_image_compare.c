/* Unit tests of render/image_compare (pure C). */
#include "image_compare.h"
#include "test.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

static void psnr_identical_is_infinite(void)
{
    uint8_t a[4 * 16];
    for (size_t i = 0; i < sizeof a; i++)
        a[i] = (uint8_t)(i * 7);
    TV_CHECK(isinf(rnd_psnr_rgb8(a, a, 16, 4)) && rnd_psnr_rgb8(a, a, 16, 4) > 0);
}

static void psnr_known_difference(void)
{
    /* 4 RGB pixels, one channel off by 10: MSE = 100 / 12,
     * PSNR = 10 log10(255^2 * 12 / 100) = 38.92262 dB */
    uint8_t a[12] = {10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120};
    uint8_t b[12];
    memcpy(b, a, sizeof a);
    b[7] += 10;
    TV_CHECK_NEAR(rnd_psnr_rgb8(a, b, 4, 3), 38.92261607, 1e-6);
    /* the alpha byte of RGBA input is ignored */
    uint8_t c[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
    uint8_t d[16];
    memcpy(d, c, sizeof c);
    d[3] = 200;
    d[15] = 0;
    TV_CHECK(isinf(rnd_psnr_rgb8(c, d, 4, 4)));
    /* every channel off by 255: PSNR 0 dB */
    uint8_t black[3] = {0, 0, 0}, white[3] = {255, 255, 255};
    TV_CHECK_NEAR(rnd_psnr_rgb8(black, white, 1, 3), 0.0, 1e-12);
}

static void diff_pixels_with_tolerance(void)
{
    uint8_t a[4 * 3] = {0};
    uint8_t b[4 * 3] = {0};
    b[1] = 1;  /* pixel 0: off by 1 */
    b[5] = 9;  /* pixel 1: off by 9 */
    b[9] = 20; /* pixel 3: off by 20 */
    TV_CHECK(rnd_count_diff_pixels(a, b, 4, 3, 0) == 3);
    TV_CHECK(rnd_count_diff_pixels(a, b, 4, 3, 1) == 2);
    TV_CHECK(rnd_count_diff_pixels(a, b, 4, 3, 10) == 1);
    TV_CHECK(rnd_count_diff_pixels(a, b, 4, 3, 20) == 0);
}

static void false_negative_pixels(void)
{
    const uint32_t ids[8] = {0, 1, 2, 0xFFFFFFFFu, 2, 2, 4, 1};
    const uint8_t in_set[5] = {1, 0, 1, 1, 0}; /* 1 and 4 missing */
    TV_CHECK(rnd_count_fn_pixels(ids, 8, in_set, 5) == 3);
    const uint8_t all[5] = {1, 1, 1, 1, 1};
    TV_CHECK(rnd_count_fn_pixels(ids, 8, all, 5) == 0);
    const uint8_t none[5] = {0};
    TV_CHECK(rnd_count_fn_pixels(ids, 8, none, 5) == 7); /* background is never a false negative */
}

int main(void)
{
    TV_TEST_RUN(psnr_identical_is_infinite);
    TV_TEST_RUN(psnr_known_difference);
    TV_TEST_RUN(diff_pixels_with_tolerance);
    TV_TEST_RUN(false_negative_pixels);
    return tv_test_finish();
}
