/* trimvr replay: the main job. Options map onto tv_replay_desc; with no
 * options it replays the built-in city along its bundled walk. */
#define _POSIX_C_SOURCE 200809L
#include "app_scene.h"
#include "args.h"
#include "auto_place.h"
#include "commands.h"
#include "replay.h"

#include <stdio.h>
#include <string.h>
#include <unistd.h> /* isatty */

#define DEFAULT_PATH "paths/city-walk.csv"

int tv_cmd_replay(int argc, char** argv)
{
    const char *method = "tr", *predictor = "cv", *policy = "adaptive", *path = NULL, *scene = NULL;
    const char* out = "out/replay";
    unsigned res[2] = {640, 360}, pvs_res[2] = {0, 0};
    float fov = 60.0f, delta = 0.10f, fov_pvs = 0.0f, latency_ms = 50.0f, latency_factor = 0.0f;
    float quantile = 0.99f, ipd = 0.063f, cpu_ms = 4.0f, rate = 90.0f, noise_mm = 0.2f, noise_deg = 0.02f;
    int every = 1, frames = 0, samples = 0, k = 0, seed = 1;
    bool noiseless = false, no_late_latch = false, no_plots = false, no_progress = false;
    const tv_arg args[] = {
        {"scene", TV_ARG_STRING, &scene, "S", "scene (default: the path's '# scene:' line)"},
        {"path", TV_ARG_STRING, &path, "FILE",
         "head-motion path (default: with --scene its bundled walk or an automatic one, else " DEFAULT_PATH ")"},
        {"out", TV_ARG_STRING, &out, "DIR", "output folder (default out/replay)"},
        {"method", TV_ARG_STRING, &method, "M", "PVS method: tr, gt, sas, frompoint, q3vis (default tr)"},
        {"predictor", TV_ARG_STRING, &predictor, "P", "cv, ca or kalman (default cv)"},
        {"policy", TV_ARG_STRING, &policy, "P", "viewcell sizing: adaptive or fixed (default adaptive)"},
        {"delta", TV_ARG_FLOAT, &delta, "M", "fixed policy: viewcell radius (default 0.10)"},
        {"fov-pvs", TV_ARG_FLOAT, &fov_pvs, "DEG", "fixed policy: PVS FOV, square frustum (default 90)"},
        {"quantile", TV_ARG_FLOAT, &quantile, "Q", "adaptive policy: error quantile (default 0.99)"},
        {"latency-ms", TV_ARG_FLOAT, &latency_ms, "MS", "fixed latency model: request to use (default 50)"},
        {"latency-factor", TV_ARG_FLOAT, &latency_factor, "F", "measured latency model: compute time x F (overrides --latency-ms)"},
        {"res", TV_ARG_RES, res, "WxH", "eye image resolution (default 640x360)"},
        {"fov", TV_ARG_FLOAT, &fov, "DEG", "eye horizontal FOV (default 60, the paper's target)"},
        {"pvs-res", TV_ARG_RES, pvs_res, "WxH", "tr: PVS resolution (default 512x512)"},
        {"k", TV_ARG_INT, &k, "N", "tr: k-buffer slots per pixel (default 16)"},
        {"samples", TV_ARG_INT, &samples, "N", "gt: views per viewcell (default 200)"},
        {"every", TV_ARG_INT, &every, "N", "render and compare every Nth display frame (default 1)"},
        {"frames", TV_ARG_INT, &frames, "N", "stop after N display frames (default: whole path)"},
        {"rate", TV_ARG_FLOAT, &rate, "HZ", "display rate (default 90)"},
        {"ipd", TV_ARG_FLOAT, &ipd, "M", "inter-pupillary distance (default 0.063)"},
        {"cpu-ms", TV_ARG_FLOAT, &cpu_ms, "MS", "simulated frame CPU time before submit (default 4)"},
        {"noise-mm", TV_ARG_FLOAT, &noise_mm, "MM", "sensor position noise sigma (default 0.2)"},
        {"noise-deg", TV_ARG_FLOAT, &noise_deg, "DEG", "sensor rotation noise sigma (default 0.02)"},
        {"noiseless", TV_ARG_FLAG, &noiseless, NULL, "no sensor noise or jitter"},
        {"seed", TV_ARG_INT, &seed, "N", "sensor noise seed (default 1)"},
        {"no-late-latch", TV_ARG_FLAG, &no_late_latch, NULL, "latch the pose at frame start instead of at submit"},
        {"no-plots", TV_ARG_FLAG, &no_plots, NULL, "skip the gnuplot PNGs"},
        {"no-progress", TV_ARG_FLAG, &no_progress, NULL, "no progress bar even on a terminal"},
    };
    const char* summary =
        "Replays a head-motion path through the simulated HMD: predicts the head, sizes a viewcell,\n"
        "computes PVSs asynchronously and renders every frame per eye from the PVS and from the full\n"
        "scene. Writes DIR/frames.csv (row by row), DIR/summary.json, DIR/plot_*.png and the worst\n"
        "frame's images (worst_full.png, worst_pvs.png, worst_diff.png); prints a summary table.";
    tv_args_result r = tv_args_parse("replay", summary, args, (int)(sizeof args / sizeof args[0]), argc, argv);
    if (r != TV_ARGS_OK)
        return r == TV_ARGS_HELP ? 0 : 2;

    tv_replay_desc d;
    memset(&d, 0, sizeof d);
    char path_buf[4300];
    d.scene = scene;
    d.path = path ? path : scene ? tv_default_walk(scene, out, path_buf, sizeof path_buf)
                                 : tv_bundled_file(DEFAULT_PATH, path_buf, sizeof path_buf);
    if (!d.path)
        return 1;
    d.out_dir = out;
    if (!pvs_method_from_name(method, &d.method.kind)) {
        fprintf(stderr, "trimvr replay: error: --method: unknown method '%s' (tr, gt, sas, frompoint, q3vis)\n", method);
        return 2;
    }
    if (!pred_kind_from_name(predictor, &d.predictor.kind)) {
        fprintf(stderr, "trimvr replay: error: --predictor: unknown predictor '%s' (cv, ca, kalman)\n", predictor);
        return 2;
    }
    if (strcmp(policy, "adaptive") != 0 && strcmp(policy, "fixed") != 0) {
        fprintf(stderr, "trimvr replay: error: --policy: expected adaptive or fixed, got '%s'\n", policy);
        return 2;
    }
    if (every < 1 || frames < 0 || samples < 0 || k < 0 || !(fov > 1.0f && fov < 170.0f) || !(delta >= 0.0f) ||
        !(fov_pvs == 0.0f || (fov_pvs >= fov && fov_pvs < 179.0f)) || !(quantile > 0.0f && quantile <= 1.0f) ||
        !(latency_ms >= 0.0f) || !(latency_factor >= 0.0f) || !(rate > 0.0f) || !(ipd >= 0.0f) ||
        !(cpu_ms >= 0.0f && cpu_ms * 1e-3f < 1.0f / rate) || !(noise_mm >= 0.0f) || !(noise_deg >= 0.0f)) {
        fprintf(stderr, "trimvr replay: error: an option is out of range (see trimvr replay --help): need "
                        "--every >= 1, 1 < --fov < 170, --fov <= --fov-pvs < 179, 0 < --quantile <= 1, "
                        "--cpu-ms below one display frame, and non-negative sizes\n");
        return 2;
    }
    /* tr's frustum is square (the viewcell's PVS FOV on both axes): a square image by default */
    d.method.tr.width = pvs_res[0] ? pvs_res[0] : 512;
    d.method.tr.height = pvs_res[1] ? pvs_res[1] : 512;
    d.method.tr.k = (uint32_t)k;
    d.method.gt_samples = (uint32_t)samples;
    d.viewcell.policy = strcmp(policy, "fixed") == 0 ? PRED_POLICY_FIXED : PRED_POLICY_ADAPTIVE;
    d.viewcell.fixed_delta_m = delta;
    d.viewcell.fixed_fov_pvs_deg = fov_pvs;
    d.viewcell.quantile = quantile;
    d.viewcell.ipd_m = ipd;
    d.viewcell.display_fov_h_deg = fov;
    d.viewcell.display_fov_v_deg = rnd_fov_y_from_x(fov, (float)res[0] / (float)res[1]);
    d.hmd.display_rate_hz = rate;
    d.hmd.ipd_m = ipd;
    d.hmd.pos_noise_m = noise_mm * 1e-3;
    d.hmd.rot_noise_deg = noise_deg;
    d.hmd.noiseless = noiseless || (noise_mm == 0.0f && noise_deg == 0.0f);
    d.hmd.seed = (uint64_t)seed;
    d.latency_model = latency_factor > 0.0f ? TV_LATENCY_MEASURED : TV_LATENCY_FIXED;
    d.latency_s = latency_ms * 1e-3;
    d.latency_factor = latency_factor;
    d.width = res[0];
    d.height = res[1];
    d.near_m = 0.05f;
    d.far_m = 500.0f;
    d.every = every;
    d.max_frames = (uint64_t)frames;
    d.cpu_ms = cpu_ms;
    d.no_late_latch = no_late_latch;
    d.progress = !no_progress && isatty(STDERR_FILENO);
    d.plots = !no_plots;
    return tv_replay_run(&d);
}
