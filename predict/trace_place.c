#include "trace_place.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static double _yaw_of(double fx, double fz)
{
    /* heading 0 looks down -Z, 90 degrees down -X */
    return (fx == 0.0 && fz == 0.0) ? 0.0 : atan2(-fx, -fz);
}

void pred_trace_reference(const pred_path* path, pred_place_ref ref, double point[3], double* yaw)
{
    assert(path && path->count >= 1 && point && yaw);
    double f[3];
    if (ref == PRED_PLACE_START) {
        for (int i = 0; i < 3; i++)
            point[i] = path->poses[0].p[i];
        pred_pose_forward(path->poses[0].q, f);
        *yaw = _yaw_of(f[0], f[2]);
        return;
    }
    double sum[3] = {0.0, 0.0, 0.0}, fx = 0.0, fz = 0.0;
    for (size_t k = 0; k < path->count; k++) {
        for (int i = 0; i < 3; i++)
            sum[i] += path->poses[k].p[i];
        pred_pose_forward(path->poses[k].q, f);
        double h = hypot(f[0], f[2]); /* each sample's heading counts once, however it pitches */
        if (h > 1e-9) {
            fx += f[0] / h;
            fz += f[2] / h;
        }
    }
    for (int i = 0; i < 3; i++)
        point[i] = sum[i] / (double)path->count;
    *yaw = hypot(fx, fz) > 1e-9 * (double)path->count ? _yaw_of(fx, fz) : 0.0;
}

static int _cmp_double(const void* a, const void* b)
{
    double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

double pred_trace_median_height(const pred_path* path)
{
    assert(path && path->count >= 1);
    double* y = malloc(path->count * sizeof *y);
    if (!y)
        return NAN;
    for (size_t k = 0; k < path->count; k++)
        y[k] = path->poses[k].p[1];
    qsort(y, path->count, sizeof *y, _cmp_double);
    size_t n = path->count;
    double m = n % 2 ? y[n / 2] : 0.5 * (y[n / 2 - 1] + y[n / 2]);
    free(y);
    return m;
}

bool pred_trace_place(pred_path* path, const pred_placement* pl)
{
    assert(path && path->count >= 1 && pl);
    double ref[3], yaw;
    pred_trace_reference(path, pl->ref, ref, &yaw);
    double from_y = ref[1], to_y = pl->anchor[1] + pl->height_offset_m;
    if (pl->eye_height_m > 0.0) {
        from_y = pred_trace_median_height(path);
        if (isnan(from_y))
            return false;
        to_y += pl->eye_height_m;
    }
    double turn = pl->heading_deg * PRED_DEG - yaw;
    double rot[4];
    pred_quat_from_ypr(turn, 0.0, 0.0, rot);
    for (size_t k = 0; k < path->count; k++) {
        pred_pose* s = &path->poses[k];
        double d[3] = {s->p[0] - ref[0], 0.0, s->p[2] - ref[2]};
        pred_quat_rotate(rot, d, d);
        s->p[0] = pl->anchor[0] + d[0];
        s->p[1] = s->p[1] - from_y + to_y;
        s->p[2] = pl->anchor[2] + d[2];
        pred_quat_mul(rot, s->q, s->q);
        pred_quat_normalize(s->q);
    }
    return true;
}

int pred_placement_format(const pred_placement* pl, char* buf, size_t size)
{
    return snprintf(buf, size, "placement: anchor=%.3f,%.3f,%.3f heading=%.2f ref=%s eye-height=%.3f height-offset=%.3f",
                    pl->anchor[0], pl->anchor[1], pl->anchor[2], pl->heading_deg,
                    pl->ref == PRED_PLACE_CENTROID ? "centroid" : "start", pl->eye_height_m, pl->height_offset_m);
}
