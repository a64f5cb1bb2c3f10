/* The bundled paths in paths/: they load, match their recipes (`trimvr path
 * synth` reproduces them), have the claimed speeds and durations, and stay inside the
 * free space each scene's contract declares (docs/paths.md). */
#include "path_bundled.h"
#include "test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char* g_root;

static bool _in_city_streets(const double p[3])
{
    if (fabs(p[0]) > 80.0 || fabs(p[2]) > 80.0)
        return false;
    double dx = fabs(p[0] - 40.0 * round(p[0] / 40.0)), dz = fabs(p[2] - 40.0 * round(p[2] / 40.0));
    return fmin(dx, dz) <= 1.5;
}

static bool _in_interior_free_space(const double p[3])
{
    const double head = 0.2; /* a head's radius from the walls */
    if (fabs(p[2]) <= 1.5 - head && fabs(p[0]) <= 24.0 - head)
        return true;
    const double rooms[4] = {-18, -6, 6, 18};
    for (int r = 0; r < 4; r++) /* on the doorway -> room centre line (door 1.2 m wide) */
        if (fabs(p[0] - rooms[r]) <= 0.6 - head && fabs(p[2]) <= 6.5)
            return true;
    return false;
}

/* builtin:house: within 0.45 m of the walk's lanes (procedural.h; tested
 * clear 0.3 m either side by test_procedural), which the 1 m corner fillets
 * cut by at most 0.41 m, inside the rooms they turn in. */
static bool _on_house_lanes(const double p[3])
{
    const double lanes[7][2] = {{-0.75, 8.5}, {-0.75, -2.25}, {-3.25, -2.25}, {-3.25, 2.25},
                                {-0.75, 2.25}, {-0.75, -3.25}, {3.25, -3.25}};
    for (int i = 0; i < 6; i++) {
        double x0 = fmin(lanes[i][0], lanes[i + 1][0]), x1 = fmax(lanes[i][0], lanes[i + 1][0]);
        double z0 = fmin(lanes[i][1], lanes[i + 1][1]), z1 = fmax(lanes[i][1], lanes[i + 1][1]);
        double dx = fmax(0.0, fmax(x0 - p[0], p[0] - x1)), dz = fmax(0.0, fmax(z0 - p[2], p[2] - z1));
        if (dx * dx + dz * dz <= 0.45 * 0.45)
            return true;
    }
    return false;
}

/* Checked against the Sponza geometry (docs/paths.md): no triangle comes
 * within 0.48 m (horizontally) of this box between 0.05 and 2 m above the floor. */
static bool _in_sponza_atrium(const double p[3])
{
    return p[0] >= -10.5 && p[0] <= 11.3 && p[2] >= -1.8 && p[2] <= 1.4;
}

static void test_bundled(void)
{
    TV_CHECK(pred_bundled_path_count() == 10);
    for (int i = 0; i < pred_bundled_path_count(); i++) {
        const pred_bundled_path* b = pred_bundled_path_get(i);
        char file[1024], err[512];
        snprintf(file, sizeof file, "%s/paths/%s", g_root, b->file);
        pred_path on_disk, fresh;
        bool loaded = pred_path_load(file, &on_disk, err, sizeof err);
        if (!loaded)
            fprintf(stderr, "%s\n", err);
        TV_CHECK(loaded);
        if (!loaded)
            continue;
        TV_CHECK(pred_path_synth(&b->desc, &fresh, err, sizeof err));
        TV_CHECK(strcmp(on_disk.scene, b->desc.scene) == 0);
        TV_CHECK(on_disk.count == fresh.count);
        double worst = 0.0;
        for (size_t s = 0; s < on_disk.count && on_disk.count == fresh.count; s++) {
            worst = fmax(worst, fabs(on_disk.poses[s].t - fresh.poses[s].t));
            worst = fmax(worst, pred_vec3_dist(on_disk.poses[s].p, fresh.poses[s].p));
            worst = fmax(worst, pred_quat_angle_deg(on_disk.poses[s].q, fresh.poses[s].q) * PRED_DEG);
        }
        if (worst > 2e-6)
            fprintf(stderr, "%s differs from its recipe by %g: rerun trimvr path synth --out paths\n", b->file, worst);
        TV_CHECK(worst <= 2e-6);

        double duration = pred_path_duration(&on_disk);
        bool is_run = strcmp(b->label, "run") == 0, is_walk = strcmp(b->label, "walk") == 0;
        if (is_walk || is_run) {
            double nominal = is_run ? 3.0 : 1.4;
            TV_CHECK(b->desc.speed == (is_run ? 3.0 : 0.0)); /* 0: the 1.4 m/s default */
            double moving = pred_path_mean_speed(&on_disk, 0.1 * nominal);
            if (fabs(moving / nominal - 1.0) > 0.1)
                fprintf(stderr, "%s: mean moving speed %.3f m/s, claimed %.1f\n", b->file, moving, nominal);
            TV_CHECK(fabs(moving / nominal - 1.0) <= 0.1);
            TV_CHECK(is_walk ? (duration >= 20.0 && duration <= 40.0) : (duration >= 10.0 && duration <= 20.0));
        } else {
            TV_CHECK(pred_path_mean_speed(&on_disk, 0.0) < 0.05);
            TV_CHECK(duration >= 10.0 && duration <= 20.0);
        }
        int outside = 0, bad_height = 0;
        for (size_t s = 0; s < on_disk.count; s++) {
            const double* p = on_disk.poses[s].p;
            bad_height += fabs(p[1] - 1.7) > 0.05;
            if (strcmp(on_disk.scene, "builtin:city") == 0)
                outside += !_in_city_streets(p);
            else if (strcmp(on_disk.scene, "builtin:interior") == 0)
                outside += !_in_interior_free_space(p);
            else if (strcmp(on_disk.scene, "builtin:house") == 0)
                outside += !_on_house_lanes(p);
            else
                outside += !_in_sponza_atrium(p);
        }
        if (outside || bad_height)
            fprintf(stderr, "%s: %d samples outside the free space, %d off eye height\n", b->file, outside, bad_height);
        TV_CHECK(outside == 0 && bad_height == 0);
        pred_path_free(&on_disk);
        pred_path_free(&fresh);
    }
}

int main(void)
{
    g_root = getenv("TRIMVR_SOURCE_DIR");
    if (!g_root) {
        printf("skip: TRIMVR_SOURCE_DIR is not set\n");
        return 77;
    }
    TV_TEST_RUN(test_bundled);
    return tv_test_finish();
}
