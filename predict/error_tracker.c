#include "error_tracker.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static bool _window_init(pred_error_window* w, int size)
{
    memset(w, 0, sizeof *w);
    w->ring = malloc((size_t)size * sizeof *w->ring);
    w->sorted = malloc((size_t)size * sizeof *w->sorted);
    return w->ring && w->sorted;
}

static void _window_free(pred_error_window* w)
{
    free(w->ring);
    free(w->sorted);
    memset(w, 0, sizeof *w);
}

/* First index in sorted whose value is >= v. */
static int _lower_bound(const double* sorted, int n, double v)
{
    int lo = 0, hi = n;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (sorted[mid] < v)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

static void _window_add(pred_error_window* w, int size, double v)
{
    if (w->count == size) {
        int at = _lower_bound(w->sorted, w->count, w->ring[w->next]);
        memmove(w->sorted + at, w->sorted + at + 1, (size_t)(w->count - at - 1) * sizeof *w->sorted);
        w->count--;
    }
    int at = _lower_bound(w->sorted, w->count, v);
    memmove(w->sorted + at + 1, w->sorted + at, (size_t)(w->count - at) * sizeof *w->sorted);
    w->sorted[at] = v;
    w->count++;
    w->ring[w->next] = v;
    w->next = (w->next + 1) % size;
    w->max = w->total ? fmax(w->max, v) : v;
    w->total++;
}

static double _window_quantile(const pred_error_window* w, double q)
{
    assert(q > 0.0 && q <= 1.0);
    if (!w->count)
        return 0.0;
    int rank = (int)ceil(q * w->count - 1e-9);
    rank = rank < 1 ? 1 : rank;
    return w->sorted[rank - 1];
}

bool pred_error_tracker_init(pred_error_tracker* tr, const pred_error_tracker_desc* desc)
{
    assert(tr && desc);
    memset(tr, 0, sizeof *tr);
    if (desc->horizon_count < 0 || desc->horizon_count > PRED_MAX_HORIZONS)
        return false;
    if (desc->horizon_count) {
        tr->horizon_count = desc->horizon_count;
        for (int h = 0; h < desc->horizon_count; h++) {
            tr->horizons_s[h] = desc->horizons_s[h];
            if (!(desc->horizons_s[h] > 0.0) || (h && !(desc->horizons_s[h] > desc->horizons_s[h - 1])))
                return false;
        }
    } else {
        tr->horizon_count = 10;
        for (int h = 0; h < 10; h++)
            tr->horizons_s[h] = 0.01 * (h + 1);
    }
    tr->window = desc->window > 0 ? desc->window : 4096;
    bool ok = true;
    for (int h = 0; h < tr->horizon_count; h++)
        ok = _window_init(&tr->pos[h], tr->window) && _window_init(&tr->rot[h], tr->window) && ok;
    if (!ok)
        pred_error_tracker_free(tr);
    return ok;
}

void pred_error_tracker_free(pred_error_tracker* tr)
{
    for (int h = 0; h < PRED_MAX_HORIZONS; h++) {
        _window_free(&tr->pos[h]);
        _window_free(&tr->rot[h]);
        free(tr->pending[h].items);
    }
    memset(tr, 0, sizeof *tr);
}

bool pred_error_tracker_push(pred_error_tracker* tr, int h, const pred_pose* predicted)
{
    assert(h >= 0 && h < tr->horizon_count);
    pred_error_pending* q = &tr->pending[h];
    if (q->count == q->cap) {
        int cap = q->cap ? 2 * q->cap : 64;
        pred_pose* items = malloc((size_t)cap * sizeof *items);
        if (!items)
            return false;
        for (int i = 0; i < q->count; i++)
            items[i] = q->items[(q->head + i) % q->cap];
        free(q->items);
        q->items = items;
        q->head = 0;
        q->cap = cap;
    }
    q->items[(q->head + q->count) % q->cap] = *predicted;
    q->count++;
    return true;
}

void pred_error_tracker_record(pred_error_tracker* tr, int h, double pos_err_m, double rot_err_deg)
{
    assert(h >= 0 && h < tr->horizon_count);
    _window_add(&tr->pos[h], tr->window, pos_err_m);
    _window_add(&tr->rot[h], tr->window, rot_err_deg);
}

void pred_error_tracker_observe(pred_error_tracker* tr, const pred_pose* sample)
{
    if (tr->have_last && !(sample->t > tr->last.t))
        return; /* non-monotonic: ignored like the history does */
    for (int h = 0; h < tr->horizon_count; h++) {
        pred_error_pending* q = &tr->pending[h];
        while (q->count && q->items[q->head].t <= sample->t) {
            const pred_pose* pred = &q->items[q->head];
            if (tr->have_last && pred->t >= tr->last.t) {
                pred_pose truth;
                pred_pose_lerp(&tr->last, sample, (pred->t - tr->last.t) / (sample->t - tr->last.t), &truth);
                pred_error_tracker_record(tr, h, pred_vec3_dist(pred->p, truth.p),
                                          pred_quat_angle_deg(pred->q, truth.q));
            }
            q->head = (q->head + 1) % q->cap;
            q->count--;
        }
    }
    tr->last = *sample;
    tr->have_last = true;
}

double pred_error_tracker_quantile_pos(const pred_error_tracker* tr, int h, double q)
{
    assert(h >= 0 && h < tr->horizon_count);
    return _window_quantile(&tr->pos[h], q);
}

double pred_error_tracker_quantile_rot(const pred_error_tracker* tr, int h, double q)
{
    assert(h >= 0 && h < tr->horizon_count);
    return _window_quantile(&tr->rot[h], q);
}

void pred_error_tracker_bound(const pred_error_tracker* tr, double horizon_s, double q,
                              double* pos_m, double* rot_deg)
{
    int n = tr->horizon_count;
    const double* hs = tr->horizons_s;
    int hi = 0;
    while (hi < n && hs[hi] < horizon_s)
        hi++;
    if (hi == 0) {
        *pos_m = pred_error_tracker_quantile_pos(tr, 0, q);
        *rot_deg = pred_error_tracker_quantile_rot(tr, 0, q);
    } else if (hi == n) {
        double s = (horizon_s / hs[n - 1]) * (horizon_s / hs[n - 1]);
        *pos_m = s * pred_error_tracker_quantile_pos(tr, n - 1, q);
        *rot_deg = s * pred_error_tracker_quantile_rot(tr, n - 1, q);
    } else {
        double u = (horizon_s - hs[hi - 1]) / (hs[hi] - hs[hi - 1]);
        *pos_m = (1.0 - u) * pred_error_tracker_quantile_pos(tr, hi - 1, q) +
                 u * pred_error_tracker_quantile_pos(tr, hi, q);
        *rot_deg = (1.0 - u) * pred_error_tracker_quantile_rot(tr, hi - 1, q) +
                   u * pred_error_tracker_quantile_rot(tr, hi, q);
    }
}

static void _stats(const pred_error_window* w, pred_error_stats* s)
{
    s->count = w->total;
    s->p50 = _window_quantile(w, 0.50);
    s->p95 = _window_quantile(w, 0.95);
    s->p99 = _window_quantile(w, 0.99);
    s->max = w->total ? w->max : 0.0;
}

void pred_error_tracker_stats(const pred_error_tracker* tr, int h, pred_error_stats* pos,
                              pred_error_stats* rot)
{
    assert(h >= 0 && h < tr->horizon_count);
    _stats(&tr->pos[h], pos);
    _stats(&tr->rot[h], rot);
}
