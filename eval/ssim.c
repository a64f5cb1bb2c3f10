#include "ssim.h"

#include <assert.h>
#include <math.h>

#define K1 0.01
#define K2 0.03
#define SIGMA 1.5

void rnd_ssim_weights(double w[RND_SSIM_WINDOW])
{
    double sum = 0.0;
    for (int k = 0; k < RND_SSIM_WINDOW; k++) {
        double d = k - RND_SSIM_WINDOW / 2;
        w[k] = exp(-d * d / (2.0 * SIGMA * SIGMA));
        sum += w[k];
    }
    for (int k = 0; k < RND_SSIM_WINDOW; k++)
        w[k] /= sum;
}

size_t rnd_ssim_scratch_count(uint32_t width, uint32_t height)
{
    return 2 * (size_t)width * height + 5 * (size_t)width;
}

double rnd_ssim_rgb8(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height, size_t stride,
                     double* scratch)
{
    assert(a && b && scratch && stride >= 3);
    size_t pixels = (size_t)width * height;
    double *x = scratch, *y = scratch + pixels;
    for (size_t p = 0; p < pixels; p++) {
        const uint8_t *pa = &a[p * stride], *pb = &b[p * stride];
        x[p] = 0.299 * pa[0] + 0.587 * pa[1] + 0.114 * pa[2];
        y[p] = 0.299 * pb[0] + 0.587 * pb[1] + 0.114 * pb[2];
    }
    return rnd_ssim_luma(x, y, width, height, scratch + 2 * pixels);
}

/* The window is separable: for each output row, the vertical weighted sums
 * of x, y, x^2, y^2 and xy over its 11 image rows (one value per column, in
 * scratch), then the horizontal sums of those give each window's moments.
 * Memory stays 5 columns' worth whatever the image height. */
double rnd_ssim_luma(const double* x, const double* y, uint32_t width, uint32_t height, double* scratch)
{
    assert(x && y && scratch);
    const int n = RND_SSIM_WINDOW;
    if (width < (uint32_t)n || height < (uint32_t)n)
        return NAN;
    double w[RND_SSIM_WINDOW];
    rnd_ssim_weights(w);
    const double c1 = (K1 * 255.0) * (K1 * 255.0), c2 = (K2 * 255.0) * (K2 * 255.0);
    double *vx = scratch, *vy = vx + width, *vxx = vy + width, *vyy = vxx + width, *vxy = vyy + width;
    double sum = 0.0;
    for (uint32_t r = 0; r + n <= height; r++) {
        for (uint32_t c = 0; c < width; c++) {
            double sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0, sxy = 0.0;
            for (int k = 0; k < n; k++) {
                size_t p = (size_t)(r + k) * width + c;
                double px = x[p], py = y[p];
                sx += w[k] * px;
                sy += w[k] * py;
                sxx += w[k] * px * px;
                syy += w[k] * py * py;
                sxy += w[k] * px * py;
            }
            vx[c] = sx;
            vy[c] = sy;
            vxx[c] = sxx;
            vyy[c] = syy;
            vxy[c] = sxy;
        }
        for (uint32_t c = 0; c + n <= width; c++) {
            double mx = 0.0, my = 0.0, exx = 0.0, eyy = 0.0, exy = 0.0;
            for (int k = 0; k < n; k++) {
                mx += w[k] * vx[c + k];
                my += w[k] * vy[c + k];
                exx += w[k] * vxx[c + k];
                eyy += w[k] * vyy[c + k];
                exy += w[k] * vxy[c + k];
            }
            double sx2 = exx - mx * mx, sy2 = eyy - my * my, sxy = exy - mx * my;
            sum += (2.0 * mx * my + c1) * (2.0 * sxy + c2) / ((mx * mx + my * my + c1) * (sx2 + sy2 + c2));
        }
    }
    return sum / ((double)(width - n + 1) * (height - n + 1));
}
