#include "rng.h"

#include <math.h>

void tv_rng_seed(tv_rng* rng, uint64_t seed, uint64_t stream)
{
    rng->state = 0u;
    rng->inc = (stream << 1u) | 1u;
    tv_rng_u32(rng);
    rng->state += seed;
    tv_rng_u32(rng);
}

uint32_t tv_rng_u32(tv_rng* rng)
{
    uint64_t old = rng->state;
    rng->state = old * 6364136223846793005ull + rng->inc;
    uint32_t xorshifted = (uint32_t)(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = (uint32_t)(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
}

double tv_rng_uniform(tv_rng* rng)
{
    return tv_rng_u32(rng) * (1.0 / 4294967296.0);
}

double tv_rng_range(tv_rng* rng, double lo, double hi)
{
    return lo + (hi - lo) * tv_rng_uniform(rng);
}

double tv_rng_gauss(tv_rng* rng)
{
    double u1 = 1.0 - tv_rng_uniform(rng); /* (0, 1]: log stays finite */
    double u2 = tv_rng_uniform(rng);
    return sqrt(-2.0 * log(u1)) * cos(2.0 * 3.14159265358979323846 * u2);
}
