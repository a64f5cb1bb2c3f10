#include "rng.h"

#include "pose.h"

#include <math.h>

void pred_rng_seed(pred_rng* rng, uint64_t seed, uint64_t stream)
{
    rng->state = 0u;
    rng->inc = (stream << 1u) | 1u;
    pred_rng_u32(rng);
    rng->state += seed;
    pred_rng_u32(rng);
}

uint32_t pred_rng_u32(pred_rng* rng)
{
    uint64_t old = rng->state;
    rng->state = old * 6364136223846793005ull + rng->inc;
    uint32_t xorshifted = (uint32_t)(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = (uint32_t)(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
}

double pred_rng_uniform(pred_rng* rng)
{
    return pred_rng_u32(rng) * (1.0 / 4294967296.0);
}

double pred_rng_range(pred_rng* rng, double lo, double hi)
{
    return lo + (hi - lo) * pred_rng_uniform(rng);
}

double pred_rng_gauss(pred_rng* rng)
{
    double u1 = 1.0 - pred_rng_uniform(rng); /* (0, 1]: log stays finite */
    double u2 = pred_rng_uniform(rng);
    return sqrt(-2.0 * log(u1)) * cos(2.0 * PRED_PI * u2);
}
