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
