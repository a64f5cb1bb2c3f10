/* trimvr render: frames of a scene along a head-motion path, as PNG files,
 * with a per-frame CSV of poses and draw times. */
#include "app_scene.h"
#include "args.h"
#include "commands.h"
#include "image_io.h"
#include "path.h"
#include "fs.h"
#include "stats.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct render_opts {
    const char* scene;
    const char* path;
    const char* out;
    int every;
    int frames;
    unsigned res[2];
    float fov;
    float rate;
    float near_m, far_m;
    float ipd;
    bool stereo;
} render_opts;

static bool write_frame(const char* dir, int frame, const char* suffix, const uint8_t* rgba, unsigned w,
                        unsigned h)
{
    char file[4200], err[512];
    snprintf(file, sizeof file, "%s/frame_%05d%s.png", dir, frame, suffix);
    if (!scn_image_write_png(file, rgba, w, h, 4, err, sizeof err)) {
        fprintf(stderr, "trimvr render: error: %s\n", err);
        return false;
    }
    return true;
}

int tv_cmd_render(int argc, char** argv)
{
    render_opts o = {.every = 1, .frames = 0, .res = {640, 360}, .fov = 60.0f, .rate = 90.0f,
                     .near_m = 0.05f, .far_m = 500.0f, .ipd = 0.063f};
    const tv_arg args[] = {
        {"scene", TV_ARG_STRING, &o.scene, "S", "scene: .gltf/.glb, builtin:NAME, sponza or oa:LEVEL (default: the path's '# scene:')"},
        {"path", TV_ARG_STRING, &o.path, "FILE", "head-motion path CSV (required)"},
        {"out", TV_ARG_STRING, &o.out, "DIR", "output folder (required; created)"},
        {"every", TV_ARG_INT, &o.every, "N", "write every Nth display frame (default 1)"},
        {"frames", TV_ARG_INT, &o.frames, "N", "stop after N written frames (default: whole path)"},
        {"res", TV_ARG_RES, o.res, "WxH", "resolution (default 640x360)"},
        {"fov", TV_ARG_FLOAT, &o.fov, "DEG", "vertical field of view (default 60)"},
        {"rate", TV_ARG_FLOAT, &o.rate, "HZ", "display rate the path is sampled at (default 90)"},
        {"near", TV_ARG_FLOAT, &o.near_m, "M", "near plane (default 0.05)"},
        {"far", TV_ARG_FLOAT, &o.far_m, "M", "far plane (default 500)"},
        {"stereo", TV_ARG_FLAG, &o.stereo, NULL, "render both eyes (frame_N_left.png, frame_N_right.png)"},
        {"ipd", TV_ARG_FLOAT, &o.ipd, "M", "inter-pupillary distance for --stereo (default 0.063)"},
    };
    const char* summary = "Renders the full scene along a head-motion path at the display rate and writes\n"
                          "every Nth frame as PNG plus frames.csv (frame, time, pose, draw ms).";
    tv_args_result r = tv_args_parse("render", summary, args, (int)(sizeof args / sizeof args[0]), argc, argv);
    if (r != TV_ARGS_OK)
        return r == TV_ARGS_HELP ? 0 : 2;
    if (!o.path || !o.out) {
        fprintf(stderr, "trimvr render: error: --path and --out are required (see trimvr render --help)\n");
        return 2;
    }
    if (o.every < 1 || o.frames < 0 || !(o.rate > 0.0f) || !(o.fov > 0.0f && o.fov < 179.0f) ||
        !(o.near_m > 0.0f && o.far_m > o.near_m) || !(o.ipd >= 0.0f)) {
        fprintf(stderr, "trimvr render: error: --every >= 1, --frames >= 0, --rate > 0, 0 < --fov < 179, "
                        "0 < --near < --far and --ipd >= 0 are required\n");
        return 2;
    }

    char err[512];
    pred_path path;
    if (!pred_path_load(o.path, &path, err, sizeof err)) {
        fprintf(stderr, "trimvr render: error: %s\n", err);
        return 1;
    }
    const char* spec = o.scene ? o.scene : path.scene;
    if (!spec[0]) {
        fprintf(stderr, "trimvr render: error: %s has no '# scene:' line; pass --scene\n", o.path);
        pred_path_free(&path);
        return 2;
    }
    if (!tv_mkdirs(o.out)) {
        fprintf(stderr, "trimvr render: error: %s: cannot create the output folder\n", o.out);
        pred_path_free(&path);
        return 1;
    }

    tv_app_scene s;
    if (!tv_app_scene_open("render", spec, &s)) {
        pred_path_free(&path);
        return 1;
    }
    int status = 0;
    unsigned w = o.res[0], h = o.res[1];
    rnd_target* target = rnd_target_create(s.ctx, w, h, err, sizeof err);
    uint8_t* rgba = malloc((size_t)w * h * 4);
    char csv_name[4200];
    snprintf(csv_name, sizeof csv_name, "%s/frames.csv", o.out);
    FILE* csv = fopen(csv_name, "w");
    double* draw_ms = NULL;
    if (!target || !rgba || !csv) {
        fprintf(stderr, "trimvr render: error: %s\n", !target ? err : !rgba ? "out of memory" : csv_name);
        status = 1;
        goto done;
    }
    fprintf(csv, "frame,t,px,py,pz,qx,qy,qz,qw,eye,draw_cpu_ms,draw_gpu_ms\n");

    double t0 = path.poses[0].t, duration = pred_path_duration(&path);
    int display_frames = (int)(duration * o.rate) + 1;
    int wanted = (display_frames + o.every - 1) / o.every;
    if (o.frames > 0 && o.frames < wanted)
        wanted = o.frames;
    draw_ms = malloc(sizeof(double) * (size_t)wanted * 2);
    int written = 0, draws = 0;
    for (int f = 0; f < display_frames && written < wanted && status == 0; f += o.every, written++) {
        pred_pose head;
        pred_path_sample(&path, t0 + f / (double)o.rate, &head);
        rnd_camera cams[2];
        cams[0] = tv_camera_at_pose(&head, o.fov, o.near_m, o.far_m);
        int eyes = 1;
        if (o.stereo) {
            rnd_camera base = cams[0];
            rnd_stereo_cameras(base.position, base.orientation, o.ipd, &base, &cams[0], &cams[1]);
            eyes = 2;
        }
        for (int e = 0; e < eyes; e++) {
            rnd_draw_stats st;
            if (!rnd_draw(s.ctx, target, s.gpu, &cams[e], NULL, 0, &st) ||
                !rnd_target_read_color(s.ctx, target, rgba)) {
                fprintf(stderr, "trimvr render: error: drawing frame %d failed\n", f);
                status = 1;
                break;
            }
            const char* eye_name = eyes == 1 ? "head" : e == 0 ? "left" : "right";
            if (!write_frame(o.out, f, eyes == 1 ? "" : e == 0 ? "_left" : "_right", rgba, w, h)) {
                status = 1;
                break;
            }
            draw_ms[draws++] = st.cpu_ms;
            fprintf(csv, "%d,%.6f,%.6f,%.6f,%.6f,%.8f,%.8f,%.8f,%.8f,%s,%.3f,%.3f\n", f, head.t, head.p[0],
                    head.p[1], head.p[2], head.q[0], head.q[1], head.q[2], head.q[3], eye_name, st.cpu_ms,
                    st.gpu_ms);
            fflush(csv); /* an interrupted run keeps every finished frame */
        }
    }
    if (status == 0)
        printf("trimvr render: %s, %u triangles, %d frame(s) at %ux%u on %s into %s; draw ms median %.2f "
               "(p90 %.2f), scene load %.0f ms, upload %.0f ms\n",
               spec, s.scene.triangle_count, written, w, h, rnd_device_name(s.ctx), o.out,
               tv_percentile(draw_ms, (size_t)draws, 50.0), tv_percentile(draw_ms, (size_t)draws, 90.0),
               s.load_ms, s.upload_ms);
done:
    free(draw_ms);
    if (csv)
        fclose(csv);
    free(rgba);
    if (target)
        rnd_target_destroy(s.ctx, target);
    if (!tv_app_scene_close("render", &s))
        status = 1;
    pred_path_free(&path);
    return status;
}
