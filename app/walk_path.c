#include "walk_path.h"

#include "path_synth.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TARGETS 12      /* farthest-point samples a walk visits at most */
#define MAX_ROUTE 65536 /* joined points of a whole walk */

bool tv_auto_path_kind_from_name(const char* name, tv_auto_path_kind* out)
{
    static const char* names[] = {"walk", "run", "lookaround"};
    for (int i = 0; i < 3; i++)
        if (strcmp(name, names[i]) == 0) {
            *out = (tv_auto_path_kind)i;
            return true;
        }
    return false;
}

static void floor_point(const tv_walkable* w, uint32_t i, float out[3])
{
    tv_walkable_point(w, i, out, NULL);
    out[1] -= tv_walkable_desc(w).eye_height_m;
}

static float dist_xz(const float a[3], const float b[3])
{
    return hypotf(a[0] - b[0], a[2] - b[2]);
}

/* The tour: from the first sample to the nearest unvisited one, and on,
 * along joined points, until `length` metres; into route (point indices). */
static int tour(const tv_walkable* w, const uint32_t* targets, int ntargets, float length, uint32_t* route)
{
    bool visited[TARGETS] = {true};
    int n = 1;
    route[0] = targets[0];
    float walked = 0.0f, a[3], b[3];
    for (int leg = 1; leg < ntargets && walked < length; leg++) {
        int next = -1;
        float best = INFINITY;
        floor_point(w, route[n - 1], a);
        for (int t = 0; t < ntargets; t++) {
            floor_point(w, targets[t], b);
            if (!visited[t] && dist_xz(a, b) < best) {
                best = dist_xz(a, b);
                next = t;
            }
        }
        visited[next] = true;
        int m = tv_walkable_route(w, route[n - 1], targets[next], route + n - 1, MAX_ROUTE - n);
        for (int k = n; m > 1 && k < n + m - 1; k++) {
            floor_point(w, route[k - 1], a);
            floor_point(w, route[k], b);
            walked += dist_xz(a, b);
        }
        n += m > 1 ? m - 1 : 0;
    }
    return n;
}

/* String pulling: the farthest point still reachable in a straight walkable
 * line becomes the next waypoint. Returns the waypoint count (at most
 * PRED_SYNTH_MAX_WAYPOINTS); floor heights into fy. */
static int straighten(const tv_walkable* w, const uint32_t* route, int n, double (*wp)[2], float* fy)
{
    int count = 0, i = 0;
    float a[3], b[3];
    for (;;) {
        floor_point(w, route[i], a);
        wp[count][0] = a[0];
        wp[count][1] = a[2];
        fy[count++] = a[1];
        if (i == n - 1 || count == PRED_SYNTH_MAX_WAYPOINTS)
            return count;
        int j = i + 1;
        while (j + 1 < n && (floor_point(w, route[j + 1], b), tv_walkable_segment(w, a, b)))
            j++;
        i = j;
    }
}

/* Distance in x-z from (x, z) to segment seg of the polyline; *u receives
 * the clamped parameter of the nearest point. */
static double seg_distance(const double (*wp)[2], int seg, double x, double z, double* u)
{
    double dx = wp[seg + 1][0] - wp[seg][0], dz = wp[seg + 1][1] - wp[seg][1];
    double t = ((x - wp[seg][0]) * dx + (z - wp[seg][1]) * dz) / (dx * dx + dz * dz);
    *u = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    return hypot(x - wp[seg][0] - *u * dx, z - wp[seg][1] - *u * dz);
}

/* Raises each pose by the floor height under it, interpolated along the
 * waypoint polyline (a cursor follows the path's progress, so overlapping
 * storeys are not confused). */
static void lift(pred_path* p, const double (*wp)[2], const float* fy, int n)
{
    int seg = 0;
    for (size_t i = 0; i < p->count; i++) {
        double x = p->poses[i].p[0], z = p->poses[i].p[2], u = 0.0;
        double d = seg_distance(wp, seg, x, z, &u), d_next, u_next;
        /* on to the next segment once past this one's end or closer to the next (after a fillet) */
        while (seg + 2 < n && (u >= 1.0 - 1e-6 || (d_next = seg_distance(wp, seg + 1, x, z, &u_next)) < d)) {
            seg++;
            d = seg_distance(wp, seg, x, z, &u);
        }
        p->poses[i].p[1] += fy[seg] + u * (fy[seg + 1] - fy[seg]);
    }
}

bool tv_walkable_path(const tv_walkable* w, const char* spec, tv_auto_path_kind kind, uint64_t seed, pred_path* out,
                      char* err, size_t err_size)
{
    assert(w && tv_walkable_count(w) > 0);
    float pos[3 * TARGETS], dir[3 * TARGETS], eye = tv_walkable_desc(w).eye_height_m;
    uint32_t targets[TARGETS];
    int nt = tv_walkable_viewcells(w, tv_walkable_largest_region(w), TARGETS, pos, dir, targets);
    bool run = kind == TV_AUTO_RUN;
    pred_synth_desc d = run ? (pred_synth_desc){PRED_SYNTH_RUN_GAIT, .accel_time = 1.5} : (pred_synth_desc){0};
    d.seed = seed;
    d.eye_height = eye;
    d.scene = spec;
    double wp[PRED_SYNTH_MAX_WAYPOINTS][2];
    float fy[PRED_SYNTH_MAX_WAYPOINTS];
    char text[256];
    int n = 1;
    bool ok = true;
    if (kind == TV_AUTO_LOOKAROUND) {
        d.kind = PRED_SYNTH_LOOKAROUND;
        d.waypoint_count = 1;
        d.waypoints[0][0] = pos[0];
        d.waypoints[0][1] = pos[2];
        d.floor_y = pos[1] - eye;
        d.base_yaw_deg = atan2(-dir[0], -dir[2]) / PRED_DEG; /* yaw 0 looks down -Z */
        snprintf(text, sizeof text, "automatic seated look-around at %.2f,%.2f,%.2f (docs/scenes.md)", pos[0], pos[1],
                 pos[2]);
    } else {
        uint32_t* route = malloc(MAX_ROUTE * sizeof *route);
        int nr = route ? tour(w, targets, nt, run ? 90.0f : 40.0f, route) : 0;
        n = nr > 1 ? straighten(w, route, nr, wp, fy) : 0;
        free(route);
        ok = n >= 2;
        if (!ok)
            snprintf(err, err_size, "%s: the largest walkable region has no room for a %s", spec, run ? "run" : "walk");
        d.kind = PRED_SYNTH_WALK;
        d.waypoint_count = n;
        memcpy(d.waypoints, wp, (size_t)(n > 0 ? n : 0) * sizeof wp[0]);
        d.corner_radius = 0.5; /* fillets cut corners by 0.2 m at 90 degrees: inside the head clearance */
        snprintf(text, sizeof text, "automatic %s over the walkable floor, %d waypoints (docs/scenes.md)",
                 run ? "run" : "walk", n);
    }
    d.description = text;
    ok = ok && pred_path_synth(&d, out, err, err_size);
    if (ok && kind != TV_AUTO_LOOKAROUND)
        lift(out, (const double(*)[2])wp, fy, n);
    return ok;
}

