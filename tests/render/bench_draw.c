/* render_bench: full-scene draw timings.
 *
 *   render_bench [scene-spec] [repeats] [WxH...]
 *
 * Loads the scene (default builtin:city), puts the camera at the centre of
 * its bounds looking along the longer horizontal axis, and prints the median
 * CPU (record + submit + wait) and GPU (timestamp) time of `repeats` full
 * draws (default 10) at each size (default 640x360 and 1280x720), after one
 * warm-up draw.
 * Validation follows TRIMVR_VALIDATION like everything else: leave it unset
 * when measuring. Relative paths of shared scenes may be given as
 * shared:<path>, resolved against TRIMVR_SHARED. */
#include "render.h"

#include "stats.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int fail(const char* what, const char* err)
{
    fprintf(stderr, "render_bench: %s: %s\n", what, err);
    return 1;
}

static rnd_camera centre_camera(const scn_scene* s)
{
    rnd_camera cam = {.fov_y_deg = 60, .near_m = 0.05f, .far_m = 1000};
    for (int i = 0; i < 3; i++)
        cam.position[i] = 0.5f * (s->bounds_min[i] + s->bounds_max[i]);
    const float h = sqrtf(0.5f);
    bool along_x = s->bounds_max[0] - s->bounds_min[0] > s->bounds_max[2] - s->bounds_min[2];
    /* -90 degrees about +Y turns the camera's -Z onto +X */
    const float q[4] = {0, along_x ? -h : 0, 0, along_x ? h : 1};
    memcpy(cam.orientation, q, sizeof q);
    return cam;
}

int main(int argc, char** argv)
{
    const char* spec = argc > 1 ? argv[1] : "builtin:city";
    const int repeats = argc > 2 ? atoi(argv[2]) : 10;
    if (repeats < 1)
        return fail("repeats", "must be a positive integer");
    char path[1024], err[1024];
    if (strncmp(spec, "shared:", 7) == 0) {
        const char* shared = getenv("TRIMVR_SHARED");
        if (!shared || !*shared) {
            fprintf(stderr, "render_bench: %s needs TRIMVR_SHARED; skipping\n", spec);
            return 77;
        }
        snprintf(path, sizeof path, "%s/%s", shared, spec + 7);
        spec = path;
    }
    scn_scene scene;
    if (!scn_load(spec, &scene, err, sizeof err))
        return fail("scene", err);
    rnd_context* ctx = rnd_create(NULL, err, sizeof err);
    if (!ctx)
        return fail("device", err);
    rnd_gpu_scene* gpu = rnd_scene_create(ctx, &scene, err, sizeof err);
    if (!gpu)
        return fail("upload", err);
    const rnd_camera cam = centre_camera(&scene);
    const char* tunables = getenv("GLIBC_TUNABLES");
    printf("scene %s: %u triangles, device %s, GLIBC_TUNABLES %s\n", scene.name, scene.triangle_count,
           rnd_device_name(ctx), tunables && *tunables ? tunables : "(unset)");
    uint32_t sizes[16][2] = {{640, 360}, {1280, 720}};
    int size_count = argc > 3 ? 0 : 2;
    for (int a = 3; a < argc && size_count < 16; a++, size_count++)
        if (sscanf(argv[a], "%ux%u", &sizes[size_count][0], &sizes[size_count][1]) != 2)
            return fail(argv[a], "expected a size WxH");
    double* cpu = malloc(repeats * sizeof *cpu);
    double* gpu_ms = malloc(repeats * sizeof *gpu_ms);
    int status = 0;
    for (int s = 0; s < size_count && status == 0; s++) {
        rnd_target* t = rnd_target_create(ctx, sizes[s][0], sizes[s][1], err, sizeof err);
        if (!t)
            return fail("target", err);
        rnd_draw_stats stats;
        status = !rnd_draw(ctx, t, gpu, &cam, NULL, 0, &stats); /* warm-up: first-use allocations */
        for (int i = 0; i < repeats && status == 0; i++) {
            status = !rnd_draw(ctx, t, gpu, &cam, NULL, 0, &stats);
            cpu[i] = stats.cpu_ms;
            gpu_ms[i] = stats.gpu_ms;
        }
        if (status == 0)
            printf("%ux%u: full draw median cpu %.2f ms, gpu %.2f ms (%d draws)\n", sizes[s][0], sizes[s][1],
                   tv_percentile(cpu, (size_t)repeats, 50.0), tv_percentile(gpu_ms, (size_t)repeats, 50.0), repeats);
        rnd_target_destroy(ctx, t);
    }
    free(cpu);
    free(gpu_ms);
    rnd_scene_destroy(ctx, gpu);
    rnd_destroy(ctx);
    scn_scene_free(&scene);
    return status;
}
