#include "history.h"

#include <assert.h>
#include <string.h>

void pred_history_clear(pred_history* h)
{
    memset(h, 0, sizeof *h);
}

bool pred_history_push(pred_history* h, const pred_pose* sample)
{
    if (h->count && !(sample->t > h->items[h->newest].t)) {
        h->dropped++;
        return false;
    }
    h->newest = h->count ? (h->newest + 1) % PRED_HISTORY_CAPACITY : 0;
    h->items[h->newest] = *sample;
    if (h->count < PRED_HISTORY_CAPACITY)
        h->count++;
    return true;
}

const pred_pose* pred_history_get(const pred_history* h, int age)
{
    assert(age >= 0 && age < h->count);
    return &h->items[(h->newest - age + PRED_HISTORY_CAPACITY) % PRED_HISTORY_CAPACITY];
}

bool pred_history_interpolate(const pred_history* h, double t, pred_pose* out)
{
    if (!h->count || t > pred_history_get(h, 0)->t || t < pred_history_get(h, h->count - 1)->t)
        return false;
    /* binary search over ages: age 0 is newest (largest t) */
    int lo = 0, hi = h->count - 1; /* invariant: t(lo) >= t >= t(hi) */
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (pred_history_get(h, mid)->t >= t)
            lo = mid;
        else
            hi = mid;
    }
    const pred_pose* a = pred_history_get(h, hi);
    const pred_pose* b = pred_history_get(h, lo);
    double span = b->t - a->t;
    pred_pose_lerp(a, b, span > 0.0 ? (t - a->t) / span : 0.0, out);
    out->t = t;
    return true;
}
