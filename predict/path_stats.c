#include "path_stats.h"

#include "stats.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

bool pred_path_stats_compute(const pred_path* path, pred_path_stats* out, char* err, size_t err_size)
{
    assert(path && out);
    memset(out, 0, sizeof *out);
    if (path->count < 2) {
        snprintf(err, err_size, "path statistics need two samples, the path has %zu", path->count);
        return false;
    }
    size_t n = path->count - 1;
    double* buf = malloc(3 * n * sizeof *buf);
    if (!buf) {
        snprintf(err, err_size, "path statistics: out of memory");
        return false;
    }
    double *dt = buf, *speed = buf + n, *ang = buf + 2 * n;
    double dist = 0.0, angle = 0.0, fy = 0.0;
    for (size_t i = 0; i < n; i++) {
        const pred_pose *a = &path->poses[i], *b = &path->poses[i + 1];
        dt[i] = b->t - a->t; /* > 0: paths are strictly increasing */
        double step = pred_vec3_dist(a->p, b->p), turn = pred_quat_angle_deg(a->q, b->q);
        speed[i] = step / dt[i];
        ang[i] = turn / dt[i];
        dist += step;
        angle += turn;
    }
    for (size_t i = 0; i < path->count; i++) {
        double f[3];
        pred_pose_forward(path->poses[i].q, f);
        fy += fabs(f[1]);
    }
    out->samples = path->count;
    out->duration_s = pred_path_duration(path);
    out->dt_median_s = tv_percentile(dt, n, 50.0);
    out->dt_max_s = tv_percentile(dt, n, 100.0);
    out->speed_mean = dist / out->duration_s;
    out->speed_p50 = tv_percentile(speed, n, 50.0);
    out->speed_p99 = tv_percentile(speed, n, 99.0);
    out->ang_speed_mean = angle / out->duration_s;
    out->ang_speed_p50 = tv_percentile(ang, n, 50.0);
    out->ang_speed_p99 = tv_percentile(ang, n, 99.0);
    out->forward_y_mean_abs = fy / (double)path->count;
    free(buf);
    return true;
}
