/* rng.h - PCG32 (O'Neill's permuted congruential generator, XSH-RR variant).
 *
 * Everything random (predict/'s path synthesis and sensor noise, scene/'s
 * procedural scenes) draws from a tv_rng seeded by the caller, so a run is
 * reproducible from its seed on every platform. */
#ifndef TRIMVR_BASE_RNG_H
#define TRIMVR_BASE_RNG_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct tv_rng {
    uint64_t state;
    uint64_t inc; /* stream selector, always odd */
} tv_rng;

/* Seeds the generator; different `stream` values give independent sequences. */
void tv_rng_seed(tv_rng* rng, uint64_t seed, uint64_t stream);
uint32_t tv_rng_u32(tv_rng* rng);
/* Uniform in [0, 1). */
double tv_rng_uniform(tv_rng* rng);
/* Uniform in [lo, hi). */
double tv_rng_range(tv_rng* rng, double lo, double hi);
/* Standard normal (Box-Muller; one draw per call, the pair's second value is
 * discarded so the sequence does not depend on call parity). */
double tv_rng_gauss(tv_rng* rng);

#ifdef __cplusplus
}
#endif

#endif
