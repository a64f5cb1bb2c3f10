/* Two threads drawing and reading back at once, each on its own target,
 * sharing one context, one queue and one uploaded scene: every result must
 * equal the single-threaded reference. */
#include "render_fixture.h"
#include "test.h"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#define W 80
#define H 48
#define N (W * H)
#define DRAWS 12

static rnd_context* ctx;
static rnd_gpu_scene* gpu;
static uint32_t reference_full[N], reference_subset[N];
static const uint32_t subset_ids[4] = {4, 5, 2, 3}; /* quads 1 and 2 */

typedef struct worker {
    int use_subset;
    int mismatches;
    int failures;
} worker;

static void* run(void* arg)
{
    worker* w = arg;
    char err[256];
    rnd_target* t = rnd_target_create(ctx, W, H, err, sizeof err);
    uint32_t* ids = malloc(N * sizeof *ids);
    const rnd_camera cam = fx_camera();
    for (int i = 0; i < DRAWS && t; i++) {
        bool ok = w->use_subset ? rnd_draw(ctx, t, gpu, &cam, subset_ids, 4, NULL)
                                : rnd_draw(ctx, t, gpu, &cam, NULL, 0, NULL);
        ok = ok && rnd_target_read_ids(ctx, t, ids);
        w->failures += !ok;
        w->mismatches += memcmp(ids, w->use_subset ? reference_subset : reference_full, sizeof reference_full) != 0;
    }
    w->failures += t == NULL;
    free(ids);
    rnd_target_destroy(ctx, t);
    return NULL;
}

static void concurrent_draws_match_reference(void)
{
    char err[256];
    rnd_target* t = rnd_target_create(ctx, W, H, err, sizeof err);
    const rnd_camera cam = fx_camera();
    TV_CHECK(rnd_draw(ctx, t, gpu, &cam, NULL, 0, NULL) && rnd_target_read_ids(ctx, t, reference_full));
    TV_CHECK(rnd_draw(ctx, t, gpu, &cam, subset_ids, 4, NULL) && rnd_target_read_ids(ctx, t, reference_subset));
    rnd_target_destroy(ctx, t);
    TV_CHECK(memcmp(reference_full, reference_subset, sizeof reference_full) != 0);

    worker workers[2] = {{.use_subset = 0}, {.use_subset = 1}};
    pthread_t threads[2];
    for (int i = 0; i < 2; i++)
        TV_CHECK(pthread_create(&threads[i], NULL, run, &workers[i]) == 0);
    for (int i = 0; i < 2; i++) {
        pthread_join(threads[i], NULL);
        TV_CHECK(workers[i].failures == 0 && workers[i].mismatches == 0);
    }
}

int main(void)
{
    char err[256];
    ctx = fx_context();
    scn_scene s;
    fx_scene_init(&s, 3, 3);
    fx_quad_z(&s, -1, -1, 1, 1, -5, fx_material(&s, 1, 0, 0, SCN_ALPHA_OPAQUE, false, -1));
    fx_quad_z(&s, 0, -2, 2, 0, -4, fx_material(&s, 0, 1, 0, SCN_ALPHA_OPAQUE, false, -1));
    fx_quad_z(&s, -2, 0, 0, 2, -6, fx_material(&s, 0, 0, 1, SCN_ALPHA_OPAQUE, true, -1));
    gpu = rnd_scene_create(ctx, &s, err, sizeof err);
    if (!gpu) {
        fprintf(stderr, "set-up: %s\n", err);
        return 1;
    }
    TV_TEST_RUN(concurrent_draws_match_reference);
    rnd_scene_destroy(ctx, gpu);
    scn_scene_free(&s);
    TV_CHECK(rnd_validation_message_count(ctx) == 0);
    rnd_destroy(ctx);
    return tv_test_finish();
}
