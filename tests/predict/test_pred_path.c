/* Path CSV parsing, error messages, save/load round trip, interpolation. */
#include "path.h"
#include "rng.h"
#include "test.h"

#include <stdlib.h>
#include <string.h>

static void _write(const char* file, const char* text)
{
    FILE* f = fopen(file, "wb");
    fputs(text, f);
    fclose(f);
}

/* Loads `text` from a scratch file and returns whether it loaded; err gets the message. */
static bool _load_text(const char* text, pred_path* path, char* err, size_t err_size)
{
    _write("pred_path_case.csv", text);
    return pred_path_load("pred_path_case.csv", path, err, err_size);
}

static void test_good_file(void)
{
    const char* text = "# scene: builtin:city\n"
                       "# description:  a short test path \n"
                       "\n"
                       "qw, t,px,py,pz,qx,qy,qz\n"
                       "1,0,0,1.7,0,0,0,0\n"
                       "# a comment between rows\n"
                       "\n"
                       "2,0.5,1,1.7,0,0,0,0\n" /* norm 2 quaternion: normalised */
                       "0.70710678,1.0,2,1.7,-1,0,0.70710678,0\r\n";
    pred_path path;
    char err[256] = "";
    TV_CHECK(_load_text(text, &path, err, sizeof err));
    TV_CHECK(path.count == 3);
    TV_CHECK(strcmp(path.scene, "builtin:city") == 0);
    TV_CHECK(strcmp(path.description, "a short test path") == 0);
    TV_CHECK_NEAR(path.poses[1].t, 0.5, 0);
    TV_CHECK_NEAR(path.poses[1].p[0], 1.0, 0);
    TV_CHECK_NEAR(path.poses[1].q[3], 1.0, 1e-15);
    TV_CHECK_NEAR(path.poses[2].p[2], -1.0, 0);
    TV_CHECK_NEAR(path.poses[2].q[1], sqrt(0.5), 1e-8);
    TV_CHECK_NEAR(pred_path_duration(&path), 1.0, 0);
    pred_path_free(&path);
    TV_CHECK(path.poses == NULL && path.count == 0);
}

typedef struct error_case {
    const char* text;
    const char* expect; /* substring of the message, after the file name */
} error_case;

static void test_errors_name_file_and_line(void)
{
    const error_case cases[] = {
        {"", "pred_path_case.csv:1: empty file"},
        {"# only\n\n# comments\n", "pred_path_case.csv:3: empty file"},
        {"t,px,py,pz,qx,qy,qz\n0,0,0,0,0,0,0\n", ":1: missing column 'qw'"},
        {"#c\nt,px,py,pz,qx,qy,qz,qw,speed\n", ":2: unknown column 'speed'"},
        {"t,px,py,pz,qx,qy,qz,qw,t\n", ":1: duplicate column 't'"},
        {"t,px,py,pz,qx,qy,qz,qw\n", ":1: no samples"},
        {"t,px,py,pz,qx,qy,qz,qw\n0,0,0,0,0,0,0\n", ":2: expected 8 fields, found 7"},
        {"t,px,py,pz,qx,qy,qz,qw\n0,0,0,0,0,0,0,1,5\n", ":2: expected 8 fields, found 9"},
        {"t,px,py,pz,qx,qy,qz,qw\n0,0,0,0,0,0,0,1\n1,0,abc,0,0,0,0,1\n", ":3: unparsable number 'abc' in column py"},
        {"t,px,py,pz,qx,qy,qz,qw\n0,0,0,,0,0,0,1\n", ":2: unparsable number '' in column pz"},
        {"t,px,py,pz,qx,qy,qz,qw\n0,0,0,1.5x,0,0,0,1\n", ":2: unparsable number '1.5x'"},
        {"t,px,py,pz,qx,qy,qz,qw\n0,nan,0,0,0,0,0,1\n", ":2: non-finite value 'nan' in column px"},
        {"t,px,py,pz,qx,qy,qz,qw\n0,0,0,0,0,0,0,1\n1,0,0,inf,0,0,0,1\n", ":3: non-finite value 'inf' in column pz"},
        {"t,px,py,pz,qx,qy,qz,qw\n0,0,1e300,0,0,0,0,1\n", ":2: position 1e+300 in column py is beyond 1e+06 m"},
        /* a replay from 1e15 s never ended: its 1 ms sensor steps did not advance the clock */
        {"t,px,py,pz,qx,qy,qz,qw\n1e15,0,0,0,0,0,0,1\n1.000000000000125e15,0,0,0,0,0,0,1\n",
         ":2: time 1e+15 is beyond 1e+10 s"},
        {"t,px,py,pz,qx,qy,qz,qw\n0,0,0,0,0,0,0,1\n-2e10,0,0,0,0,0,0,1\n", ":3: time -2e+10 is beyond 1e+10 s"},
        {"t,px,py,pz,qx,qy,qz,qw\n0,0,0,0,0,0,0,0.3\n", ":2: quaternion norm 0.3"},
        {"t,px,py,pz,qx,qy,qz,qw\n0,0,0,0,2,0,0,1\n", ":2: quaternion norm"},
        {"t,px,py,pz,qx,qy,qz,qw\n0,0,0,0,0,0,0,1\n#x\n0.5,0,0,0,0,0,0,1\n0.2,0,0,0,0,0,0,1\n",
         ":5: time 0.2 goes backwards (previous 0.5 on line 4)"},
        {"t,px,py,pz,qx,qy,qz,qw\n0,0,0,0,0,0,0,1\n0,0,0,0,0,0,0,1\n", ":3: duplicate time 0 (also on line 2)"},
        /* a file cut in its last number ("0.9" of "0.95") still parses: refuse a last row without newline */
        {"t,px,py,pz,qx,qy,qz,qw\n0,0,0,0,0,0,0,1\n1,0,0,0,0,0,0,0.9", ":3: last line has no newline"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        pred_path path;
        char err[256] = "";
        bool ok = _load_text(cases[i].text, &path, err, sizeof err);
        TV_CHECK(!ok);
        TV_CHECK(path.poses == NULL && path.count == 0);
        TV_CHECK(strncmp(err, "pred_path_case.csv:", 19) == 0);
        TV_CHECK(strchr(err, '\n') == NULL);
        if (!strstr(err, cases[i].expect))
            fprintf(stderr, "case %zu: message '%s' lacks '%s'\n", i, err, cases[i].expect);
        TV_CHECK(strstr(err, cases[i].expect) != NULL);
    }
}

static void test_missing_file(void)
{
    pred_path path;
    char err[256] = "";
    TV_CHECK(!pred_path_load("no/such/dir/path.csv", &path, err, sizeof err));
    TV_CHECK(strstr(err, "no/such/dir/path.csv: cannot open") == err);
    /* a folder opens but does not read: the message says why, not only "read error" */
    TV_CHECK(!pred_path_load(".", &path, err, sizeof err));
    TV_CHECK(strcmp(err, ".: read error (Is a directory)") == 0);
}

static void test_round_trip(void)
{
    pred_path a = {0};
    a.count = 50;
    a.poses = calloc(a.count, sizeof *a.poses);
    snprintf(a.scene, sizeof a.scene, "builtin:interior");
    snprintf(a.description, sizeof a.description, "round trip");
    for (size_t i = 0; i < a.count; i++) {
        pred_pose* p = &a.poses[i];
        p->t = 0.0123 * (double)i + 1e-7;
        p->p[0] = -12.3456789 + 0.1 * i;
        p->p[1] = 1.7 + 0.001 * sin(i);
        p->p[2] = 40.0 * cos(0.1 * i);
        pred_quat_from_ypr(0.3 * i, 0.2 * sin(i), 0.01 * i, p->q);
    }
    char err[256];
    TV_CHECK(pred_path_save(&a, "pred_path_round_trip.csv", "generated by: test\nsecond line", err, sizeof err));
    pred_path b;
    TV_CHECK(pred_path_load("pred_path_round_trip.csv", &b, err, sizeof err));
    TV_CHECK(b.count == a.count);
    TV_CHECK(strcmp(b.scene, a.scene) == 0 && strcmp(b.description, a.description) == 0);
    for (size_t i = 0; i < a.count && b.count == a.count; i++) {
        TV_CHECK_NEAR(b.poses[i].t, a.poses[i].t, 1e-6);
        for (int k = 0; k < 3; k++)
            TV_CHECK_NEAR(b.poses[i].p[k], a.poses[i].p[k], 1e-6);
        for (int k = 0; k < 4; k++)
            TV_CHECK_NEAR(b.poses[i].q[k], a.poses[i].q[k], 1e-6);
    }
    TV_CHECK(!pred_path_save(&a, "no/such/dir/x.csv", NULL, err, sizeof err));
    TV_CHECK(strstr(err, "no/such/dir/x.csv: cannot create") == err);
    pred_path_free(&a);
    pred_path_free(&b);
}

static pred_path _two_poses(const double q0[4], const double q1[4])
{
    pred_path path = {0};
    path.count = 2;
    path.poses = calloc(2, sizeof *path.poses);
    path.poses[0] = (pred_pose){.t = 1.0, .p = {0, 0, 0}, .q = {q0[0], q0[1], q0[2], q0[3]}};
    path.poses[1] = (pred_pose){.t = 3.0, .p = {2, 4, -6}, .q = {q1[0], q1[1], q1[2], q1[3]}};
    return path;
}

static void test_sample_lerp_slerp(void)
{
    double q0[4], q1[4], expect[4];
    pred_quat_from_ypr(0.0, 0.0, 0.0, q0);
    pred_quat_from_ypr(1.2, 0.0, 0.0, q1);
    pred_path path = _two_poses(q0, q1);
    pred_pose s;
    pred_path_sample(&path, 2.0, &s);
    TV_CHECK_NEAR(s.t, 2.0, 0);
    TV_CHECK_NEAR(s.p[0], 1.0, 1e-12);
    TV_CHECK_NEAR(s.p[1], 2.0, 1e-12);
    TV_CHECK_NEAR(s.p[2], -3.0, 1e-12);
    pred_quat_from_ypr(0.6, 0.0, 0.0, expect);
    TV_CHECK_NEAR(pred_quat_angle_deg(s.q, expect), 0.0, 1e-9);
    pred_path_sample(&path, 1.5, &s);
    pred_quat_from_ypr(0.3, 0.0, 0.0, expect);
    TV_CHECK_NEAR(pred_quat_angle_deg(s.q, expect), 0.0, 1e-9);
    /* clamped outside the time span */
    pred_path_sample(&path, -5.0, &s);
    TV_CHECK(s.p[0] == 0.0 && s.q[3] == q0[3] && s.t == -5.0);
    pred_path_sample(&path, 99.0, &s);
    TV_CHECK(s.p[2] == -6.0 && pred_quat_angle_deg(s.q, q1) < 1e-12);
    pred_path_free(&path);
}

static void test_slerp_shortest_arc(void)
{
    /* yaw 170 deg stored as -q: the short way to yaw -170 is 20 deg through 180 */
    double q0[4], q1[4], expect[4];
    pred_quat_from_ypr(170.0 * PRED_DEG, 0.0, 0.0, q0);
    pred_quat_from_ypr(-170.0 * PRED_DEG, 0.0, 0.0, q1);
    for (int i = 0; i < 4; i++)
        q0[i] = -q0[i];
    pred_path path = _two_poses(q0, q1);
    pred_pose s;
    pred_path_sample(&path, 2.0, &s);
    pred_quat_from_ypr(180.0 * PRED_DEG, 0.0, 0.0, expect);
    TV_CHECK_NEAR(pred_quat_angle_deg(s.q, expect), 0.0, 1e-9);
    pred_path_sample(&path, 1.5, &s);
    pred_quat_from_ypr(175.0 * PRED_DEG, 0.0, 0.0, expect);
    TV_CHECK_NEAR(pred_quat_angle_deg(s.q, expect), 0.0, 1e-9);
    pred_path_free(&path);
}

static void test_sample_many(void)
{
    /* binary search: every knot and every midpoint of a long uneven path */
    pred_path path = {0};
    path.count = 1000;
    path.poses = calloc(path.count, sizeof *path.poses);
    double t = 0.0;
    for (size_t i = 0; i < path.count; i++) {
        t += 0.001 + 0.0005 * (double)(i % 7);
        path.poses[i] = (pred_pose){.t = t, .p = {(double)i, 0, 0}, .q = {0, 0, 0, 1}};
    }
    int bad = 0;
    for (size_t i = 0; i + 1 < path.count; i++) {
        pred_pose s;
        pred_path_sample(&path, path.poses[i].t, &s);
        bad += s.p[0] != (double)i;
        pred_path_sample(&path, 0.5 * (path.poses[i].t + path.poses[i + 1].t), &s);
        bad += fabs(s.p[0] - (i + 0.5)) > 1e-9;
    }
    TV_CHECK(bad == 0);
    pred_path_free(&path);
}

/* Random byte edits and truncations of a good file: every load either fails
 * with a one-line "file:..." message and an empty path, or gives a valid path
 * (finite values, increasing time, unit quaternions). Under ASan this is the
 * parser's memory-safety check. */
static void test_mutations(void)
{
    const char* good = "# scene: s\nt,px,py,pz,qx,qy,qz,qw\n0,1,2,3,0,0,0,1\n0.01,1.5,2,3,0,0.1,0,1\n"
                       "#c\n0.02,-1e3,2e-3,3,0.2,0,0,1\n0.5,0,0,0,0,0,1,0\n";
    const char alphabet[] = "0123456789.,-+e#\n\r nNaIf";
    tv_rng rng;
    tv_rng_seed(&rng, 77, 0);
    char text[256];
    int loaded = 0, failed = 0, bad = 0;
    for (int iter = 0; iter < 3000; iter++) {
        size_t n = strlen(good);
        memcpy(text, good, n + 1);
        int edits = 1 + (int)(tv_rng_u32(&rng) % 3);
        for (int e = 0; e < edits; e++)
            text[tv_rng_u32(&rng) % n] = alphabet[tv_rng_u32(&rng) % (sizeof alphabet - 1)];
        if (tv_rng_u32(&rng) % 4 == 0)
            text[tv_rng_u32(&rng) % n] = '\0';
        pred_path path;
        char err[256] = "";
        if (_load_text(text, &path, err, sizeof err)) {
            loaded++;
            for (size_t i = 0; i < path.count; i++) {
                const pred_pose* p = &path.poses[i];
                double qn = sqrt(p->q[0] * p->q[0] + p->q[1] * p->q[1] + p->q[2] * p->q[2] + p->q[3] * p->q[3]);
                bad += !isfinite(p->t) || !isfinite(p->p[0] + p->p[1] + p->p[2]) || fabs(qn - 1.0) > 1e-12;
                bad += i > 0 && !(p->t > path.poses[i - 1].t);
            }
            pred_path_free(&path);
        } else {
            failed++;
            bad += path.poses != NULL || strncmp(err, "pred_path_case.csv:", 19) != 0 || strchr(err, '\n') != NULL;
        }
    }
    TV_CHECK(bad == 0);
    TV_CHECK(loaded > 100 && failed > 100); /* the mutations exercise both outcomes */
}

int main(void)
{
    TV_TEST_RUN(test_good_file);
    TV_TEST_RUN(test_errors_name_file_and_line);
    TV_TEST_RUN(test_missing_file);
    TV_TEST_RUN(test_round_trip);
    TV_TEST_RUN(test_sample_lerp_slerp);
    TV_TEST_RUN(test_slerp_shortest_arc);
    TV_TEST_RUN(test_sample_many);
    TV_TEST_RUN(test_mutations);
    return tv_test_finish();
}
