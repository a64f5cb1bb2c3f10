/* resolve_harness.h - one pixel of P3 driven by lists of fragments, for the
 * trim-sequence resolve tests (test_pvs_resolve*.c). Depths are arbitrary
 * monotonic units; F/B/T/U build fronts (triangle id), backs, trims and
 * umbrae (trim-region id), C candidate fronts. CHECK_OUT and CHECK_NONE need
 * test.h, which the test files include. */
#ifndef TRIMVR_TESTS_RESOLVE_HARNESS_H
#define TRIMVR_TESTS_RESOLVE_HARNESS_H

#include "resolve.h"

#include <stdbool.h>
#include <stdint.h>

typedef struct item {
    uint32_t kind;
    float depth;
    uint32_t id;
} item;

#define BACK_ID 500u
#define F(d, id) {TV_ENTRY_FRONT, d, id}
#define B(d) {TV_ENTRY_BACK, d, BACK_ID} /* every back is one triangle: its id only matters when output */
#define BI(d, id) {TV_ENTRY_BACK, d, id}
#define T(d, r) {TV_ENTRY_TRIM, d, r}
#define U(d, r) {TV_ENTRY_UMBRA, d, r}

typedef struct layer_result {
    uint32_t out[PVS_RESOLVE_MAX_OUTPUT];
    uint32_t count;
    uint32_t spilled[64]; /* fronts P2 could not store */
    uint32_t spilled_count;
    uint32_t spill_out; /* how many of them pvs_spill_output adds to the PVS ... */
    uint32_t spill_ids[64]; /* ... and their ids */
    uint32_t pages_taken;   /* k-buffer pages asked for */
    bool overflowed;
} layer_result;

/* Pages of the k-buffer pool each run_layer* gets (at most
 * HARNESS_MAX_PAGES, which holds every list of one pixel at K). */
#define HARNESS_MAX_PAGES (TV_PVS_LISTS * TV_K_FRONT / TV_PVS_PAGE)
extern uint32_t harness_pages;
/* pvs_kbuf.k_exact of each run_layer* (0: none, no pixel is deep). */
extern uint32_t harness_k_exact;
/* pvs_kbuf.k_lists of each run_layer* (0: TV_K_FRONT, TV_K_BACK). */
extern uint32_t harness_k_lists;
/* Front patches (pvs/patches.h): run_layer_kept's P2 labels a front with harness_tri_patch (NULL: every front
 * TV_PVS_PATCH_NONE); the resolve reads region id r's label at harness_region_patch[r] (NULL: none known). */
extern uint32_t (*harness_tri_patch)(uint32_t id);
extern const uint32_t* harness_region_patch;
extern uint32_t harness_region_patches;


/* One layer: pushes `items` into a k-buffer as P2 would (prior_front /
 * prior_back: P2's nearest front / back depth at the pixel centre over this
 * and the earlier layers, 0: none), resolves the pixel and asks
 * pvs_spill_output about the fronts that did not fit. */
layer_result run_layer_prior(pvs_pixel_state* s, float prior_front, float prior_back, const item* items, uint32_t n);
layer_result run_layer(pvs_pixel_state* s, const item* items, uint32_t n);
/* The same with the prior faces P2 keeps from the layers run this way (pvs_centre_store): `centre`, one
 * TV_PVS_CENTRE_STRIDE entry as the GPU's, all INFINITY before the first layer. */
layer_result run_layer_kept(pvs_pixel_state* s, float centre[TV_PVS_CENTRE_STRIDE], const item* items, uint32_t n);

/* Output equals exactly the ids in `want` (order free). */
bool same_set(const layer_result* r, const uint32_t* want, uint32_t n);

#define CHECK_OUT(r, ...)                                                       \
    do {                                                                        \
        const uint32_t want_[] = {__VA_ARGS__};                                 \
        TV_CHECK(same_set(&(r), want_, sizeof want_ / sizeof want_[0]));        \
    } while (0)
#define CHECK_NONE(r) TV_CHECK((r).count == 0)
#define RUN(s, ...)                                                             \
    run_layer(&(s), (const item[]){__VA_ARGS__}, sizeof((const item[]){__VA_ARGS__}) / sizeof(item))

#define RUN_PRIOR(s, f, b, ...)                                                 \
    run_layer_prior(&(s), f, b, (const item[]){__VA_ARGS__}, sizeof((const item[]){__VA_ARGS__}) / sizeof(item))

#define C(d, id) {TV_ENTRY_FRONT, d, (id) | TV_ID_CANDIDATE}
#define RUN_KEPT(s, centre, ...)                                                \
    run_layer_kept(&(s), centre, (const item[]){__VA_ARGS__}, sizeof((const item[]){__VA_ARGS__}) / sizeof(item))

#endif
