/* trimvr render: frames of a scene along a head-motion path, as PNG files,
 * with a per-frame CSV of poses and draw times. */
#include "app_scene.h"
#include "args.h"
#include "commands.h"
#include "image_io.h"
#include "interrupt.h"
#include "path.h"
#include "stats.h"
#include "log.h"

#include <limits.h>
#include <math.h>
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

#define MAX_RATE_HZ 10000.0f

static bool write_frame(const char* dir, int64_t frame, const char* suffix, const uint8_t* rgba, unsigned w,
                        unsigned h)
{
    char file[4200], err[512];
    snprintf(file, sizeof file, "%s/frame_%05lld%s.png", dir, (long long)frame, suffix);
    if (!scn_image_write_png(file, rgba, w, h, 4, err, sizeof err)) {
        tv_log(TV_LOG_ERROR, "%s", err);
        return false;
    }
    return true;
}

typedef struct render_run {
    const render_opts* o;
    pred_path path;
    tv_app_scene s;
    rnd_target* target;
    uint8_t* rgba;
    FILE* csv;
    double* draw_ms;
    int written, draws;
} render_run;

static tv_args_result parse(render_opts* o, int argc, char** argv)
{
    const tv_arg args[] = {
        {"scene", TV_ARG_STRING, &o->scene, "S", "scene: .gltf/.glb, builtin:NAME, sponza or oa:LEVEL (default: the path's '# scene:')"},
        {"path", TV_ARG_STRING, &o->path, "FILE", "head-motion path CSV (required)"},
        {"out", TV_ARG_STRING, &o->out, "DIR", "output folder (required; created)"},
        {"every", TV_ARG_INT, &o->every, "N", "write every Nth display frame (default 1)"},
        {"frames", TV_ARG_INT, &o->frames, "N", "stop after N written frames (default: whole path)"},
        {"res", TV_ARG_RES, o->res, "WxH", "resolution (default 640x360)"},
        {"fov", TV_ARG_FLOAT, &o->fov, "DEG", "vertical field of view (default 60)"},
        {"rate", TV_ARG_FLOAT, &o->rate, "HZ", "display rate the path is sampled at (default 90)"},
        {"near", TV_ARG_FLOAT, &o->near_m, "M", "near plane (default 0.05)"},
        {"far", TV_ARG_FLOAT, &o->far_m, "M", "far plane (default 500)"},
        {"stereo", TV_ARG_FLAG, &o->stereo, NULL, "render both eyes (frame_N_left.png, frame_N_right.png)"},
        {"ipd", TV_ARG_FLOAT, &o->ipd, "M", "inter-pupillary distance for --stereo (default 0.063)"},
    };
    const char* summary = "Renders the full scene along a head-motion path at the display rate and writes\n"
                          "every Nth frame as PNG plus frames.csv (frame, time, pose, draw ms).";
    return tv_args_parse("render", summary, args, (int)(sizeof args / sizeof args[0]), argc, argv);
}

static bool validate(const render_opts* o)
{
    if (!o->path || !o->out) {
        tv_log(TV_LOG_ERROR, "--path and --out are required (see trimvr render --help)");
        return false;
    }
    return tv_arg_require("every", o->every, o->every >= 1, ">= 1") &&
           tv_arg_require("frames", o->frames, o->frames >= 0, ">= 0") &&
           tv_arg_require("rate", o->rate, o->rate > 0.0f && o->rate <= MAX_RATE_HZ, "in (0, 10000] Hz") &&
           tv_arg_require("fov", o->fov, o->fov > 0.0f && o->fov < 179.0f, "in (0, 179) degrees") &&
           tv_arg_require("near", o->near_m, o->near_m > 0.0f, "> 0") &&
           tv_arg_require("far", o->far_m, o->far_m > o->near_m, "beyond --near") &&
           tv_arg_require("ipd", o->ipd, o->ipd >= 0.0f && o->ipd <= 1.0f, "in [0, 1] m");
}

/* The number of frames to write: the path's display frames at the rate,
 * every Nth, at most --frames. 0 (after an error) when that count does not
 * fit in an int. */
static int frames_wanted(const render_opts* o, const pred_path* path)
{
    double display = floor(pred_path_duration(path) * o->rate) + 1.0;
    double wanted = ceil(display / o->every);
    if (o->frames > 0 && o->frames < wanted)
        wanted = o->frames;
    if (!(wanted <= INT_MAX)) {
        tv_log(TV_LOG_ERROR, "%s: %.0f s at --rate %g gives %.3g frames to write, more than %d; pass --frames",
               o->path, pred_path_duration(path), o->rate, wanted, INT_MAX);
        return 0;
    }
    return (int)wanted;
}

static bool render_frame(render_run* r, int64_t f, const pred_pose* head)
{
    const render_opts* o = r->o;
    rnd_camera cams[2];
    cams[0] = tv_camera_at_pose(head, o->fov, o->near_m, o->far_m);
    int eyes = 1;
    if (o->stereo) {
        rnd_camera base = cams[0];
        rnd_stereo_cameras(base.position, base.orientation, o->ipd, &base, &cams[0], &cams[1]);
        eyes = 2;
    }
    char err[512] = "";
    const rnd_gpu_scene* gpu = tv_app_scene_at(&r->s, head->t, err, sizeof err); /* movers at the frame's time */
    if (!gpu) {
        tv_log(TV_LOG_ERROR, "frame %lld: %s", (long long)f, err);
        return false;
    }
    for (int e = 0; e < eyes; e++) {
        rnd_draw_stats st;
        if (!rnd_draw(r->s.ctx, r->target, gpu, &cams[e], NULL, 0, &st) ||
            !rnd_target_read_color(r->s.ctx, r->target, r->rgba)) {
            tv_log(TV_LOG_ERROR, "drawing frame %lld failed", (long long)f);
            return false;
        }
        const char* eye_name = eyes == 1 ? "head" : e == 0 ? "left" : "right";
        if (!write_frame(o->out, f, eyes == 1 ? "" : e == 0 ? "_left" : "_right", r->rgba, o->res[0], o->res[1]))
            return false;
        r->draw_ms[r->draws++] = st.cpu_ms;
        fprintf(r->csv, "%lld,%.6f,%.6f,%.6f,%.6f,%.8f,%.8f,%.8f,%.8f,%s,%.3f,%.3f\n", (long long)f, head->t,
                head->p[0], head->p[1], head->p[2], head->q[0], head->q[1], head->q[2], head->q[3], eye_name,
                st.cpu_ms, st.gpu_ms);
        fflush(r->csv); /* an interrupted run keeps every finished frame */
    }
    return true;
}

static bool run(render_run* r, int wanted)
{
    const render_opts* o = r->o;
    const pred_path* path = &r->path;
    char err[512], csv_name[4200];
    snprintf(csv_name, sizeof csv_name, "%s/frames.csv", o->out);
    r->target = rnd_target_create(r->s.ctx, o->res[0], o->res[1], err, sizeof err);
    r->rgba = malloc((size_t)o->res[0] * o->res[1] * 4);
    r->draw_ms = malloc(sizeof(double) * (size_t)wanted * 2);
    r->csv = fopen(csv_name, "w");
    if (!r->target || !r->rgba || !r->draw_ms || !r->csv) {
        tv_log(TV_LOG_ERROR, "%s", !r->target ? err : !r->csv ? csv_name : "out of memory");
        return false;
    }
    fprintf(r->csv, "frame,t,px,py,pz,qx,qy,qz,qw,eye,draw_cpu_ms,draw_gpu_ms\n");
    double t0 = path->poses[0].t;
    /* 64-bit frame numbers: wanted * every can exceed an int; a signal stops
     * the run between frames, frames.csv then lists every PNG written */
    for (int64_t f = 0; r->written < wanted && !tv_interrupted(); f += o->every, r->written++) {
        pred_pose head;
        pred_path_sample(path, t0 + (double)f / o->rate, &head);
        if (!render_frame(r, f, &head))
            return false;
    }
    return true;
}

int tv_cmd_render(int argc, char** argv)
{
    render_opts o = {.every = 1, .frames = 0, .res = {640, 360}, .fov = 60.0f, .rate = 90.0f,
                     .near_m = 0.05f, .far_m = 500.0f, .ipd = 0.063f};
    tv_args_result pr = parse(&o, argc, argv);
    if (pr != TV_ARGS_OK)
        return pr == TV_ARGS_HELP ? 0 : 2;
    if (!validate(&o))
        return 2;
    render_run r = {.o = &o};
    const char* spec;
    int status = tv_app_load_path(o.path, o.scene, &r.path, &spec);
    if (status != 0)
        return status;
    int wanted = frames_wanted(&o, &r.path);
    tv_interrupt_install(); /* a signal during the scene load stops the run before the first frame */
    if (wanted == 0 || !tv_app_scene_open_out(spec, o.out, &r.s)) {
        pred_path_free(&r.path);
        return wanted == 0 ? 2 : 1;
    }
    status = run(&r, wanted) ? 0 : 1;
    int sig = tv_interrupted();
    if (status == 0 && sig) {
        tv_log(TV_LOG_ERROR, "interrupted by signal %d after %d of %d frame(s); %s/frames.csv lists them", sig,
               r.written, wanted, o.out);
        status = tv_interrupt_status(sig);
    } else if (status == 0)
        printf("trimvr render: %s, %u triangles, %d frame(s) at %ux%u on %s into %s; draw ms median %.2f "
               "(p90 %.2f), scene load %.0f ms, upload %.0f ms\n",
               spec, r.s.scene.triangle_count, r.written, o.res[0], o.res[1], rnd_device_name(r.s.ctx),
               o.out, tv_percentile(r.draw_ms, (size_t)r.draws, 50.0), tv_percentile(r.draw_ms, (size_t)r.draws, 90.0),
               r.s.load_ms, r.s.upload_ms);
    free(r.draw_ms);
    if (r.csv)
        fclose(r.csv);
    free(r.rgba);
    if (r.target)
        rnd_target_destroy(r.s.ctx, r.target);
    if (!tv_app_scene_close(&r.s))
        status = 1;
    pred_path_free(&r.path);
    return status;
}
