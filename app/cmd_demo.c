/* trimvr demo: options map onto tv_demo_desc (demo.h). */
#include "args.h"
#include "cli_loop.h"
#include "commands.h"
#include "demo.h"
#include "demo_hud.h"
#include "log.h"

#include <stdio.h>
#include <string.h>

typedef struct demo_opts {
    tv_loop_opts loop;
    const char *scene, *path, *view, *screenshot, *start_text;
    unsigned res[2];
    float rate, seconds, yaw;
    int frames, every;
    bool no_hud, mailbox, overview;
} demo_opts;

static tv_args_result parse(demo_opts* o, int argc, char** argv)
{
    const tv_arg own[] = {
        {"scene", TV_ARG_STRING, &o->scene, "S", "scene (default: the path's '# scene:', else builtin:interior)"},
        {"path", TV_ARG_STRING, &o->path, "FILE", "follow this head-motion path, looping (movement keys take over)"},
        {"res", TV_ARG_RES, o->res, "WxH", "per-eye resolution (default 640x360; the window is 2W x H)"},
        {"view", TV_ARG_STRING, &o->view, "V", "initial view: pvs, full or fn (default pvs)"},
        {"overview", TV_ARG_FLAG, &o->overview, NULL, "start with the Figure 1 overview in the right half (O toggles it)"},
        {"every", TV_ARG_INT, &o->every, "N", "render the full scene too and compare every Nth frame (default 30)"},
        {"start", TV_ARG_STRING, &o->start_text, "X,Y,Z", "without --path: start position (default: where paths/NAME-walk.csv starts)"},
        {"yaw", TV_ARG_FLOAT, &o->yaw, "DEG", "without --path: start heading, 0 looks down -Z (default 0)"},
        {"mailbox", TV_ARG_FLAG, &o->mailbox, NULL, "MAILBOX presentation (no vsync wait) when offered; default FIFO"},
        {"no-hud", TV_ARG_FLAG, &o->no_hud, NULL, "start with the HUD hidden (U toggles it)"},
        {"frames", TV_ARG_INT, &o->frames, "N", "run N frames on a fixed-step clock (reproducible; fixed latency model), then exit"},
        {"rate", TV_ARG_FLOAT, &o->rate, "HZ", "--frames: clock step 1/HZ (default 90)"},
        {"seconds", TV_ARG_FLOAT, &o->seconds, "S", "real clock: quit after S seconds (timing runs)"},
        {"screenshot", TV_ARG_STRING, &o->screenshot, "FILE", "--frames: write the last presented frame as PNG"},
    };
    enum { OWN = (int)(sizeof own / sizeof own[0]) };
    tv_arg args[OWN + TV_LOOP_ARG_COUNT];
    memcpy(args, own, sizeof own);
    tv_loop_args(&o->loop, args + OWN);
    char summary[2048];
    snprintf(summary, sizeof summary,
             "Opens a window showing both eyes side by side (a headset's mirror window) and runs the\n"
             "replay's loop live: predicted viewcells, asynchronous PVS, late-latched rendering, a check\n"
             "against the full scene every N frames; a HUD shows the numbers. Needs a display (or\n"
             "xvfb-run -a). Controls:\n%s",
             tv_demo_controls);
    return tv_args_parse("demo", summary, args, OWN + TV_LOOP_ARG_COUNT, argc, argv);
}

static bool validate(const demo_opts* o)
{
    if (o->screenshot && o->frames == 0) {
        tv_log(TV_LOG_ERROR, "--screenshot needs --frames");
        return false;
    }
    return tv_loop_validate(&o->loop) && tv_arg_require("every", o->every, o->every >= 1, ">= 1") &&
           tv_arg_require("frames", o->frames, o->frames >= 0, ">= 0") &&
           tv_arg_require("rate", o->rate, o->rate > 0.0f && o->rate <= 10000.0f, "in (0, 10000] Hz") &&
           tv_arg_require("seconds", o->seconds, o->seconds >= 0.0f, ">= 0");
}

/* False (after a one-line error) when a name or --start is malformed. */
static bool fill_desc(const demo_opts* o, tv_demo_desc* d)
{
    memset(d, 0, sizeof *d);
    if (o->start_text) {
        char tail;
        if (sscanf(o->start_text, "%f,%f,%f%c", &d->start[0], &d->start[1], &d->start[2], &tail) != 3) {
            tv_log(TV_LOG_ERROR, "--start: expected X,Y,Z, got '%s'", o->start_text);
            return false;
        }
        d->have_start = true;
    }
    if (!tv_loop_fill(&o->loop, (float)o->res[0] / (float)o->res[1], &d->pvs.method, &d->pvs.predictor,
                      &d->pvs.viewcell))
        return false;
    if (strcmp(o->view, "pvs") != 0 && strcmp(o->view, "full") != 0 && strcmp(o->view, "fn") != 0) {
        tv_log(TV_LOG_ERROR, "--view: expected pvs, full or fn, got '%s'", o->view);
        return false;
    }
    d->scene = o->scene;
    d->path = o->path;
    d->width = o->res[0];
    d->height = o->res[1];
    d->fov_h_deg = o->loop.fov;
    d->ipd_m = o->loop.ipd;
    d->near_m = 0.05f;
    d->far_m = 500.0f;
    d->start_yaw_deg = o->yaw;
    d->mode = strcmp(o->view, "full") == 0 ? TV_EYE_FULL : strcmp(o->view, "fn") == 0 ? TV_EYE_FN : TV_EYE_PVS;
    d->hud = !o->no_hud;
    d->overview = o->overview;
    d->mailbox = o->mailbox;
    d->check_every = o->every;
    d->frames = o->frames;
    d->rate_hz = o->rate;
    d->screenshot = o->screenshot;
    d->seconds = o->seconds;
    /* the fixed-step clock is reproducible only with the fixed latency model */
    d->pvs.latency_model = o->frames > 0 ? TV_LATENCY_FIXED : TV_LATENCY_MEASURED;
    d->pvs.latency_s = o->loop.latency_ms * 1e-3;
    return true;
}

int tv_cmd_demo(int argc, char** argv)
{
    demo_opts o = {.loop = TV_LOOP_OPTS_DEFAULT, .view = "pvs", .res = {640, 360}, .rate = 90.0f, .every = 30};
    tv_args_result r = parse(&o, argc, argv);
    if (r != TV_ARGS_OK)
        return r == TV_ARGS_HELP ? 0 : 2;
    tv_demo_desc d;
    if (!validate(&o) || !fill_desc(&o, &d))
        return 2;
    return tv_demo_run(&d);
}
