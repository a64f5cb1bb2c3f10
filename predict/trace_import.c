#include "trace_import.h"

#include "log.h"
#include "text_io.h"

#include <assert.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { COL_T, COL_PX, COL_PY, COL_PZ, COL_QX, COL_QY, COL_QZ, COL_QW, COL_COUNT };
enum { MAX_FIELDS = 64 };

typedef struct trace_format {
    const char* columns[COL_COUNT]; /* t, px, py, pz, qx, qy, qz, qw */
    double seconds_per_unit;
} trace_format;

/* Indexed by pred_trace_format. OptiTrack: t_header_s is the message
 * header's stamp, set when Motive delivered the frame; t_bag_s is when the
 * bag recorder received it, i.e. later by the transport delay (0.05-0.33 ms
 * in the shared trace). The header stamp is the closer one to the capture. */
static const trace_format k_formats[PRED_TRACE_FORMAT_COUNT] = {
    [PRED_TRACE_HOLOLENS] = {{"timestamp", "x", "y", "z", "qx", "qy", "qz", "qw"}, 1e-7},
    [PRED_TRACE_OPTITRACK] = {{"t_header_s", "x", "y", "z", "qx", "qy", "qz", "qw"}, 1.0},
    [PRED_TRACE_QUEST] = {{"time", "HeadPosX", "HeadPosY", "HeadPosZ", "HeadOrientationX", "HeadOrientationY",
                           "HeadOrientationZ", "HeadOrientationW"},
                          1.0},
};
static const char* const k_format_names[PRED_TRACE_FORMAT_COUNT] = {"auto", "hololens", "optitrack", "quest"};

const char* pred_trace_format_name(pred_trace_format format)
{
    assert(format >= 0 && format < PRED_TRACE_FORMAT_COUNT);
    return k_format_names[format];
}

bool pred_trace_format_from_name(const char* name, pred_trace_format* format)
{
    for (int f = 0; f < PRED_TRACE_FORMAT_COUNT; f++)
        if (strcmp(name, k_format_names[f]) == 0) {
            *format = (pred_trace_format)f;
            return true;
        }
    return false;
}

/* The field index of each of the format's columns; false names the first missing one. */
static bool _match_columns(pred_trace_format f, char** names, int n, int* field_of, const char** missing)
{
    for (int c = 0; c < COL_COUNT; c++) {
        field_of[c] = -1;
        for (int i = 0; i < n; i++)
            if (strcmp(names[i], k_formats[f].columns[c]) == 0)
                field_of[c] = i;
        if (field_of[c] < 0) {
            *missing = k_formats[f].columns[c];
            return false;
        }
    }
    return true;
}

/* A time stamp as a whole part and a fraction: .NET ticks (about 6e17) and
 * Unix seconds with nanoseconds both carry more digits than a double holds,
 * and only differences from the first stamp matter. */
static bool _parse_time(const char* s, long long* whole, double* frac)
{
    char* end = NULL;
    double v = strtod(s, &end);
    if (*s == '\0' || *end != '\0' || !isfinite(v))
        return false;
    *whole = 0;
    *frac = v;
    if (strpbrk(s, "eExXpPnN")) /* exponent, hex or nan/inf spellings: the double is all there is */
        return true;
    errno = 0;
    long long w = strtoll(s, &end, 10);
    if (errno == ERANGE || (*end != '\0' && *end != '.'))
        return true;
    *whole = w;
    *frac = *end == '.' ? strtod(end, NULL) : 0.0;
    if (s[strspn(s, " ")] == '-')
        *frac = -*frac;
    return true;
}

static void _to_trimvr_frame(pred_trace_format f, pred_pose* p)
{
    if (f == PRED_TRACE_HOLOLENS) {
        /* Mirror z: M = diag(1, 1, -1). A rotation R becomes M R M, whose
         * quaternion is (-qx, -qy, qz, qw); the Unity head's forward, local
         * +Z, becomes local -Z: M R e_z = (M R M)(-e_z). */
        p->p[2] = -p->p[2];
        p->q[0] = -p->q[0];
        p->q[1] = -p->q[1];
    } else if (f == PRED_TRACE_OPTITRACK) {
        /* Already right-handed and y-up, but the rigid body faces local +Z:
         * half a turn about local +Y makes local -Z the forward. */
        static const double half_turn[4] = {0.0, 1.0, 0.0, 0.0};
        pred_quat_mul(p->q, half_turn, p->q);
    }
}

typedef struct import_state {
    const char* file;
    pred_trace_format format;
    int field_count;
    int field_of[COL_COUNT];
    long long t0_whole;
    double t0_frac;
    size_t cap;
} import_state;

static bool _header(import_state* st, char* line, size_t line_no, char* err, size_t err_size)
{
    char* names[MAX_FIELDS];
    int n = pred_text_split(line, names, MAX_FIELDS);
    if (n > MAX_FIELDS)
        return pred_text_fail(err, err_size, st->file, line_no, "header has %d columns (at most %d)", n, MAX_FIELDS);
    const char* missing = NULL;
    if (st->format != PRED_TRACE_AUTO) {
        if (!_match_columns(st->format, names, n, st->field_of, &missing))
            return pred_text_fail(err, err_size, st->file, line_no, "header lacks column '%s' of the %s format",
                                  missing, pred_trace_format_name(st->format));
    } else {
        for (int f = PRED_TRACE_AUTO + 1; f < PRED_TRACE_FORMAT_COUNT && st->format == PRED_TRACE_AUTO; f++)
            if (_match_columns((pred_trace_format)f, names, n, st->field_of, &missing))
                st->format = (pred_trace_format)f;
        if (st->format == PRED_TRACE_AUTO)
            return pred_text_fail(err, err_size, st->file, line_no,
                                  "header matches no trace format (hololens: timestamp,x,y,z,qx,qy,qz,qw; "
                                  "optitrack: t_header_s,...; quest: ...,HeadPosX,...,time)");
    }
    st->field_count = n;
    return true;
}

static bool _row(import_state* st, char* line, size_t line_no, pred_path* out, pred_trace_report* rep,
                 char* err, size_t err_size)
{
    char* fields[MAX_FIELDS];
    int n = pred_text_split(line, fields, MAX_FIELDS);
    if (n != st->field_count)
        return pred_text_fail(err, err_size, st->file, line_no, "expected %d fields, found %d", st->field_count, n);
    const char* const* names = k_formats[st->format].columns;
    long long whole;
    double frac;
    if (!_parse_time(fields[st->field_of[COL_T]], &whole, &frac))
        return pred_text_fail(err, err_size, st->file, line_no, "unparsable time '%s' in column %s",
                              fields[st->field_of[COL_T]], names[COL_T]);
    double v[COL_COUNT];
    for (int c = COL_PX; c < COL_COUNT; c++) {
        const char* s = fields[st->field_of[c]];
        char* end = NULL;
        v[c] = strtod(s, &end);
        if (*s == '\0' || *end != '\0')
            return pred_text_fail(err, err_size, st->file, line_no, "unparsable number '%s' in column %s", s,
                                  names[c]);
        if (!isfinite(v[c]))
            return pred_text_fail(err, err_size, st->file, line_no, "non-finite value '%s' in column %s", s,
                                  names[c]);
    }
    rep->rows++;
    if (rep->rows == 1) {
        st->t0_whole = whole;
        st->t0_frac = frac;
    }
    /* Times are kept relative to the first sample's, in whole units and a
     * fraction, so that nanosecond stamps keep their precision; a stamp too
     * far from the first one for that (or for a path file: PRED_PATH_MAX_TIME_S)
     * is an error, not a wrapped or infinite time. */
    double scale = k_formats[st->format].seconds_per_unit;
    long long dwhole;
    double t = 0.0;
    if (__builtin_sub_overflow(whole, st->t0_whole, &dwhole) ||
        !(fabs(t = (double)dwhole * scale + (frac - st->t0_frac) * scale) <= PRED_PATH_MAX_TIME_S))
        return pred_text_fail(err, err_size, st->file, line_no, "time '%s' in column %s is too far from the first row's",
                              fields[st->field_of[COL_T]], names[COL_T]);
    pred_pose pose = {.t = t,
                      .p = {v[COL_PX], v[COL_PY], v[COL_PZ]},
                      .q = {v[COL_QX], v[COL_QY], v[COL_QZ], v[COL_QW]}};
    double norm = pred_quat_normalize(pose.q);
    if (norm < 0.5 || norm > 2.0)
        return pred_text_fail(err, err_size, st->file, line_no, "quaternion norm %g is not near 1", norm);
    if (out->count && pose.t <= out->poses[out->count - 1].t) {
        if (!rep->dropped++)
            rep->first_dropped_line = line_no;
        return true;
    }
    _to_trimvr_frame(st->format, &pose);
    if (!pred_path_append(out, &st->cap, &pose))
        return pred_text_fail(err, err_size, st->file, line_no, "out of memory");
    return true;
}

static bool _parse(import_state* st, char* text, pred_path* out, pred_trace_report* rep, char* err,
                   size_t err_size)
{
    size_t line_no = 0;
    bool have_header = false;
    char* cursor = text;
    for (char* line; (line = pred_text_next_line(&cursor)) != NULL;) {
        line_no++;
        char* s = pred_text_trim(line);
        if (*s == '\0')
            continue;
        if (have_header && !cursor) {
            /* A recorder killed mid-write leaves such a line; its last number
             * may be cut and would still parse. */
            rep->cut_line = line_no;
            tv_log(TV_LOG_WARN, "%s:%zu: last line has no newline (file cut short?); dropped", st->file, line_no);
            break;
        }
        bool ok = have_header ? _row(st, s, line_no, out, rep, err, err_size)
                              : _header(st, s, line_no, err, err_size);
        if (!ok)
            return false;
        have_header = true;
    }
    if (!have_header)
        return pred_text_fail(err, err_size, st->file, 0, "empty file (no header line)");
    if (out->count < 2)
        return pred_text_fail(err, err_size, st->file, 0, "%zu usable sample(s); a trace needs two", out->count);
    return true;
}

bool pred_trace_import(const char* file, const pred_trace_desc* desc, pred_path* out,
                       pred_trace_report* report, char* err, size_t err_size)
{
    assert(file && desc && out);
    assert(desc->format >= 0 && desc->format < PRED_TRACE_FORMAT_COUNT);
    memset(out, 0, sizeof *out);
    pred_trace_report local;
    pred_trace_report* rep = report ? report : &local;
    memset(rep, 0, sizeof *rep);
    size_t size = 0;
    char* text = pred_text_read_file(file, &size, err, err_size);
    if (!text)
        return false;
    import_state st = {.file = file, .format = desc->format};
    bool ok = _parse(&st, text, out, rep, err, err_size);
    free(text);
    if (!ok) {
        pred_path_free(out);
        return false;
    }
    rep->format = st.format;
    double gap_s = desc->gap_s > 0.0 ? desc->gap_s : 0.1;
    for (size_t i = 1; i < out->count; i++) {
        double dt = out->poses[i].t - out->poses[i - 1].t;
        rep->gaps += dt > gap_s;
        if (dt > rep->max_gap_s)
            rep->max_gap_s = dt;
    }
    const char* base = strrchr(file, '/') ? strrchr(file, '/') + 1 : file;
    snprintf(out->description, sizeof out->description, "recorded trace %s (%s format)", base,
             pred_trace_format_name(st.format));
    return true;
}
