#include "stats.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int cmp_double(const void* a, const void* b)
{
    double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

double tv_percentile(const double* values, size_t count, double p)
{
    if (count == 0)
        return NAN;
    double* sorted = malloc(count * sizeof *sorted);
    if (!sorted)
        return NAN;
    memcpy(sorted, values, count * sizeof *sorted);
    qsort(sorted, count, sizeof *sorted, cmp_double);
    double rank = (p < 0 ? 0 : p > 100 ? 100 : p) / 100.0 * (double)(count - 1);
    size_t lo = (size_t)floor(rank), hi = (size_t)ceil(rank);
    double frac = rank - (double)lo;
    double result;
    if (frac == 0.0)
        result = sorted[lo];
    else if (isinf(sorted[hi])) /* between x and +inf: inf - inf would give NaN */
        result = sorted[hi];
    else
        result = sorted[lo] + (sorted[hi] - sorted[lo]) * frac;
    free(sorted);
    return result;
}

double tv_mean(const double* values, size_t count)
{
    if (count == 0)
        return NAN;
    double sum = 0.0;
    for (size_t i = 0; i < count; i++)
        sum += values[i];
    return sum / (double)count;
}

double tv_t975(int df)
{
    static const double table[30] = {12.7062, 4.3027, 3.1824, 2.7764, 2.5706, 2.4469, 2.3646, 2.3060, 2.2622, 2.2281,
                                     2.2010,  2.1788, 2.1604, 2.1448, 2.1314, 2.1199, 2.1098, 2.1009, 2.0930, 2.0860,
                                     2.0796,  2.0739, 2.0687, 2.0639, 2.0595, 2.0555, 2.0518, 2.0484, 2.0452, 2.0423};
    if (df < 1)
        return NAN;
    if (df <= 30)
        return table[df - 1];
    const double z = 1.959963984540054, z2 = z * z, v = df;
    return z + z * (z2 + 1.0) / (4.0 * v) + z * ((5.0 * z2 + 16.0) * z2 + 3.0) / (96.0 * v * v) +
           z * (((3.0 * z2 + 19.0) * z2 + 17.0) * z2 - 15.0) / (384.0 * v * v * v);
}

double tv_mean_ci95(const double* values, size_t count)
{
    if (count < 2)
        return NAN;
    double mean = tv_mean(values, count), ss = 0.0;
    for (size_t i = 0; i < count; i++)
        ss += (values[i] - mean) * (values[i] - mean);
    return tv_t975((int)count - 1) * sqrt(ss / (double)(count - 1) / (double)count);
}

double tv_ratio_ci95(const double* x, const double* y, size_t count)
{
    if (count < 2)
        return NAN;
    double mx = tv_mean(x, count), my = tv_mean(y, count);
    if (my == 0.0)
        return NAN;
    double r = mx / my, ss = 0.0;
    for (size_t i = 0; i < count; i++)
        ss += (x[i] - r * y[i]) * (x[i] - r * y[i]);
    return tv_t975((int)count - 1) * sqrt(ss / ((double)count * (double)(count - 1))) / my;
}
