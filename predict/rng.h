/* rng.h - PCG32 (O'Neill's permuted congruential generator, XSH-RR variant).
 *
 * Everything random in predict/ (path synthesis, sensor noise) draws from a
 * pred_rng seeded by the caller, so a run is reproducible from its seed on
 * every platform. */
#ifndef TRIMVR_PRED_RNG_H
#define TRIMVR_PRED_RNG_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pred_rng {
    uint64_t state;
    uint64_t inc; /* stream selector, always odd */
} pred_rng;

/* Seeds the generator; different `stream` values give independent sequences. */
void pred_rng_seed(pred_rng* rng, uint64_t seed, uint64_t stream);
uint32_t pred_rng_u32(pred_rng* rng);
/* Uniform in [0, 1). */
double pred_rng_uniform(pred_rng* rng);
/* Uniform in [lo, hi). */
double pred_rng_range(pred_rng* rng, double lo, double hi);
/* Standard normal (Box-Muller; one draw per call, the pair's second value is
 * discarded so the sequence does not depend on call parity). */
double pred_rng_gauss(pred_rng* rng);

#ifdef __cplusplus
}
#endif

#endif
