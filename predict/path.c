#include "path.h"

#include "text_io.h"

#include <assert.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { COL_T, COL_PX, COL_PY, COL_PZ, COL_QX, COL_QY, COL_QZ, COL_QW, COL_COUNT };
static const char* const k_columns[COL_COUNT] = {"t", "px", "py", "pz", "qx", "qy", "qz", "qw"};

/* Copies the value of a "# key: value" metadata comment into dst. */
static void _metadata(const char* comment, const char* key, char* dst, size_t dst_size)
{
    size_t k = strlen(key);
    if (strncmp(comment, key, k) != 0 || comment[k] != ':')
        return;
    char tmp[512];
    snprintf(tmp, sizeof tmp, "%s", comment + k + 1);
    snprintf(dst, dst_size, "%s", pred_text_trim(tmp));
}

/* Header line -> for each field, its column id. */
static bool _parse_header(char* line, int* field_col, int* field_count, const char* file,
                          size_t line_no, char* err, size_t err_size)
{
    int seen[COL_COUNT] = {0};
    char* names[COL_COUNT + 1];
    int n = pred_text_split(line, names, COL_COUNT + 1);
    for (int i = 0; i < n; i++) {
        if (i > COL_COUNT) /* a ninth name is unknown or a duplicate, reported below */
            break;
        int col = -1;
        for (int c = 0; c < COL_COUNT; c++)
            if (strcmp(names[i], k_columns[c]) == 0)
                col = c;
        if (col < 0)
            return pred_text_fail(err, err_size, file, line_no, "unknown column '%s'", names[i]);
        if (seen[col])
            return pred_text_fail(err, err_size, file, line_no, "duplicate column '%s'", names[i]);
        seen[col] = 1;
        field_col[i] = col;
    }
    for (int c = 0; c < COL_COUNT; c++)
        if (!seen[c])
            return pred_text_fail(err, err_size, file, line_no, "missing column '%s'", k_columns[c]);
    *field_count = n;
    return true;
}

static bool _parse_row(char* line, const int* field_col, int field_count, double* v,
                       const char* file, size_t line_no, char* err, size_t err_size)
{
    char* fields[COL_COUNT];
    int n = pred_text_split(line, fields, COL_COUNT);
    if (n != field_count)
        return pred_text_fail(err, err_size, file, line_no, "expected %d fields, found %d", field_count, n);
    for (int i = 0; i < n; i++) {
        char* end = NULL;
        const char* name = k_columns[field_col[i]];
        double x = strtod(fields[i], &end);
        if (*fields[i] == '\0' || *end != '\0')
            return pred_text_fail(err, err_size, file, line_no, "unparsable number '%s' in column %s", fields[i], name);
        if (!isfinite(x))
            return pred_text_fail(err, err_size, file, line_no, "non-finite value '%s' in column %s", fields[i], name);
        v[field_col[i]] = x;
    }
    return true;
}

bool pred_path_append(pred_path* path, size_t* capacity, const pred_pose* pose)
{
    if (path->count == *capacity) {
        size_t grown_cap = *capacity ? *capacity * 2 : 1024;
        pred_pose* grown = realloc(path->poses, grown_cap * sizeof *grown);
        if (!grown)
            return false;
        path->poses = grown;
        *capacity = grown_cap;
    }
    path->poses[path->count++] = *pose;
    return true;
}

static bool _push_pose(pred_path* out, size_t* cap, const double* v)
{
    pred_pose p = {.t = v[COL_T]};
    for (int i = 0; i < 3; i++)
        p.p[i] = v[COL_PX + i];
    for (int i = 0; i < 4; i++)
        p.q[i] = v[COL_QX + i];
    pred_quat_normalize(p.q);
    return pred_path_append(out, cap, &p);
}

static bool _parse(char* text, pred_path* out, const char* file, char* err, size_t err_size)
{
    int field_col[COL_COUNT];
    int field_count = 0;
    size_t cap = 0, line_no = 0, prev_line = 0;
    char* cursor = text;
    for (char* line; (line = pred_text_next_line(&cursor)) != NULL;) {
        line_no++;
        char* s = pred_text_trim(line);
        if (*s == '#') {
            char* comment = pred_text_trim(s + 1);
            _metadata(comment, "scene", out->scene, sizeof out->scene);
            _metadata(comment, "description", out->description, sizeof out->description);
            continue;
        }
        if (*s == '\0')
            continue;
        if (!field_count) {
            if (!_parse_header(s, field_col, &field_count, file, line_no, err, err_size))
                return false;
            continue;
        }
        if (!cursor)
            return pred_text_fail(err, err_size, file, line_no,
                                  "last line has no newline (was the file cut short?); end the file with a newline "
                                  "if the line is complete");
        double v[COL_COUNT];
        if (!_parse_row(s, field_col, field_count, v, file, line_no, err, err_size))
            return false;
        double norm = sqrt(v[COL_QX] * v[COL_QX] + v[COL_QY] * v[COL_QY] + v[COL_QZ] * v[COL_QZ] +
                           v[COL_QW] * v[COL_QW]);
        if (norm < 0.5 || norm > 2.0)
            return pred_text_fail(err, err_size, file, line_no, "quaternion norm %g is not near 1", norm);
        if (fabs(v[COL_T]) > PRED_PATH_MAX_TIME_S)
            return pred_text_fail(err, err_size, file, line_no, "time %g is beyond %g s", v[COL_T],
                                  PRED_PATH_MAX_TIME_S);
        for (int i = 0; i < 3; i++)
            if (fabs(v[COL_PX + i]) > PRED_PATH_MAX_COORD_M)
                return pred_text_fail(err, err_size, file, line_no, "position %g in column %s is beyond %g m",
                                      v[COL_PX + i], k_columns[COL_PX + i], PRED_PATH_MAX_COORD_M);
        if (out->count) {
            double prev_t = out->poses[out->count - 1].t;
            if (v[COL_T] == prev_t)
                return pred_text_fail(err, err_size, file, line_no, "duplicate time %.9g (also on line %zu)",
                             v[COL_T], prev_line);
            if (v[COL_T] < prev_t)
                return pred_text_fail(err, err_size, file, line_no,
                             "time %.9g goes backwards (previous %.9g on line %zu)", v[COL_T], prev_t,
                             prev_line);
        }
        if (!_push_pose(out, &cap, v))
            return pred_text_fail(err, err_size, file, line_no, "out of memory");
        prev_line = line_no;
    }
    if (!field_count)
        return pred_text_fail(err, err_size, file, line_no ? line_no : 1, "empty file (no header line)");
    if (!out->count)
        return pred_text_fail(err, err_size, file, line_no, "no samples after the header");
    return true;
}

bool pred_path_load(const char* file, pred_path* out, char* err, size_t err_size)
{
    assert(file && out);
    memset(out, 0, sizeof *out);
    size_t size = 0;
    char* text = pred_text_read_file(file, &size, err, err_size);
    if (!text)
        return false;
    bool ok = _parse(text, out, file, err, err_size);
    free(text);
    if (!ok)
        pred_path_free(out);
    return ok;
}

bool pred_path_save(const pred_path* path, const char* file, const char* extra_comment,
                    char* err, size_t err_size)
{
    assert(path && file);
    FILE* f = fopen(file, "wb");
    if (!f)
        return pred_text_fail(err, err_size, file, 0, "cannot create (%s)", strerror(errno));
    if (path->scene[0])
        fprintf(f, "# scene: %s\n", path->scene);
    if (path->description[0])
        fprintf(f, "# description: %s\n", path->description);
    for (const char* c = extra_comment; c && *c;) {
        const char* nl = strchr(c, '\n');
        int len = nl ? (int)(nl - c) : (int)strlen(c);
        fprintf(f, "# %.*s\n", len, c);
        c += len + (nl ? 1 : 0);
    }
    fprintf(f, "t,px,py,pz,qx,qy,qz,qw\n");
    for (size_t i = 0; i < path->count; i++) {
        const pred_pose* p = &path->poses[i];
        fprintf(f, "%.6f,%.6f,%.6f,%.6f,%.9f,%.9f,%.9f,%.9f\n", p->t, p->p[0], p->p[1], p->p[2],
                p->q[0], p->q[1], p->q[2], p->q[3]);
    }
    bool ok = !ferror(f);
    ok = (fclose(f) == 0) && ok;
    if (!ok)
        return pred_text_fail(err, err_size, file, 0, "write error");
    return true;
}

void pred_path_free(pred_path* path)
{
    free(path->poses);
    memset(path, 0, sizeof *path);
}

void pred_path_sample(const pred_path* path, double t, pred_pose* out)
{
    assert(path && path->count >= 1 && out);
    const pred_pose* s = path->poses;
    size_t n = path->count;
    if (t <= s[0].t || n == 1) {
        *out = s[0];
    } else if (t >= s[n - 1].t) {
        *out = s[n - 1];
    } else {
        size_t lo = 0, hi = n - 1; /* invariant: s[lo].t <= t < s[hi].t */
        while (hi - lo > 1) {
            size_t mid = lo + (hi - lo) / 2;
            if (s[mid].t <= t)
                lo = mid;
            else
                hi = mid;
        }
        pred_pose_lerp(&s[lo], &s[hi], (t - s[lo].t) / (s[hi].t - s[lo].t), out);
    }
    out->t = t;
}

bool pred_path_resample(const pred_path* in, double rate_hz, pred_path* out, char* err, size_t err_size)
{
    assert(in && in->count >= 1 && out);
    memset(out, 0, sizeof *out);
    double duration = pred_path_duration(in);
    if (!(rate_hz > 0.0) || duration * rate_hz > 1e9) {
        snprintf(err, err_size, "resample rate %g Hz is not in (0, %g]", rate_hz, 1e9 / (duration > 1.0 ? duration : 1.0));
        return false;
    }
    size_t n = (size_t)floor(duration * rate_hz + 1e-9) + 1;
    out->poses = malloc(n * sizeof *out->poses);
    if (!out->poses) {
        snprintf(err, err_size, "resample: out of memory (%zu samples)", n);
        return false;
    }
    for (size_t i = 0; i < n; i++)
        pred_path_sample(in, in->poses[0].t + (double)i / rate_hz, &out->poses[i]);
    out->count = n;
    memcpy(out->scene, in->scene, sizeof out->scene);
    memcpy(out->description, in->description, sizeof out->description);
    return true;
}

double pred_path_duration(const pred_path* path)
{
    return path->count ? path->poses[path->count - 1].t - path->poses[0].t : 0.0;
}

double pred_path_mean_speed(const pred_path* path, double min_speed)
{
    double len = 0.0, time = 0.0;
    for (size_t i = 1; i < path->count; i++) {
        double step = pred_vec3_dist(path->poses[i].p, path->poses[i - 1].p);
        double dt = path->poses[i].t - path->poses[i - 1].t;
        if (step >= min_speed * dt) {
            len += step;
            time += dt;
        }
    }
    return time > 0.0 ? len / time : 0.0;
}
