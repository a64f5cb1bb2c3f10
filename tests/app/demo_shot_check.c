/* demo_shot_check SHOT LEFT RIGHT WRONG: checks a `trimvr demo` screenshot
 * (both eyes side by side, read back from the swapchain) against `trimvr
 * render --stereo` images of the same pose: each half must match its own eye
 * (a broken copy, flipped rows or scaling fail this), match it clearly better
 * than the other eye (swapped eyes fail this), and WRONG, the same eye at
 * another pose, must not match (so a wrong pose fails). */
#include "image_compare.h"
#include "image_io.h"
#include "test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MATCH_DB 40.0 /* same pose and view: bit-identical in practice (inf) */

static uint8_t* load(const char* file, uint32_t* w, uint32_t* h)
{
    uint8_t* rgba = NULL;
    char err[512];
    if (!scn_image_read(file, &rgba, w, h, err, sizeof err))
        fprintf(stderr, "%s\n", err);
    return rgba;
}

/* One eye's half of the side-by-side screenshot. */
static uint8_t* half(const uint8_t* shot, uint32_t w, uint32_t h, int eye)
{
    uint8_t* out = malloc((size_t)w * h * 4);
    for (uint32_t y = 0; y < h; y++)
        memcpy(out + (size_t)y * w * 4, shot + ((size_t)y * 2 * w + (size_t)eye * w) * 4, (size_t)w * 4);
    return out;
}

/* Standard deviation of the green channel: a blank or single-colour image has ~0. */
static double spread(const uint8_t* rgba, size_t pixels)
{
    double sum = 0.0, sq = 0.0;
    for (size_t i = 0; i < pixels; i++) {
        sum += rgba[4 * i + 1];
        sq += (double)rgba[4 * i + 1] * rgba[4 * i + 1];
    }
    double mean = sum / pixels;
    return sqrt(sq / pixels - mean * mean);
}

/* Share of pixels in Figure 1's blue (false positives) and grey (culled). */
static void figure1_shares(const uint8_t* rgba, size_t pixels, double* blue, double* grey)
{
    size_t b = 0, g = 0;
    for (size_t i = 0; i < pixels; i++) {
        const uint8_t* p = rgba + 4 * i;
        b += p[2] > p[0] + 60 && p[2] > p[1] + 30;
        g += p[0] == p[1] && p[1] == p[2] && p[0] >= 40 && p[0] <= 104;
    }
    *blue = (double)b / (double)pixels;
    *grey = (double)g / (double)pixels;
}

/* --overview SHOT LEFT: the left half is the left eye, the right half the
 * Figure 1 overview, which must show false positives (blue) and culled
 * triangles (grey) beside shaded ones. */
static int check_overview(const char* shot_file, const char* left_file)
{
    uint32_t sw, sh, w, h;
    uint8_t* shot = load(shot_file, &sw, &sh);
    uint8_t* left = load(left_file, &w, &h);
    TV_CHECK(shot && left && sw == 2 * w && sh == h);
    if (!shot || !left || sw != 2 * w || sh != h)
        return tv_test_finish();
    size_t pixels = (size_t)w * h;
    uint8_t* eye[2] = {half(shot, w, h, 0), half(shot, w, h, 1)};
    double psnr = rnd_psnr_rgb8(eye[0], left, pixels, 4), blue, grey, eye_blue, eye_grey;
    figure1_shares(eye[1], pixels, &blue, &grey);
    figure1_shares(eye[0], pixels, &eye_blue, &eye_grey);
    printf("overview %ux%u: left eye %.1f dB; overview blue %.1f%%, grey %.1f%% (left eye: %.1f%%, %.1f%%)\n", sw,
           sh, psnr, 100.0 * blue, 100.0 * grey, 100.0 * eye_blue, 100.0 * eye_grey);
    TV_CHECK(psnr >= MATCH_DB);
    TV_CHECK(blue > 0.01 && grey > 0.01 && blue + grey < 0.99); /* all three classes on screen */
    TV_CHECK(eye_blue < 0.005);                                 /* the eye itself is not recoloured */
    free(eye[0]);
    free(eye[1]);
    scn_image_free(left);
    scn_image_free(shot);
    return tv_test_finish();
}

int main(int argc, char** argv)
{
    if (argc == 4 && strcmp(argv[1], "--overview") == 0)
        return check_overview(argv[2], argv[3]);
    if (argc != 5) {
        fprintf(stderr, "usage: demo_shot_check SHOT LEFT RIGHT WRONG | --overview SHOT LEFT\n");
        return 2;
    }
    uint32_t sw, sh, w[3], h[3];
    uint8_t* shot = load(argv[1], &sw, &sh);
    uint8_t* ref[3];
    for (int i = 0; i < 3; i++)
        ref[i] = load(argv[2 + i], &w[i], &h[i]);
    TV_CHECK(shot && ref[0] && ref[1] && ref[2]);
    if (!shot || !ref[0] || !ref[1] || !ref[2])
        return tv_test_finish();
    TV_CHECK(sw == 2 * w[0] && sh == h[0] && w[1] == w[0] && w[2] == w[0]);
    if (sw != 2 * w[0] || sh != h[0])
        return tv_test_finish();
    size_t pixels = (size_t)w[0] * h[0];
    uint8_t* eye[2] = {half(shot, w[0], h[0], 0), half(shot, w[0], h[0], 1)};
    double left = rnd_psnr_rgb8(eye[0], ref[0], pixels, 4), right = rnd_psnr_rgb8(eye[1], ref[1], pixels, 4);
    double crossed = rnd_psnr_rgb8(eye[0], ref[1], pixels, 4), wrong = rnd_psnr_rgb8(eye[0], ref[2], pixels, 4);
    printf("screenshot %ux%u: left %.1f dB, right %.1f dB, left vs right eye %.1f dB, left vs other pose %.1f dB, "
           "spread %.1f\n",
           sw, sh, left, right, crossed, wrong, spread(shot, (size_t)sw * sh));
    TV_CHECK(spread(shot, (size_t)sw * sh) > 10.0); /* not blank */
    TV_CHECK(left >= MATCH_DB);
    TV_CHECK(right >= MATCH_DB);
    TV_CHECK(crossed < MATCH_DB && crossed < left - 5.0);
    TV_CHECK(wrong < MATCH_DB);
    free(eye[0]);
    free(eye[1]);
    for (int i = 0; i < 3; i++)
        scn_image_free(ref[i]);
    scn_image_free(shot);
    return tv_test_finish();
}
