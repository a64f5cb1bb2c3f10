/* trimvr demo: options map onto tv_demo_desc (demo.h). */
#include "args.h"
#include "commands.h"
#include "demo.h"
#include "demo_hud.h"

#include <stdio.h>
#include <string.h>

int tv_cmd_demo(int argc, char** argv)
{
    const char *scene = NULL, *path = NULL, *method = "tr", *predictor = "cv", *policy = "adaptive";
    const char *view = "pvs", *screenshot = NULL;
    unsigned res[2] = {640, 360}, pvs_res[2] = {0, 0};
    float fov = 60.0f, ipd = 0.063f, delta = 0.10f, fov_pvs = 0.0f, quantile = 0.99f, latency_ms = 50.0f;
    float rate = 90.0f, seconds = 0.0f, yaw = 0.0f, start[3] = {0.0f, 0.0f, 0.0f};
    int frames = 0, every = 30, k = 0, samples = 0;
    bool no_hud = false, mailbox = false, have_start = false, overview = false;
    const char* start_text = NULL;
    const tv_arg args[] = {
        {"scene", TV_ARG_STRING, &scene, "S", "scene (default: the path's '# scene:', else builtin:interior)"},
        {"path", TV_ARG_STRING, &path, "FILE", "follow this head-motion path, looping (movement keys take over)"},
        {"method", TV_ARG_STRING, &method, "M", "PVS method: tr, gt, sas, frompoint, q3vis (default tr)"},
        {"predictor", TV_ARG_STRING, &predictor, "P", "cv, ca or kalman (default cv)"},
        {"policy", TV_ARG_STRING, &policy, "P", "viewcell sizing: adaptive or fixed (default adaptive)"},
        {"delta", TV_ARG_FLOAT, &delta, "M", "fixed policy: viewcell radius (default 0.10)"},
        {"fov-pvs", TV_ARG_FLOAT, &fov_pvs, "DEG", "fixed policy: PVS FOV (default 90)"},
        {"quantile", TV_ARG_FLOAT, &quantile, "Q", "adaptive policy: error quantile (default 0.99)"},
        {"res", TV_ARG_RES, res, "WxH", "per-eye resolution (default 640x360; the window is 2W x H)"},
        {"fov", TV_ARG_FLOAT, &fov, "DEG", "per-eye horizontal FOV (default 60)"},
        {"ipd", TV_ARG_FLOAT, &ipd, "M", "inter-pupillary distance (default 0.063)"},
        {"pvs-res", TV_ARG_RES, pvs_res, "WxH", "tr: PVS resolution (default 512x512)"},
        {"k", TV_ARG_INT, &k, "N", "tr: k-buffer slots per pixel (default 16)"},
        {"samples", TV_ARG_INT, &samples, "N", "gt: views per viewcell (default 200)"},
        {"view", TV_ARG_STRING, &view, "V", "initial view: pvs, full or fn (default pvs)"},
        {"overview", TV_ARG_FLAG, &overview, NULL, "start with the Figure 1 overview in the right half (O toggles it)"},
        {"every", TV_ARG_INT, &every, "N", "render the full scene too and compare every Nth frame (default 30)"},
        {"start", TV_ARG_STRING, &start_text, "X,Y,Z", "without --path: start position (default: where paths/NAME-walk.csv starts)"},
        {"yaw", TV_ARG_FLOAT, &yaw, "DEG", "without --path: start heading, 0 looks down -Z (default 0)"},
        {"mailbox", TV_ARG_FLAG, &mailbox, NULL, "MAILBOX presentation (no vsync wait) when offered; default FIFO"},
        {"no-hud", TV_ARG_FLAG, &no_hud, NULL, "start with the HUD hidden (U toggles it)"},
        {"frames", TV_ARG_INT, &frames, "N", "run N frames on a fixed-step clock (reproducible), then exit"},
        {"rate", TV_ARG_FLOAT, &rate, "HZ", "--frames: clock step 1/HZ (default 90)"},
        {"latency-ms", TV_ARG_FLOAT, &latency_ms, "MS", "--frames: fixed PVS latency on that clock (default 50)"},
        {"seconds", TV_ARG_FLOAT, &seconds, "S", "real clock: quit after S seconds (timing runs)"},
        {"screenshot", TV_ARG_STRING, &screenshot, "FILE", "--frames: write the last presented frame as PNG"},
    };
    char summary[2048];
    snprintf(summary, sizeof summary,
             "Opens a window showing both eyes side by side (a headset's mirror window) and runs the\n"
             "replay's loop live: predicted viewcells, asynchronous PVS, late-latched rendering, a check\n"
             "against the full scene every N frames; a HUD shows the numbers. Needs a display (or\n"
             "xvfb-run -a). Controls:\n%s",
             tv_demo_controls);
    tv_args_result r = tv_args_parse("demo", summary, args, (int)(sizeof args / sizeof args[0]), argc, argv);
    if (r != TV_ARGS_OK)
        return r == TV_ARGS_HELP ? 0 : 2;

    tv_demo_desc d;
    memset(&d, 0, sizeof d);
    if (start_text) {
        char tail;
        if (sscanf(start_text, "%f,%f,%f%c", &start[0], &start[1], &start[2], &tail) != 3) {
            fprintf(stderr, "trimvr demo: error: --start: expected X,Y,Z, got '%s'\n", start_text);
            return 2;
        }
        have_start = true;
    }
    if (!pvs_method_from_name(method, &d.pvs.method.kind)) {
        fprintf(stderr, "trimvr demo: error: --method: unknown method '%s' (tr, gt, sas, frompoint, q3vis)\n", method);
        return 2;
    }
    if (!pred_kind_from_name(predictor, &d.pvs.predictor.kind)) {
        fprintf(stderr, "trimvr demo: error: --predictor: unknown predictor '%s' (cv, ca, kalman)\n", predictor);
        return 2;
    }
    if (strcmp(policy, "adaptive") != 0 && strcmp(policy, "fixed") != 0) {
        fprintf(stderr, "trimvr demo: error: --policy: expected adaptive or fixed, got '%s'\n", policy);
        return 2;
    }
    if (strcmp(view, "pvs") != 0 && strcmp(view, "full") != 0 && strcmp(view, "fn") != 0) {
        fprintf(stderr, "trimvr demo: error: --view: expected pvs, full or fn, got '%s'\n", view);
        return 2;
    }
    if (every < 1 || frames < 0 || k < 0 || samples < 0 || !(fov > 1.0f && fov < 170.0f) || !(ipd >= 0.0f) ||
        !(delta >= 0.0f) || !(fov_pvs == 0.0f || (fov_pvs >= fov && fov_pvs < 179.0f)) ||
        !(quantile > 0.0f && quantile <= 1.0f) || !(rate > 0.0f) || !(latency_ms >= 0.0f) || !(seconds >= 0.0f) ||
        (screenshot && frames == 0)) {
        fprintf(stderr, "trimvr demo: error: an option is out of range (see trimvr demo --help): need --every >= 1, "
                        "1 < --fov < 170, --fov <= --fov-pvs < 179, 0 < --quantile <= 1, --rate > 0, "
                        "non-negative sizes, and --screenshot only with --frames\n");
        return 2;
    }
    d.scene = scene;
    d.path = path;
    d.width = res[0];
    d.height = res[1];
    d.fov_h_deg = fov;
    d.ipd_m = ipd;
    d.near_m = 0.05f;
    d.far_m = 500.0f;
    memcpy(d.start, start, sizeof d.start);
    d.have_start = have_start;
    d.start_yaw_deg = yaw;
    d.mode = strcmp(view, "full") == 0 ? TV_EYE_FULL : strcmp(view, "fn") == 0 ? TV_EYE_FN : TV_EYE_PVS;
    d.hud = !no_hud;
    d.overview = overview;
    d.mailbox = mailbox;
    d.check_every = every;
    d.frames = frames;
    d.rate_hz = rate;
    d.screenshot = screenshot;
    d.seconds = seconds;
    d.pvs.method.tr.width = pvs_res[0];
    d.pvs.method.tr.height = pvs_res[1];
    d.pvs.method.tr.k = (uint32_t)k;
    d.pvs.method.gt_samples = (uint32_t)samples;
    pred_viewcell_desc* vc = &d.pvs.viewcell;
    vc->policy = strcmp(policy, "fixed") == 0 ? PRED_POLICY_FIXED : PRED_POLICY_ADAPTIVE;
    vc->fixed_delta_m = delta;
    vc->fixed_fov_pvs_deg = fov_pvs;
    vc->quantile = quantile;
    vc->ipd_m = ipd;
    vc->display_fov_h_deg = fov;
    vc->display_fov_v_deg = rnd_fov_y_from_x(fov, (float)res[0] / (float)res[1]);
    /* the fixed-step clock is reproducible only with the fixed latency model */
    d.pvs.latency_model = frames > 0 ? TV_LATENCY_FIXED : TV_LATENCY_MEASURED;
    d.pvs.latency_s = latency_ms * 1e-3;
    return tv_demo_run(&d);
}
