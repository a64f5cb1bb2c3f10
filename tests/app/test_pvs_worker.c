/* The asynchronous PVS worker and its latency models, with a compute
 * function that takes a known wall time (no GPU). Runs under ThreadSanitizer
 * in the TSan build (label async). */
#define _POSIX_C_SOURCE 200809L
#include "clock.h"
#include "pvs_worker.h"
#include "test.h"

#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct fake {
    double sleep_ms;
    atomic_int calls;
    atomic_int hold;     /* while set, the compute waits (up to 2 s) before finishing */
    atomic_int finished; /* computes that have returned */
    bool fail;
} fake;

typedef struct fake_stats {
    float delta_seen;
} fake_stats;

static void sleep_ms(double ms)
{
    struct timespec ts = {.tv_sec = (time_t)(ms / 1000), .tv_nsec = (long)(((long long)(ms * 1e6)) % 1000000000LL)};
    nanosleep(&ts, NULL);
}

/* "PVS" = the triangles 0..(delta*100): lets the test check the result belongs to its viewcell */
static bool fake_compute(void* user, const void* extra, uint32_t** ids, uint32_t* count, void* stats, char* err,
                         size_t err_size)
{
    fake* f = user;
    const pred_viewcell* vc = extra;
    atomic_fetch_add(&f->calls, 1);
    sleep_ms(f->sleep_ms);
    for (int i = 0; i < 2000 && atomic_load(&f->hold); i++)
        sleep_ms(1.0);
    if (f->fail) {
        snprintf(err, err_size, "fake failure");
        atomic_fetch_add(&f->finished, 1);
        return false;
    }
    uint32_t n = (uint32_t)(vc->delta * 100.0f + 0.5f);
    *ids = malloc(sizeof(uint32_t) * (n ? n : 1));
    for (uint32_t i = 0; i < n; i++)
        (*ids)[i] = i;
    *count = n;
    ((fake_stats*)stats)->delta_seen = vc->delta;
    atomic_fetch_add(&f->finished, 1);
    return true;
}

static pred_viewcell cell(float delta)
{
    pred_viewcell vc;
    memset(&vc, 0, sizeof vc);
    vc.delta = delta;
    return vc;
}

/* The viewcell travels as the request (extra) and as the result's viewcell. */
static void submit(tv_worker* w, float delta, double t_request)
{
    pred_viewcell vc = cell(delta);
    tv_worker_submit(w, &vc, &vc, t_request);
}

static void test_fixed_latency(void)
{
    fake f = {.sleep_ms = 20, .hold = 1};
    tv_worker_desc d = {.compute = fake_compute, .user = &f, .stats_size = sizeof(fake_stats),
                        .extra_size = sizeof(pred_viewcell), .model = TV_LATENCY_FIXED, .fixed_latency_s = 0.05};
    char err[256];
    tv_worker* w = tv_worker_start(&d, err, sizeof err);
    TV_CHECK(w != NULL);
    tv_pvs_result r;
    submit(w, 0.07f, 1.0);
    TV_CHECK(tv_worker_busy(w));
    /* before its availability time the poll returns without waiting for the
     * compute, which is still held: it cannot have finished */
    TV_CHECK(tv_worker_poll(w, 1.02, &r, err, sizeof err) == 0);
    TV_CHECK(atomic_load(&f.finished) == 0);
    atomic_store(&f.hold, 0);
    /* due: the poll waits for the compute and hands it out */
    TV_CHECK(tv_worker_poll(w, 1.05, &r, err, sizeof err) == 1);
    TV_CHECK(!tv_worker_busy(w));
    TV_CHECK(r.count == 7 && r.ids[6] == 6 && r.id == 0);
    TV_CHECK_NEAR(r.t_request, 1.0, 0);
    TV_CHECK_NEAR(r.t_available, 1.05, 1e-12);
    TV_CHECK(r.compute_ms >= 19.0);
    TV_CHECK_NEAR(((fake_stats*)r.stats)->delta_seen, 0.07f, 1e-7);
    tv_pvs_result_free(&r);
    /* nothing in flight: poll returns 0 */
    TV_CHECK(tv_worker_poll(w, 5.0, &r, err, sizeof err) == 0);
    /* a second request gets the next id */
    submit(w, 0.02f, 2.0);
    TV_CHECK(tv_worker_wait(w, &r, err, sizeof err) == 1 && r.id == 1 && r.count == 2);
    tv_pvs_result_free(&r);
    tv_worker_stop(w);
    TV_CHECK(atomic_load(&f.calls) == 2);
}

static void test_measured_latency(void)
{
    fake f = {.sleep_ms = 40};
    tv_worker_desc d = {.compute = fake_compute, .user = &f, .stats_size = sizeof(fake_stats),
                        .extra_size = sizeof(pred_viewcell), .model = TV_LATENCY_MEASURED, .factor = 0.5};
    char err[256];
    tv_worker* w = tv_worker_start(&d, err, sizeof err);
    tv_pvs_result r;
    submit(w, 0.03f, 0.0);
    /* 40 ms of compute at factor 0.5 is due 20 ms after the request: at 5 ms
     * it cannot be (the poll gives up once 10 ms of compute have passed) */
    TV_CHECK(tv_worker_poll(w, 0.005, &r, err, sizeof err) == 0);
    /* a generous `now` so a loaded machine cannot make the 40 ms compute look late */
    TV_CHECK(tv_worker_poll(w, 10.0, &r, err, sizeof err) == 1);
    TV_CHECK(r.t_available >= 0.0195 && r.t_available < 10.0);
    TV_CHECK_NEAR(r.t_available, r.compute_ms * 1e-3 * 0.5, 1e-12);
    tv_pvs_result_free(&r);
    /* a PVS faster than the latency it was sized for waits for its window:
     * finished (the poll at 4 s waits for the 40 ms compute) but not handed
     * out before t_begin = 5 s */
    pred_viewcell vc = cell(0.04f);
    vc.t_begin = 5.0;
    tv_worker_submit(w, &vc, &vc, 0.0);
    TV_CHECK(tv_worker_poll(w, 4.0, &r, err, sizeof err) == 0 && atomic_load(&f.finished) == 2);
    TV_CHECK(tv_worker_poll(w, 5.0, &r, err, sizeof err) == 1);
    TV_CHECK_NEAR(r.t_available, 5.0, 0);
    tv_pvs_result_free(&r);
    tv_worker_stop(w);
}

static void test_failure_and_stop_in_flight(void)
{
    fake f = {.sleep_ms = 5, .fail = true};
    tv_worker_desc d = {.compute = fake_compute, .user = &f, .stats_size = sizeof(fake_stats),
                        .extra_size = sizeof(pred_viewcell), .model = TV_LATENCY_FIXED, .fixed_latency_s = 0.0};
    char err[256] = "";
    tv_worker* w = tv_worker_start(&d, err, sizeof err);
    tv_pvs_result r;
    submit(w, 0.01f, 0.0);
    TV_CHECK(tv_worker_poll(w, 0.0, &r, err, sizeof err) == -1);
    TV_CHECK(strcmp(err, "fake failure") == 0);
    TV_CHECK(!tv_worker_busy(w));
    f.fail = false;
    f.sleep_ms = 30;
    submit(w, 0.01f, 0.0);
    tv_worker_stop(w); /* clean shutdown with a job in flight: no leak, no hang */
}

int main(void)
{
    TV_TEST_RUN(test_fixed_latency);
    TV_TEST_RUN(test_measured_latency);
    TV_TEST_RUN(test_failure_and_stop_in_flight);
    return tv_test_finish();
}
