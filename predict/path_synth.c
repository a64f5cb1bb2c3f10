#include "path_synth.h"

#include "rng.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A piece of a leg's ground curve: a straight (k = 0) or a circular arc of
 * signed curvature k, parametrised by arc length from (x, z) at heading phi0
 * (direction (cos phi0, sin phi0) in the x-z plane). */
typedef struct _piece {
    double x, z, phi0, k, len;
} _piece;

/* A stretch walked from rest to rest; legs are separated by turns on the spot. */
typedef struct _leg {
    int first_piece, piece_count;
    double length;
    double ramp;      /* seconds of cosine speed ramp at each end */
    double t0, t1;    /* time span */
    double turn;      /* heading change (radians) in the pause after this leg */
} _leg;

/* A minimum-jerk head rotation from one (yaw, pitch) offset to another. */
typedef struct _move {
    double t0, dur, from[2], to[2];
} _move;

typedef struct _synth {
    pred_synth_desc d;
    _piece pieces[2 * PRED_SYNTH_MAX_WAYPOINTS];
    int piece_count;
    _leg legs[PRED_SYNTH_MAX_WAYPOINTS];
    int leg_count;
    double duration;
    _move* moves;
    int move_count, move_cap;
} _synth;

static const double k_pause_still = 0.2; /* s of standing still before and after a turn on the spot */

static double _def(double v, double def)
{
    return v == 0.0 ? def : v;
}

static double _amp(double v, double def)
{
    return v < 0.0 ? 0.0 : _def(v, def);
}

static pred_synth_desc _resolve(const pred_synth_desc* in)
{
    pred_synth_desc d = *in;
    d.eye_height = _def(d.eye_height, 1.7);
    d.sample_rate = _def(d.sample_rate, 100.0);
    d.speed = _def(d.speed, 1.4);
    d.accel_time = _def(d.accel_time, 1.0);
    d.corner_radius = _def(d.corner_radius, 1.0);
    d.stop_turn_deg = _def(d.stop_turn_deg, 150.0);
    d.turn_rate_deg = _def(d.turn_rate_deg, 120.0);
    d.yaw_osc_amplitude_deg = _amp(d.yaw_osc_amplitude_deg, 8.0);
    d.yaw_osc_period = _def(d.yaw_osc_period, 3.5);
    d.look_interval = _def(d.look_interval, 5.0);
    d.look_amplitude_deg = _amp(d.look_amplitude_deg, 60.0);
    d.look_hold = _def(d.look_hold, 0.6);
    d.bob_amplitude = _amp(d.bob_amplitude, 0.02);
    d.step_frequency = _def(d.step_frequency, 1.9);
    d.duration = _def(d.duration, 15.0);
    d.sway_amplitude = _amp(d.sway_amplitude, 0.015);
    d.yaw_range_deg = _def(d.yaw_range_deg, 110.0);
    d.pitch_min_deg = _def(d.pitch_min_deg, -35.0);
    d.pitch_max_deg = _def(d.pitch_max_deg, 25.0);
    d.hold_min = _def(d.hold_min, 0.3);
    d.hold_max = _def(d.hold_max, 1.2);
    d.peak_rate_min_deg = _def(d.peak_rate_min_deg, 150.0);
    d.peak_rate_max_deg = _def(d.peak_rate_max_deg, 250.0);
    return d;
}

static bool _fail(char* err, size_t err_size, const char* msg)
{
    if (err && err_size)
        snprintf(err, err_size, "path synth: %s", msg);
    return false;
}

static double _wrap(double a)
{
    while (a > PRED_PI)
        a -= 2.0 * PRED_PI;
    while (a <= -PRED_PI)
        a += 2.0 * PRED_PI;
    return a;
}

/* Minimum-jerk profile 0 -> 1 over u in [0, 1]; its peak slope is 1.875. */
static double _min_jerk(double u)
{
    u = u < 0.0 ? 0.0 : (u > 1.0 ? 1.0 : u);
    return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
}

static void _piece_eval(const _piece* p, double a, double* x, double* z, double* phi)
{
    *phi = p->phi0 + p->k * a;
    if (p->k == 0.0) {
        *x = p->x + a * cos(p->phi0);
        *z = p->z + a * sin(p->phi0);
    } else {
        *x = p->x + (sin(*phi) - sin(p->phi0)) / p->k;
        *z = p->z - (cos(*phi) - cos(p->phi0)) / p->k;
    }
}

static void _add_piece(_synth* s, double x, double z, double phi0, double k, double len)
{
    if (len <= 1e-12)
        return;
    assert(s->piece_count < 2 * PRED_SYNTH_MAX_WAYPOINTS);
    s->pieces[s->piece_count++] = (_piece){x, z, phi0, k, len};
    s->legs[s->leg_count].piece_count++;
    s->legs[s->leg_count].length += len;
}

static void _end_leg(_synth* s, double turn)
{
    _leg* leg = &s->legs[s->leg_count++];
    leg->turn = turn;
    if (s->leg_count < PRED_SYNTH_MAX_WAYPOINTS)
        s->legs[s->leg_count] = (_leg){.first_piece = s->piece_count};
}

/* Polyline -> legs of straights and fillet arcs. */
static bool _build_curve(_synth* s, char* err, size_t err_size)
{
    const pred_synth_desc* d = &s->d;
    int n = d->waypoint_count;
    assert(n >= 2); /* _validate: a walk has at least one segment */
    double len[PRED_SYNTH_MAX_WAYPOINTS], phi[PRED_SYNTH_MAX_WAYPOINTS];
    int i = 0;
    do { /* segment 0 always exists, so phi[0] below is always set */
        double dx = d->waypoints[i + 1][0] - d->waypoints[i][0];
        double dz = d->waypoints[i + 1][1] - d->waypoints[i][1];
        len[i] = sqrt(dx * dx + dz * dz);
        if (!(len[i] > 1e-6))
            return _fail(err, err_size, "two consecutive waypoints coincide");
        phi[i] = atan2(dz, dx);
    } while (++i + 1 < n);
    s->legs[0] = (_leg){0};
    double cx = d->waypoints[0][0], cz = d->waypoints[0][1];
    double heading = phi[0];
    for (i = 1; i + 1 < n; i++) {
        double wx = d->waypoints[i][0], wz = d->waypoints[i][1];
        double turn = _wrap(phi[i] - phi[i - 1]);
        if (fabs(turn) > d->stop_turn_deg * PRED_DEG) {
            _add_piece(s, cx, cz, heading, 0.0, hypot(wx - cx, wz - cz));
            _end_leg(s, turn);
            cx = wx;
            cz = wz;
            heading += turn;
            continue;
        }
        double half_tan = tan(0.5 * fabs(turn));
        double r = d->corner_radius;
        /* each segment lends at most half its length to the fillet at either end */
        double limit = 0.5 * fmin(len[i - 1], len[i]);
        if (r * half_tan > limit)
            r = limit / half_tan;
        double tl = r * half_tan;
        double ax = wx - tl * cos(phi[i - 1]), az = wz - tl * sin(phi[i - 1]);
        _add_piece(s, cx, cz, heading, 0.0, hypot(ax - cx, az - cz));
        if (fabs(turn) > 1e-12)
            _add_piece(s, ax, az, heading, (turn > 0.0 ? 1.0 : -1.0) / r, r * fabs(turn));
        heading += turn;
        cx = wx + tl * cos(phi[i]);
        cz = wz + tl * sin(phi[i]);
    }
    _add_piece(s, cx, cz, heading, 0.0,
               hypot(d->waypoints[n - 1][0] - cx, d->waypoints[n - 1][1] - cz));
    _end_leg(s, 0.0);
    /* time line: cosine ramps cover speed*ramp/2 metres each */
    double t = 0.0;
    for (int l = 0; l < s->leg_count; l++) {
        _leg* leg = &s->legs[l];
        leg->ramp = fmin(d->accel_time, leg->length / d->speed);
        leg->t0 = t;
        leg->t1 = t + leg->ramp + leg->length / d->speed;
        t = leg->t1;
        if (l + 1 < s->leg_count)
            t += 2.0 * k_pause_still + 1.875 * fabs(leg->turn) / (d->turn_rate_deg * PRED_DEG);
    }
    s->duration = t;
    return true;
}

/* Distance along the leg and speed at time tau after its start. */
static void _leg_progress(const _leg* leg, double speed, double tau, double* dist, double* v)
{
    double total = leg->t1 - leg->t0;
    double r = leg->ramp;
    double back = total - tau;
    if (tau < r) {
        *v = 0.5 * speed * (1.0 - cos(PRED_PI * tau / r));
        *dist = 0.5 * speed * (tau - r / PRED_PI * sin(PRED_PI * tau / r));
    } else if (back < r) {
        back = back < 0.0 ? 0.0 : back;
        *v = 0.5 * speed * (1.0 - cos(PRED_PI * back / r));
        *dist = leg->length - 0.5 * speed * (back - r / PRED_PI * sin(PRED_PI * back / r));
    } else {
        *v = speed;
        *dist = 0.5 * speed * r + speed * (tau - r);
    }
}

static void _leg_point(const _synth* s, const _leg* leg, double dist, double* x, double* z,
                       double* phi)
{
    int last = leg->first_piece + leg->piece_count - 1;
    *x = *z = *phi = 0.0;
    for (int i = leg->first_piece; i <= last; i++) {
        const _piece* p = &s->pieces[i];
        if (dist <= p->len || i == last) {
            _piece_eval(p, fmin(dist, p->len), x, z, phi);
            return;
        }
        dist -= p->len;
    }
}

/* Walking along `leg` at t (clamped to its end); `before` is the distance of the earlier legs. */
static void _leg_walk(const _synth* s, const _leg* leg, double t, double before, double* x, double* z,
                      double* phi, double* v, double* travelled)
{
    double dist;
    _leg_progress(leg, s->d.speed, fmin(t, leg->t1) - leg->t0, &dist, v);
    _leg_point(s, leg, dist, x, z, phi);
    *travelled = before + dist;
}

/* Ground position, heading phi, speed and travelled distance of a walk at t. */
static void _walk_eval(const _synth* s, double t, double* x, double* z, double* phi, double* v,
                       double* travelled)
{
    assert(s->leg_count >= 1); /* _build_curve ends at least one leg */
    double before = 0.0;
    for (int l = 0; l + 1 < s->leg_count; l++) {
        const _leg* leg = &s->legs[l];
        if (t <= leg->t1) {
            _leg_walk(s, leg, t, before, x, z, phi, v, travelled);
            return;
        }
        double next_t0 = s->legs[l + 1].t0;
        if (t < next_t0) { /* turning on the spot */
            double turn_time = next_t0 - leg->t1 - 2.0 * k_pause_still;
            _leg_point(s, leg, leg->length, x, z, phi);
            *phi += leg->turn * _min_jerk((t - leg->t1 - k_pause_still) / turn_time);
            *v = 0.0;
            *travelled = before + leg->length;
            return;
        }
        before += leg->length;
    }
    /* the last leg takes every later t: the walker stands at its end */
    _leg_walk(s, &s->legs[s->leg_count - 1], t, before, x, z, phi, v, travelled);
}

static void _push_move(_synth* s, _move m)
{
    if (s->move_count == s->move_cap) {
        int cap = s->move_cap ? 2 * s->move_cap : 64;
        _move* grown = realloc(s->moves, (size_t)cap * sizeof *grown);
        if (!grown)
            abort(); /* a few hundred bytes: failure here means the process is done anyway */
        s->moves = grown;
        s->move_cap = cap;
    }
    s->moves[s->move_count++] = m;
}

/* Minimum-jerk move from `from` to `to` (yaw, pitch; radians) at a peak rate in
 * the configured range; returns its duration. */
static double _add_sweep(_synth* s, tv_rng* rng, double t0, const double from[2], const double to[2])
{
    double rate = tv_rng_range(rng, s->d.peak_rate_min_deg, s->d.peak_rate_max_deg) * PRED_DEG;
    double angle = hypot(to[0] - from[0], to[1] - from[1]);
    double dur = fmax(0.15, 1.875 * angle / rate);
    _push_move(s, (_move){t0, dur, {from[0], from[1]}, {to[0], to[1]}});
    return dur;
}

/* Walk look-arounds: turn away, hold, turn back; the offsets add to the walking yaw. */
static void _plan_walk_looks(_synth* s, tv_rng* rng)
{
    const pred_synth_desc* d = &s->d;
    if (d->look_amplitude_deg <= 0.0)
        return;
    const double zero[2] = {0.0, 0.0};
    double t = tv_rng_range(rng, 0.5, 1.5) * d->look_interval;
    while (t < s->duration) {
        double sign = tv_rng_uniform(rng) < 0.5 ? -1.0 : 1.0;
        double away[2] = {sign * tv_rng_range(rng, 0.5, 1.0) * d->look_amplitude_deg * PRED_DEG,
                          tv_rng_range(rng, -15.0, 10.0) * PRED_DEG};
        t += _add_sweep(s, rng, t, zero, away) + d->look_hold;
        t += _add_sweep(s, rng, t, away, zero);
        t += tv_rng_range(rng, 0.5, 1.5) * d->look_interval;
    }
}

static void _plan_lookaround(_synth* s, tv_rng* rng)
{
    const pred_synth_desc* d = &s->d;
    double cur[2] = {0.0, 0.0};
    double t = tv_rng_range(rng, 0.3, 0.8);
    while (t < s->duration) {
        double to[2];
        /* sweeps of at least 40 degrees (or half the range): small corrections are not what
         * stresses a predictor; from any yaw in range, half of the targets qualify */
        double min_sweep = fmin(40.0, 0.5 * d->yaw_range_deg) * PRED_DEG;
        do
            to[0] = tv_rng_range(rng, -d->yaw_range_deg, d->yaw_range_deg) * PRED_DEG;
        while (fabs(to[0] - cur[0]) < min_sweep);
        to[1] = tv_rng_range(rng, d->pitch_min_deg, d->pitch_max_deg) * PRED_DEG;
        t += _add_sweep(s, rng, t, cur, to);
        t += tv_rng_range(rng, d->hold_min, d->hold_max);
        cur[0] = to[0];
        cur[1] = to[1];
    }
}

static void _moves_eval(const _synth* s, double t, double out[2])
{
    out[0] = out[1] = 0.0;
    for (int i = 0; i < s->move_count && s->moves[i].t0 <= t; i++) {
        const _move* m = &s->moves[i];
        double u = _min_jerk((t - m->t0) / m->dur);
        out[0] = m->from[0] + u * (m->to[0] - m->from[0]);
        out[1] = m->from[1] + u * (m->to[1] - m->from[1]);
    }
}

static void _sample(const _synth* s, double t, pred_pose* out)
{
    const pred_synth_desc* d = &s->d;
    double look[2];
    _moves_eval(s, t, look);
    double eye_y = d->floor_y + d->eye_height;
    double yaw, pitch, roll;
    out->t = t;
    if (d->kind == PRED_SYNTH_WALK) {
        double x, z, phi, v, travelled;
        _walk_eval(s, t, &x, &z, &phi, &v, &travelled);
        double stride = d->speed / d->step_frequency; /* metres per step */
        double gait = v / d->speed;                    /* bob fades out when slowing down */
        double step_phase = 2.0 * PRED_PI * travelled / stride;
        out->p[0] = x;
        out->p[1] = eye_y + d->bob_amplitude * gait * sin(step_phase);
        out->p[2] = z;
        /* heading phi (x-z plane) to yaw about +Y for a head looking down -Z */
        yaw = -phi - 0.5 * PRED_PI + look[0] +
              d->yaw_osc_amplitude_deg * PRED_DEG * sin(2.0 * PRED_PI * t / d->yaw_osc_period);
        pitch = -4.0 * PRED_DEG + look[1];
        roll = 1.5 * PRED_DEG * gait * sin(0.5 * step_phase); /* sway once per stride (two steps) */
    } else {
        double a = d->sway_amplitude;
        out->p[0] = d->waypoints[0][0] + a * sin(2.0 * PRED_PI * t / 3.7);
        out->p[1] = eye_y + 0.3 * a * sin(2.0 * PRED_PI * t / 4.1 + 2.0);
        out->p[2] = d->waypoints[0][1] + a * sin(2.0 * PRED_PI * t / 5.3 + 1.0);
        yaw = d->base_yaw_deg * PRED_DEG + look[0];
        pitch = look[1];
        roll = 0.0;
    }
    pred_quat_from_ypr(yaw, pitch, roll, out->q);
}

static bool _validate(const pred_synth_desc* d, char* err, size_t err_size)
{
    if (d->kind != PRED_SYNTH_WALK && d->kind != PRED_SYNTH_LOOKAROUND)
        return _fail(err, err_size, "unknown kind");
    int min_points = d->kind == PRED_SYNTH_WALK ? 2 : 1;
    if (d->waypoint_count < min_points || d->waypoint_count > PRED_SYNTH_MAX_WAYPOINTS)
        return _fail(err, err_size, d->kind == PRED_SYNTH_WALK ? "a walk needs 2 to 64 waypoints"
                                                                : "a look-around needs 1 to 64 waypoints");
    for (int i = 0; i < d->waypoint_count; i++)
        if (!isfinite(d->waypoints[i][0]) || !isfinite(d->waypoints[i][1]))
            return _fail(err, err_size, "non-finite waypoint");
    const double positive[] = {d->eye_height, d->sample_rate, d->speed, d->accel_time, d->corner_radius,
                               d->stop_turn_deg, d->turn_rate_deg, d->yaw_osc_period, d->look_interval,
                               d->look_hold, d->step_frequency, d->duration, d->yaw_range_deg,
                               d->hold_min, d->peak_rate_min_deg};
    for (size_t i = 0; i < sizeof positive / sizeof positive[0]; i++)
        if (!(positive[i] > 0.0) || !isfinite(positive[i]))
            return _fail(err, err_size, "rates, speeds, durations and radii must be positive");
    if (d->hold_max < d->hold_min || d->peak_rate_max_deg < d->peak_rate_min_deg ||
        d->pitch_max_deg < d->pitch_min_deg)
        return _fail(err, err_size, "a range's maximum is below its minimum");
    if (d->duration * d->sample_rate > 1e8)
        return _fail(err, err_size, "more than 1e8 samples");
    return true;
}

bool pred_path_synth(const pred_synth_desc* desc, pred_path* out, char* err, size_t err_size)
{
    assert(desc && out);
    memset(out, 0, sizeof *out);
    _synth* s = calloc(1, sizeof *s);
    if (!s)
        return _fail(err, err_size, "out of memory");
    s->d = _resolve(desc);
    bool ok = _validate(&s->d, err, err_size);
    if (ok && s->d.kind == PRED_SYNTH_WALK)
        ok = _build_curve(s, err, err_size);
    if (ok) {
        tv_rng rng;
        tv_rng_seed(&rng, s->d.seed, 0x7472696d7672ull);
        if (s->d.kind == PRED_SYNTH_WALK) {
            _plan_walk_looks(s, &rng);
        } else {
            s->duration = s->d.duration;
            _plan_lookaround(s, &rng);
        }
        size_t n = (size_t)floor(s->duration * s->d.sample_rate + 1e-9) + 1;
        out->poses = malloc(n * sizeof *out->poses);
        ok = out->poses != NULL;
        if (!ok)
            _fail(err, err_size, "out of memory");
        for (size_t i = 0; ok && i < n; i++)
            _sample(s, (double)i / s->d.sample_rate, &out->poses[i]);
        out->count = ok ? n : 0;
        snprintf(out->scene, sizeof out->scene, "%s", s->d.scene ? s->d.scene : "");
        snprintf(out->description, sizeof out->description, "%s",
                 s->d.description ? s->d.description : "");
    }
    free(s->moves);
    free(s);
    return ok;
}
