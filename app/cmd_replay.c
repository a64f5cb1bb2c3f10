/* trimvr replay: the main job. Options map onto tv_replay_desc; with no
 * options it replays the built-in city along its bundled walk. */
#define _POSIX_C_SOURCE 200809L
#include "app_scene.h"
#include "args.h"
#include "cli_loop.h"
#include "auto_place.h"
#include "commands.h"
#include "log.h"
#include "replay.h"

#include <stdio.h>
#include <string.h>
#include <unistd.h> /* isatty */

#define DEFAULT_PATH "paths/city-walk.csv"

typedef struct replay_opts {
    tv_loop_opts loop;
    const char *path, *scene, *out;
    unsigned res[2];
    float latency_factor, cpu_ms, rate, noise_mm, noise_deg;
    int every, frames, seed;
    bool noiseless, no_late_latch, no_plots, no_progress, coverage_only;
} replay_opts;

static tv_args_result parse(replay_opts* o, int argc, char** argv)
{
    const tv_arg own[] = {
        {"scene", TV_ARG_STRING, &o->scene, "S", "scene (default: the path's '# scene:' line)"},
        {"path", TV_ARG_STRING, &o->path, "FILE",
         "head-motion path (default: with --scene its bundled walk or an automatic one, else " DEFAULT_PATH ")"},
        {"out", TV_ARG_STRING, &o->out, "DIR", "output folder (default out/replay; an earlier run's outputs are removed)"},
        {"latency-factor", TV_ARG_FLOAT, &o->latency_factor, "F", "measured latency model: compute time x F (overrides --latency-ms)"},
        {"res", TV_ARG_RES, o->res, "WxH", "eye image resolution (default 640x360)"},
        {"every", TV_ARG_INT, &o->every, "N", "render and compare every Nth display frame (default 1)"},
        {"frames", TV_ARG_INT, &o->frames, "N", "stop after N display frames (default: whole path)"},
        {"rate", TV_ARG_FLOAT, &o->rate, "HZ", "display rate (default 90)"},
        {"cpu-ms", TV_ARG_FLOAT, &o->cpu_ms, "MS", "simulated frame CPU time before submit (default 4)"},
        {"noise-mm", TV_ARG_FLOAT, &o->noise_mm, "MM", "sensor position noise sigma (default 0.2)"},
        {"noise-deg", TV_ARG_FLOAT, &o->noise_deg, "DEG", "sensor rotation noise sigma (default 0.02)"},
        {"noiseless", TV_ARG_FLAG, &o->noiseless, NULL, "no sensor noise or jitter"},
        {"seed", TV_ARG_INT, &o->seed, "N", "sensor noise seed (default 1)"},
        {"no-late-latch", TV_ARG_FLAG, &o->no_late_latch, NULL, "latch the pose at frame start instead of at submit"},
        {"no-plots", TV_ARG_FLAG, &o->no_plots, NULL, "skip the gnuplot PNGs"},
        {"no-progress", TV_ARG_FLAG, &o->no_progress, NULL, "no progress bar even on a terminal"},
        {"coverage-only", TV_ARG_FLAG, &o->coverage_only, NULL,
         "viewcell sizing and coverage of every frame only: no PVS, no image (fixed latency model)"},
    };
    enum { OWN = (int)(sizeof own / sizeof own[0]) };
    tv_arg args[OWN + TV_LOOP_ARG_COUNT];
    memcpy(args, own, sizeof own);
    tv_loop_args(&o->loop, args + OWN);
    const char* summary =
        "Replays a head-motion path through the simulated HMD: predicts the head, sizes a viewcell,\n"
        "computes PVSs asynchronously and renders every frame per eye from the PVS and from the full\n"
        "scene. Writes DIR/frames.csv (row by row), DIR/summary.json, DIR/plot_*.png and the worst\n"
        "frame's images (worst_full.png, worst_pvs.png, worst_diff.png); prints a summary table.\n"
        "Ctrl-C (SIGINT) or SIGTERM stops after the current frame and writes summary.json with\n"
        "\"interrupted\": true; the exit status is then 128 + the signal number.";
    return tv_args_parse("replay", summary, args, OWN + TV_LOOP_ARG_COUNT, argc, argv);
}

static bool validate(const replay_opts* o)
{
    if (o->coverage_only && o->latency_factor > 0.0f) {
        tv_log(TV_LOG_ERROR, "--coverage-only: the measured latency model (--latency-factor %g) needs the PVS "
               "computed, its time is the latency", o->latency_factor);
        return false;
    }
    return tv_loop_validate(&o->loop) && tv_arg_require("every", o->every, o->every >= 1, ">= 1") &&
           tv_arg_require("frames", o->frames, o->frames >= 0, ">= 0") &&
           tv_arg_require("latency-factor", o->latency_factor, o->latency_factor >= 0.0f && o->latency_factor <= 1000.0f,
                          "in [0, 1000]") &&
           tv_arg_require("rate", o->rate, o->rate > 0.0f && o->rate <= 10000.0f, "in (0, 10000] Hz") &&
           tv_arg_require("cpu-ms", o->cpu_ms, o->cpu_ms >= 0.0f && o->cpu_ms * 1e-3f < 1.0f / o->rate,
                          "non-negative and below one display frame (1000 / --rate ms)") &&
           tv_arg_require("noise-mm", o->noise_mm, o->noise_mm >= 0.0f && o->noise_mm <= 1000.0f, "in [0, 1000] mm") &&
           tv_arg_require("noise-deg", o->noise_deg, o->noise_deg >= 0.0f && o->noise_deg <= 180.0f,
                          "in [0, 180] degrees");
}

/* False (after a one-line error) when a name is unknown. */
static bool fill_desc(const replay_opts* o, tv_replay_desc* d)
{
    memset(d, 0, sizeof *d);
    if (!tv_loop_fill(&o->loop, (float)o->res[0] / (float)o->res[1], &d->method, &d->predictor, &d->viewcell))
        return false;
    d->scene = o->scene;
    d->path = o->path;
    d->out_dir = o->out;
    d->hmd.display_rate_hz = o->rate;
    d->hmd.ipd_m = o->loop.ipd;
    d->hmd.pos_noise_m = o->noise_mm * 1e-3;
    d->hmd.rot_noise_deg = o->noise_deg;
    d->hmd.noiseless = o->noiseless || (o->noise_mm == 0.0f && o->noise_deg == 0.0f);
    d->hmd.seed = (uint64_t)o->seed;
    d->latency_model = o->latency_factor > 0.0f ? TV_LATENCY_MEASURED : TV_LATENCY_FIXED;
    d->latency_s = o->loop.latency_ms * 1e-3;
    d->latency_factor = o->latency_factor;
    d->width = o->res[0];
    d->height = o->res[1];
    d->near_m = 0.05f;
    d->far_m = 500.0f;
    d->every = o->every;
    d->max_frames = (uint64_t)o->frames;
    d->cpu_ms = o->cpu_ms;
    d->no_late_latch = o->no_late_latch;
    d->progress = !o->no_progress && isatty(STDERR_FILENO);
    d->plots = !o->no_plots;
    d->coverage_only = o->coverage_only;
    return true;
}

int tv_cmd_replay(int argc, char** argv)
{
    replay_opts o = {.loop = TV_LOOP_OPTS_DEFAULT, .out = "out/replay", .res = {640, 360}, .cpu_ms = 4.0f,
                     .rate = 90.0f, .noise_mm = 0.2f, .noise_deg = 0.02f, .every = 1, .seed = 1};
    tv_args_result r = parse(&o, argc, argv);
    if (r != TV_ARGS_OK)
        return r == TV_ARGS_HELP ? 0 : 2;
    char path_buf[4300];
    tv_replay_desc d;
    if (!validate(&o) || !fill_desc(&o, &d))
        return 2;
    if (!o.path) {
        d.path = o.scene ? tv_default_walk(o.scene, o.out, path_buf, sizeof path_buf)
                         : tv_bundled_file(DEFAULT_PATH, path_buf, sizeof path_buf);
        if (!d.path)
            return 1;
    }
    return tv_replay_run(&d);
}
