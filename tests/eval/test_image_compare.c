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

/* Figure 1 classes and the red false negatives, per pixel, in place and into RGB. */
static void figure1_and_false_negative_colours(void)
{
    const uint32_t ids[4] = {0, 1, 2, 0xFFFFFFFFu};
    const uint8_t visible[3] = {1, 0, 0}, pvs[3] = {1, 1, 0}; /* 0 visible, 1 false positive, 2 culled */
    uint8_t rgba[4 * 4];
    for (int i = 0; i < 16; i++)
        rgba[i] = (uint8_t)(100 + i);
    uint8_t rgb[4 * 3];
    rnd_colour_figure1(rgba, ids, 4, visible, pvs, 3, rgb, 3);
    TV_CHECK(rgb[0] == 100 && rgb[1] == 101 && rgb[2] == 102);  /* visible: shaded as rendered */
    TV_CHECK(rgb[5] > rgb[3] + 60 && rgb[5] > rgb[4] + 30);     /* false positive: blue */
    TV_CHECK(rgb[6] == rgb[7] && rgb[7] == rgb[8] && rgb[6] < 100); /* culled: dark grey */
    TV_CHECK(rgb[9] == 112 && rgb[10] == 113 && rgb[11] == 114); /* background kept */
    uint8_t in_place[16];
    memcpy(in_place, rgba, sizeof in_place);
    rnd_colour_false_negatives(in_place, ids, 4, pvs, 3, in_place, 4);
    TV_CHECK(memcmp(in_place, rgba, 8) == 0);                          /* in the PVS: unchanged */
    TV_CHECK(in_place[8] > 200 && in_place[9] < 40 && in_place[10] < 40); /* missing: red */
    TV_CHECK(in_place[11] == rgba[11]);                                 /* alpha untouched */
    TV_CHECK(memcmp(in_place + 12, rgba + 12, 4) == 0);                /* background */
}

int main(void)
{
    TV_TEST_RUN(psnr_identical_is_infinite);
    TV_TEST_RUN(psnr_known_difference);
    TV_TEST_RUN(diff_pixels_with_tolerance);
    TV_TEST_RUN(false_negative_pixels);
    TV_TEST_RUN(figure1_and_false_negative_colours);
    return tv_test_finish();
}
