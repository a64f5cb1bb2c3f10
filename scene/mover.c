/* mover.c - keyframe evaluation, posing and swept bounds of movers. */
#include "mover.h"

#include "scene.h"

#include <assert.h>
#include <cglm/cglm.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int _scn_track_width(int which) { return which == SCN_TRACK_ROTATION ? 4 : 3; }

bool scn_mover_init(scn_mover* m, const scn_scene* scene, char* err, size_t err_size)
{
    assert(m && scene && (uint64_t)m->first_vertex + m->vertex_count <= scene->vertex_count);
    static const char* names[SCN_TRACK_COUNT] = {"translation", "rotation", "scale"};
    m->period_s = 0.0f;
    for (int k = 0; k < SCN_TRACK_COUNT; k++) {
        const scn_track* tr = &m->track[k];
        int w = _scn_track_width(k);
        for (uint32_t i = 0; i < tr->count; i++) {
            if (!isfinite(tr->times[i]) || tr->times[i] < 0.0f || (i > 0 && !(tr->times[i] > tr->times[i - 1]))) {
                snprintf(err, err_size, "mover %s: %s key %u time %g is not finite, >= 0 and increasing", m->name,
                         names[k], i, (double)tr->times[i]);
                return false;
            }
            double len2 = 0.0;
            for (int c = 0; c < w; c++) {
                float v = tr->values[(size_t)w * i + c];
                len2 += (double)v * v;
                if (!isfinite(v)) {
                    snprintf(err, err_size, "mover %s: %s key %u has a non-finite value", m->name, names[k], i);
                    return false;
                }
            }
            if (k == SCN_TRACK_ROTATION && !(len2 > 1e-12)) {
                snprintf(err, err_size, "mover %s: rotation key %u is a zero quaternion", m->name, i);
                return false;
            }
        }
        if (tr->count && tr->times[tr->count - 1] > m->period_s)
            m->period_s = tr->times[tr->count - 1];
    }
    m->rest = malloc((size_t)(m->vertex_count ? m->vertex_count : 1) * 6 * sizeof(float));
    if (!m->rest) {
        snprintf(err, err_size, "mover %s: out of memory", m->name);
        return false;
    }
    for (int k = 0; k < 3; k++)
        m->local_min[k] = FLT_MAX, m->local_max[k] = -FLT_MAX;
    for (uint32_t v = 0; v < m->vertex_count; v++) {
        const float* p = scene->positions + 3 * (size_t)(m->first_vertex + v);
        memcpy(m->rest + 6 * (size_t)v, p, 3 * sizeof(float));
        memcpy(m->rest + 6 * (size_t)v + 3, scene->normals + 3 * (size_t)(m->first_vertex + v), 3 * sizeof(float));
        for (int k = 0; k < 3; k++) {
            m->local_min[k] = fminf(m->local_min[k], p[k]);
            m->local_max[k] = fmaxf(m->local_max[k], p[k]);
        }
    }
    return true;
}

void scn_mover_free(scn_mover* m)
{
    free(m->rest);
    for (int k = 0; k < SCN_TRACK_COUNT; k++) {
        free(m->track[k].times);
        free(m->track[k].values);
    }
    memset(m, 0, sizeof *m);
}

/* Value of track `which` at local time tau (already folded into the loop);
 * with `left`, the limit from below (a STEP track's value just before a key). */
static void _scn_track_eval(const scn_mover* m, int which, double tau, bool left, float* out)
{
    const scn_track* tr = &m->track[which];
    int w = _scn_track_width(which);
    const float* base = which == SCN_TRACK_TRANSLATION ? m->base_t : which == SCN_TRACK_ROTATION ? m->base_r : m->base_s;
    uint32_t hi = 0, n = tr->count; /* the first key after tau (at or after, with left) */
    for (uint32_t end = n; hi < end;) {
        uint32_t mid = (hi + end) / 2;
        if (left ? tr->times[mid] < tau : tr->times[mid] <= tau)
            hi = mid + 1;
        else
            end = mid;
    }
    if (n == 0) {
        memcpy(out, base, (size_t)w * sizeof(float));
    } else if (hi == 0 || hi == n) {
        memcpy(out, tr->values + (size_t)w * (hi ? n - 1 : 0), (size_t)w * sizeof(float));
    } else {
        const float* a = tr->values + (size_t)w * (hi - 1);
        const float* b = tr->values + (size_t)w * hi;
        float f = (float)((tau - tr->times[hi - 1]) / ((double)tr->times[hi] - tr->times[hi - 1]));
        if (tr->interp == SCN_INTERP_STEP)
            memcpy(out, a, (size_t)w * sizeof(float));
        else if (which == SCN_TRACK_ROTATION)
            glm_quat_slerp((float*)a, (float*)b, f, out);
        else
            glm_vec3_lerp((float*)a, (float*)b, f, out);
    }
    if (which == SCN_TRACK_ROTATION)
        glm_quat_normalize(out);
}

/* Folds t into the loop: [0, period); a static mover keeps its t = 0 pose. */
static double _scn_fold(const scn_mover* m, double t)
{
    if (!(m->period_s > 0.0f))
        return 0.0;
    double tau = fmod(t, m->period_s);
    return tau < 0.0 ? tau + m->period_s : tau;
}

/* Local TRS matrix (without parent) at local time tau. */
static void _scn_local_matrix(const scn_mover* m, double tau, mat4 out)
{
    vec3 t, s;
    versor r;
    _scn_track_eval(m, SCN_TRACK_TRANSLATION, tau, false, t);
    _scn_track_eval(m, SCN_TRACK_ROTATION, tau, false, r);
    _scn_track_eval(m, SCN_TRACK_SCALE, tau, false, s);
    mat4 rot;
    glm_quat_mat4(r, rot);
    glm_mat4_identity(out);
    glm_translate(out, t);
    glm_mat4_mul(out, rot, out);
    glm_scale(out, s);
}

void scn_mover_matrix(const scn_mover* m, double t, float out[16])
{
    mat4 local, world, parent;
    _scn_local_matrix(m, _scn_fold(m, t), local);
    memcpy(parent, m->parent, sizeof parent);
    glm_mat4_mul(parent, local, world);
    memcpy(out, world, sizeof world);
}

void scn_scene_pose(scn_scene* scene, double t)
{
    assert(scene);
    for (uint32_t i = 0; i < scene->mover_count; i++) {
        const scn_mover* m = &scene->movers[i];
        mat4 world;
        mat3 normal_matrix;
        scn_mover_matrix(m, t, (float*)world);
        glm_mat4_pick3(world, normal_matrix);
        glm_mat3_inv(normal_matrix, normal_matrix);
        glm_mat3_transpose(normal_matrix);
        for (uint32_t v = 0; v < m->vertex_count; v++) {
            const float* r = m->rest + 6 * (size_t)v;
            float* p = scene->positions + 3 * (size_t)(m->first_vertex + v);
            float* n = scene->normals + 3 * (size_t)(m->first_vertex + v);
            glm_mat4_mulv3(world, (float*)r, 1.0f, p);
            glm_mat3_mulv(normal_matrix, (float*)r + 3, n);
            glm_vec3_normalize(n);
        }
    }
}

/* Sub-intervals per piece: at most this rotation each, so the arc term stays small. */
#define SCN_BOUNDS_MAX_ANGLE 0.0873 /* 5 degrees */
#define SCN_BOUNDS_MAX_STEPS 64

/* Grows [mn, mx] by the box corners at exactly local time tau. */
static void _scn_bounds_at(const scn_mover* m, double tau, vec3 mn, vec3 mx)
{
    mat4 local;
    _scn_local_matrix(m, tau, local);
    for (int c = 0; c < 8; c++) {
        vec3 p = {(c & 1) ? m->local_max[0] : m->local_min[0], (c & 2) ? m->local_max[1] : m->local_min[1],
                  (c & 4) ? m->local_max[2] : m->local_min[2]}, w;
        glm_mat4_mulv3(local, p, 1.0f, w);
        glm_vec3_minv(mn, w, mn);
        glm_vec3_maxv(mx, w, mx);
    }
}

/* Grows the parent-frame box [mn, mx] by the mover over local times
 * [a, b] of one loop, no key time lying inside (a STEP track holds its
 * value on [a, b) and may jump at b: the pose at b is added on its own).
 * A corner c moves as T(t) + R(t) g(t), g = S(t) c. Per sub-interval
 * [u0, u1]: T and g are linear, R a slerp, i.e. a rotation by 0..theta about
 * one axis. So T(t) lies in box(T0, T1); R(t) g0 on an arc from R0 g0 to
 * R1 g0, within |g0| (1 - cos(theta / 2)) of its chord (theta <= pi); and
 * |R(t) (g(t) - g0)| <= |g1 - g0|. The sum of the two boxes, grown by those
 * two terms, holds the corner; with translation alone it is the exact sweep. */
static void _scn_bounds_piece(const scn_mover* m, double a, double b, vec3 mn, vec3 mx)
{
    versor ra, rb;
    _scn_track_eval(m, SCN_TRACK_ROTATION, a, false, ra);
    _scn_track_eval(m, SCN_TRACK_ROTATION, b, true, rb);
    double angle = 2.0 * acos(fmin(1.0, fabs((double)glm_quat_dot(ra, rb))));
    int steps = (int)ceil(angle / SCN_BOUNDS_MAX_ANGLE);
    steps = steps < 1 ? 1 : steps > SCN_BOUNDS_MAX_STEPS ? SCN_BOUNDS_MAX_STEPS : steps;
    for (int i = 0; i < steps; i++) {
        double u[2] = {a + (b - a) * i / steps, i + 1 == steps ? b : a + (b - a) * (i + 1) / steps};
        vec3 t[2], s[2];
        versor r[2];
        for (int e = 0; e < 2; e++) {
            bool left = e == 1; /* the sweep ends just before b */
            _scn_track_eval(m, SCN_TRACK_TRANSLATION, u[e], left, t[e]);
            _scn_track_eval(m, SCN_TRACK_ROTATION, u[e], left, r[e]);
            _scn_track_eval(m, SCN_TRACK_SCALE, u[e], left, s[e]);
        }
        double theta = 2.0 * acos(fmin(1.0, fabs((double)glm_quat_dot(r[0], r[1]))));
        for (int c = 0; c < 8; c++) {
            vec3 corner = {(c & 1) ? m->local_max[0] : m->local_min[0], (c & 2) ? m->local_max[1] : m->local_min[1],
                           (c & 4) ? m->local_max[2] : m->local_min[2]};
            vec3 g[2], f[2];
            glm_vec3_mul(s[0], corner, g[0]);
            glm_vec3_mul(s[1], corner, g[1]);
            glm_quat_rotatev(r[0], g[0], f[0]);
            glm_quat_rotatev(r[1], g[0], f[1]);
            float grow = (float)(glm_vec3_norm(g[0]) * (1.0 - cos(0.5 * theta))) + glm_vec3_distance(g[0], g[1]);
            grow = grow > 0.0f ? grow * 1.0001f + 1e-6f : 0.0f; /* float rounding of the poses */
            for (int k = 0; k < 3; k++) {
                mn[k] = fminf(mn[k], fminf(t[0][k], t[1][k]) + fminf(f[0][k], f[1][k]) - grow);
                mx[k] = fmaxf(mx[k], fmaxf(t[0][k], t[1][k]) + fmaxf(f[0][k], f[1][k]) + grow);
            }
        }
    }
    _scn_bounds_at(m, b, mn, mx);
}

/* The first key time of any track after x, or b when none comes before b. */
static double _scn_next_key(const scn_mover* m, double x, double b)
{
    double next = b;
    for (int k = 0; k < SCN_TRACK_COUNT; k++) {
        const scn_track* tr = &m->track[k];
        uint32_t lo = 0, hi = tr->count; /* first index with times > x */
        while (lo < hi) {
            uint32_t mid = (lo + hi) / 2;
            if (tr->times[mid] <= x)
                lo = mid + 1;
            else
                hi = mid;
        }
        if (lo < tr->count && tr->times[lo] < next)
            next = tr->times[lo];
    }
    return next;
}

/* Grows the box over local times [a, b] of one loop, split at key times. */
static void _scn_bounds_loop(const scn_mover* m, double a, double b, vec3 mn, vec3 mx)
{
    for (double x = a;;) {
        double next = _scn_next_key(m, x, b);
        _scn_bounds_piece(m, x, next, mn, mx);
        if (next >= b)
            break;
        x = next;
    }
}

void scn_mover_bounds(const scn_scene* scene, uint32_t index, double t0, double t1, float out_min[3],
                      float out_max[3])
{
    assert(scene && index < scene->mover_count && t0 <= t1);
    const scn_mover* m = &scene->movers[index];
    vec3 mn = {FLT_MAX, FLT_MAX, FLT_MAX}, mx = {-FLT_MAX, -FLT_MAX, -FLT_MAX};
    double period = m->period_s;
    if (!(period > 0.0)) {
        _scn_bounds_at(m, 0.0, mn, mx);
    } else if (t1 - t0 >= period) {
        _scn_bounds_loop(m, 0.0, period, mn, mx);
    } else {
        double a = _scn_fold(m, t0), b = a + (t1 - t0);
        if (b <= period) {
            _scn_bounds_loop(m, a, b, mn, mx);
        } else { /* the window wraps: the end of one loop, the start of the next */
            _scn_bounds_loop(m, a, period, mn, mx);
            _scn_bounds_loop(m, 0.0, b - period, mn, mx);
        }
    }
    /* the parent box: its corners' hull holds every point of the local one */
    mat4 parent;
    memcpy(parent, m->parent, sizeof parent);
    for (int k = 0; k < 3; k++)
        out_min[k] = FLT_MAX, out_max[k] = -FLT_MAX;
    for (int c = 0; c < 8; c++) {
        vec3 p = {(c & 1) ? mx[0] : mn[0], (c & 2) ? mx[1] : mn[1], (c & 4) ? mx[2] : mn[2]}, w;
        glm_mat4_mulv3(parent, p, 1.0f, w);
        for (int k = 0; k < 3; k++) {
            out_min[k] = fminf(out_min[k], w[k]);
            out_max[k] = fmaxf(out_max[k], w[k]);
        }
    }
}
