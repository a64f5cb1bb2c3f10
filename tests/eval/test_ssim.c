/* Unit tests of eval/ssim against values derived on paper from the
 * definition (Wang et al. 2004): C1 = (0.01 * 255)^2, C2 = (0.03 * 255)^2,
 * 11 x 11 Gaussian window of sigma 1.5, mean over the windows inside the
 * image. */
#include "ssim.h"
#include "test.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#define C1 (2.55 * 2.55)
#define C2 (7.65 * 7.65)

/* The luminance factor of one window: means mx, my. */
static double lum(double mx, double my)
{
    return (2.0 * mx * my + C1) / (mx * mx + my * my + C1);
}

/* The window's 1-D weights written out from the definition, independently
 * of the library: exp(-d^2 / 4.5), d = -5..5, over their sum. */
static void weights(double w[11])
{
    double sum = 0.0;
    for (int k = 0; k < 11; k++) {
        w[k] = exp(-(k - 5) * (k - 5) / 4.5);
        sum += w[k];
    }
    for (int k = 0; k < 11; k++)
        w[k] /= sum;
}

/* Deterministic N(0, sigma^2) samples (xorshift + Box-Muller). */
static double gauss(uint64_t* s, double sigma)
{
    double u[2];
    for (int i = 0; i < 2; i++) {
        *s ^= *s << 13;
        *s ^= *s >> 7;
        *s ^= *s << 17;
        u[i] = ((*s >> 11) + 0.5) / 9007199254740992.0;
    }
    return sigma * sqrt(-2.0 * log(u[0])) * cos(6.283185307179586 * u[1]);
}

static void window_is_the_stated_gaussian(void)
{
    double w[RND_SSIM_WINDOW], ref[11], sum = 0.0;
    rnd_ssim_weights(w);
    weights(ref);
    for (int k = 0; k < RND_SSIM_WINDOW; k++) {
        TV_CHECK_NEAR(w[k], ref[k], 1e-15);
        TV_CHECK_NEAR(w[k], w[RND_SSIM_WINDOW - 1 - k], 0.0);
        sum += w[k];
    }
    TV_CHECK_NEAR(sum, 1.0, 1e-15);
    TV_CHECK_NEAR(w[5] / w[4], exp(1.0 / 4.5), 1e-12);
}

static void identical_images_give_one(void)
{
    enum { W = 40, H = 23 };
    static uint8_t a[W * H * 4];
    for (size_t i = 0; i < sizeof a; i++)
        a[i] = (uint8_t)(i * 37 + (i >> 5));
    double* scratch = malloc(rnd_ssim_scratch_count(W, H) * sizeof *scratch);
    TV_CHECK(rnd_ssim_rgb8(a, a, W, H, 4, scratch) == 1.0);
    TV_CHECK(rnd_ssim_rgb8(a, a, W, H, 3, scratch) == 1.0);
    free(scratch);
}

static void smaller_than_a_window_has_none(void)
{
    uint8_t a[10 * 30 * 3] = {0};
    double scratch[2 * 10 * 30 + 5 * 30];
    TV_CHECK(isnan(rnd_ssim_rgb8(a, a, 10, 30, 3, scratch)));
    TV_CHECK(isnan(rnd_ssim_rgb8(a, a, 30, 10, 3, scratch)));
    TV_CHECK(rnd_ssim_rgb8(a, a, 11, 11, 3, scratch) == 1.0); /* exactly one window */
}

/* Constant images a and a + c: every window has zero variance, so the
 * contrast-structure factor is C2 / C2 and SSIM = (2a(a+c) + C1) / (a^2 +
 * (a+c)^2 + C1). The offset goes into red only, so the luma weight 0.299
 * is checked too; alpha differs and must not count. */
static void constant_offset_is_the_luminance_term(void)
{
    enum { W = 16, H = 12 };
    static uint8_t a[W * H * 4], b[W * H * 4];
    for (int p = 0; p < W * H; p++) {
        for (int k = 0; k < 3; k++)
            a[4 * p + k] = b[4 * p + k] = 100;
        b[4 * p] = 140;
        a[4 * p + 3] = 255;
        b[4 * p + 3] = 0;
    }
    double scratch[2 * W * H + 5 * W];
    double y = 100.0 + 0.299 * 40.0;
    TV_CHECK_NEAR(rnd_ssim_rgb8(a, b, W, H, 4, scratch), lum(100.0, y), 1e-12);
    TV_CHECK_NEAR(rnd_ssim_rgb8(b, a, W, H, 4, scratch), lum(100.0, y), 1e-12);
    /* green weight: black against pure green 200 */
    for (int p = 0; p < W * H; p++) {
        a[4 * p] = a[4 * p + 1] = a[4 * p + 2] = 0;
        b[4 * p] = b[4 * p + 2] = 0;
        b[4 * p + 1] = 200;
    }
    TV_CHECK_NEAR(rnd_ssim_rgb8(a, b, W, H, 4, scratch), lum(0.0, 0.587 * 200.0), 1e-12);
}

/* A horizontal ramp x = a + g j and y = x + c. A symmetric window's mean of
 * a linear function is its value at the centre, and x and y have the same
 * variance and covariance in every window, so the structure factor is 1
 * and each window scores lum(a + g j0, a + g j0 + c) at its centre column j0. */
static void offset_on_a_ramp_keeps_structure(void)
{
    enum { W = 64, H = 20 };
    const double a = 40.0, g = 1.0, c = 30.0;
    static double x[W * H], y[W * H], scratch[5 * W];
    for (int i = 0; i < H; i++)
        for (int j = 0; j < W; j++) {
            x[i * W + j] = a + g * j;
            y[i * W + j] = x[i * W + j] + c;
        }
    double expect = 0.0;
    for (int j0 = 5; j0 <= W - 6; j0++)
        expect += lum(a + g * j0, a + g * j0 + c) / (W - 10);
    TV_CHECK_NEAR(rnd_ssim_luma(x, y, W, H, scratch), expect, 1e-9);
    TV_CHECK(expect < 0.95); /* the offset is visible: not 1 */
}

/* Stripes one pixel wide, x = a + b (-1)^j, blurred by averaging each pixel
 * with its neighbour: y = a everywhere (all structure gone). Per window:
 * mx = a + b e (-1)^j0 with e = sum_k w_k (-1)^(k-5), sx^2 = b^2 (1 - e^2),
 * sy = sxy = 0, so SSIM = lum(mx, a) * C2 / (sx^2 + C2). */
static void blur_that_removes_stripes(void)
{
    enum { W = 48, H = 16 };
    const double a = 120.0, b = 40.0;
    static double x[W * H], y[W * H], scratch[5 * W];
    for (int i = 0; i < H; i++)
        for (int j = 0; j < W; j++) {
            x[i * W + j] = a + ((j & 1) ? -b : b);
            int n = j + 1 < W ? j + 1 : j - 1;
            y[i * W + j] = 0.5 * (x[i * W + j] + a + ((n & 1) ? -b : b));
        }
    double w[11], e = 0.0;
    weights(w);
    for (int k = 0; k < 11; k++)
        e += ((k - 5) & 1 ? -w[k] : w[k]);
    double expect = 0.0;
    for (int j0 = 5; j0 <= W - 6; j0++) {
        double mx = a + b * e * ((j0 & 1) ? -1.0 : 1.0);
        expect += lum(mx, a) * C2 / (b * b * (1.0 - e * e) + C2) / (W - 10);
    }
    TV_CHECK_NEAR(rnd_ssim_luma(x, y, W, H, scratch), expect, 1e-9);
    TV_CHECK_NEAR(expect, C2 / (b * b + C2), 1e-3); /* e is tiny: about C2 / (b^2 + C2) */
}

/* Independent Gaussian noise of variance s2 on an image whose windows all
 * have variance v and mean near a. A weighted window's variance estimate has
 * expectation s2 (1 - S) with S = sum of the squared 2-D weights (the mean is
 * estimated too), and the cross term has expectation 0, so the structure
 * factor is near (2v + C2) / (2v + s2 (1 - S) + C2). For a flat image (v = 0)
 * the second-order term of E[C2 / (X + C2)], with Var X = 2 s2^2 S for
 * Gaussian noise, is added; luminance stays within 1e-4 of 1. */
static void noise_lowers_structure_as_derived(void)
{
    enum { W = 256, H = 256 };
    static double x[W * H], y[W * H], scratch[5 * W];
    double w[11], s1 = 0.0;
    weights(w);
    for (int k = 0; k < 11; k++)
        s1 += w[k] * w[k];
    const double S = s1 * s1;
    uint64_t seed = 0x9E3779B97F4A7C15ull;
    const double a = 128.0, s = 5.0, s2 = s * s;
    for (int p = 0; p < W * H; p++) {
        x[p] = a;
        y[p] = a + gauss(&seed, s);
    }
    double m = s2 * (1.0 - S), flat = C2 / (m + C2) + C2 * 2.0 * s2 * s2 * S / pow(m + C2, 3.0);
    TV_CHECK_NEAR(rnd_ssim_luma(x, y, W, H, scratch), flat, 0.003);
    TV_CHECK(flat < 0.75);
    /* checkerboard a +- 20 (variance 400 in every window, to within e^2) with noise of sd 10 */
    const double b = 20.0, n = 10.0;
    for (int i = 0; i < H; i++)
        for (int j = 0; j < W; j++) {
            x[i * W + j] = a + (((i + j) & 1) ? -b : b);
            y[i * W + j] = x[i * W + j] + gauss(&seed, n);
        }
    double v = b * b, board = (2.0 * v + C2) / (2.0 * v + n * n * (1.0 - S) + C2);
    TV_CHECK_NEAR(rnd_ssim_luma(x, y, W, H, scratch), board, 0.003);
    TV_CHECK(board < 0.92);
}

int main(void)
{
    TV_TEST_RUN(window_is_the_stated_gaussian);
    TV_TEST_RUN(identical_images_give_one);
    TV_TEST_RUN(smaller_than_a_window_has_none);
    TV_TEST_RUN(constant_offset_is_the_luminance_term);
    TV_TEST_RUN(offset_on_a_ramp_keeps_structure);
    TV_TEST_RUN(blur_that_removes_stripes);
    TV_TEST_RUN(noise_lowers_structure_as_derived);
    return tv_test_finish();
}
