/* trimvr path: head-motion path files.
 *
 *   path import   a recorded trace (HoloLens, OptiTrack, Quest) into trimvr's
 *                 path format, optionally placed in a scene and resampled
 *   path synth    the bundled synthetic paths (predict/path_bundled.c)
 *   path info     duration, sampling and speed statistics of a path
 *   path check    how close the head comes to the scene's geometry
 *
 * The logic is in predict/ (trace_import.h, trace_place.h, path_stats.h) and
 * clearance.h. */
#include "app_scene.h"
#include "args.h"
#include "auto_place.h"
#include "clearance.h"
#include "commands.h"
#include "fs.h"
#include "path_bundled.h"
#include "path_stats.h"
#include "trace_import.h"
#include "trace_place.h"
#include "log.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define ARG_COUNT(a) ((int)(sizeof a / sizeof a[0]))

typedef struct import_opts {
    const char *in, *out, *format, *scene, *ref;
    float anchor[3];
    float heading, eye_height, height_offset, resample, gap;
} import_opts;

/* Placement is applied when any of its options is given; NAN marks "not given". */
static bool placement_from_opts(const import_opts* o, pred_placement* pl)
{
    bool any = !isnan(o->anchor[0]) || !isnan(o->heading) || !isnan(o->eye_height) ||
               !isnan(o->height_offset) || o->ref;
    memset(pl, 0, sizeof *pl);
    for (int i = 0; i < 3; i++)
        pl->anchor[i] = isnan(o->anchor[0]) ? 0.0 : o->anchor[i];
    pl->heading_deg = isnan(o->heading) ? 0.0 : o->heading;
    pl->eye_height_m = isnan(o->eye_height) ? 0.0 : o->eye_height;
    pl->height_offset_m = isnan(o->height_offset) ? 0.0 : o->height_offset;
    pl->ref = o->ref && strcmp(o->ref, "centroid") == 0 ? PRED_PLACE_CENTROID : PRED_PLACE_START;
    return any;
}

static int path_import(int argc, char** argv)
{
    import_opts o = {.anchor = {NAN, NAN, NAN}, .heading = NAN, .eye_height = NAN, .height_offset = NAN,
                     .resample = NAN};
    const tv_arg args[] = {
        {"in", TV_ARG_STRING, &o.in, "FILE", "recorded trace CSV (required)"},
        {"out", TV_ARG_STRING, &o.out, "FILE", "path CSV to write (required)"},
        {"format", TV_ARG_STRING, &o.format, "F", "auto, hololens, optitrack or quest (default auto: from the header)"},
        {"scene", TV_ARG_STRING, &o.scene, "S", "scene recorded as the path's '# scene:' line"},
        {"anchor", TV_ARG_VEC3, o.anchor, "X,Y,Z", "where the reference point lands (default 0,0,0)"},
        {"heading", TV_ARG_FLOAT, &o.heading, "DEG", "yaw of the reference forward direction, 0 = -Z, 90 = -X (default 0)"},
        {"ref", TV_ARG_STRING, &o.ref, "R", "start (first sample) or centroid (mean position and heading); default start"},
        {"eye-height", TV_ARG_FLOAT, &o.eye_height, "M", "put the median head height M above the anchor's y"},
        {"height-offset", TV_ARG_FLOAT, &o.height_offset, "M", "added to every height after placement"},
        {"resample", TV_ARG_FLOAT, &o.resample, "HZ", "resample uniformly at HZ (default: keep the recorded samples)"},
        {"gap", TV_ARG_FLOAT, &o.gap, "S", "report sample intervals longer than S seconds as gaps (default 0.1)"},
    };
    const char* summary =
        "Converts a recorded head-motion trace to trimvr's path format (metres, right-handed, +Y up, the head\n"
        "looking down -Z), dropping samples whose time does not increase. Any placement option moves and\n"
        "turns the whole trace rigidly into a scene (docs/paths.md, 'Recorded traces').";
    tv_args_result r = tv_args_parse("path import", summary, args, ARG_COUNT(args), argc, argv);
    if (r != TV_ARGS_OK)
        return r == TV_ARGS_HELP ? 0 : 2;
    pred_trace_desc desc = {.gap_s = o.gap};
    if (!o.in || !o.out) {
        tv_log(TV_LOG_ERROR, "--in and --out are required (see trimvr path import --help)");
        return 2;
    }
    if (o.format && !pred_trace_format_from_name(o.format, &desc.format)) {
        tv_log(TV_LOG_ERROR, "--format: unknown format '%s' (auto, hololens, optitrack, quest)",
               o.format);
        return 2;
    }
    if (o.ref && strcmp(o.ref, "start") != 0 && strcmp(o.ref, "centroid") != 0) {
        tv_log(TV_LOG_ERROR, "--ref: expected start or centroid, got '%s'", o.ref);
        return 2;
    }
    /* NAN: not given, keep the recorded samples; 0 Hz is no rate at all */
    if ((!isnan(o.resample) && !tv_arg_require("resample", o.resample, o.resample > 0.0f, "> 0 Hz")) ||
        !tv_arg_require("gap", o.gap, o.gap >= 0.0f, ">= 0 s") ||
        (!isnan(o.eye_height) && !tv_arg_require("eye-height", o.eye_height, o.eye_height > 0.0f, "> 0 m")))
        return 2;
    char err[512];
    pred_path path;
    pred_trace_report rep;
    if (!pred_trace_import(o.in, &desc, &path, &rep, err, sizeof err)) {
        tv_log(TV_LOG_ERROR, "%s", err);
        return 1;
    }
    pred_placement pl;
    char comment[1024], placement[256] = "placement: none (the recording's origin and heading)";
    if (placement_from_opts(&o, &pl)) {
        if (!pred_trace_place(&path, &pl)) {
            tv_log(TV_LOG_ERROR, "out of memory");
            pred_path_free(&path);
            return 1;
        }
        pred_placement_format(&pl, placement, sizeof placement);
    }
    if (!isnan(o.resample)) {
        pred_path resampled;
        if (!pred_path_resample(&path, o.resample, &resampled, err, sizeof err)) {
            tv_log(TV_LOG_ERROR, "%s", err);
            pred_path_free(&path);
            return 1;
        }
        pred_path_free(&path);
        path = resampled;
    }
    if (o.scene)
        snprintf(path.scene, sizeof path.scene, "%s", o.scene);
    snprintf(comment, sizeof comment,
             "source: %s (%s), %zu rows, %zu dropped (time not increasing), %zu gaps > %.3g s, longest %.1f ms\n"
             "%s\nresampled: %s",
             o.in, pred_trace_format_name(rep.format), rep.rows, rep.dropped, rep.gaps,
             desc.gap_s > 0.0 ? desc.gap_s : 0.1, rep.max_gap_s * 1e3, placement,
             !isnan(o.resample) ? "uniformly (see the sample times)" : "no (recorded sample times)");
    char dir[4096];
    snprintf(dir, sizeof dir, "%s", o.out);
    char* slash = strrchr(dir, '/');
    if (slash && slash != dir) {
        *slash = '\0';
        tv_mkdirs(dir); /* a failure shows as the save's "cannot create" */
    }
    bool ok = pred_path_save(&path, o.out, comment, err, sizeof err);
    if (ok) {
        char dropped[64] = "";
        if (rep.dropped)
            snprintf(dropped, sizeof dropped, " (first on line %zu)", rep.first_dropped_line);
        printf("trimvr path import: %s (%s): %zu rows, %zu dropped%s, %zu gap(s) > %.3g s (longest %.1f ms) -> "
               "%s: %zu samples, %.2f s\n",
               o.in, pred_trace_format_name(rep.format), rep.rows, rep.dropped, dropped, rep.gaps,
               desc.gap_s > 0.0 ? desc.gap_s : 0.1, rep.max_gap_s * 1e3, o.out, path.count,
               pred_path_duration(&path));
    }
    else
        tv_log(TV_LOG_ERROR, "%s", err);
    pred_path_free(&path);
    return ok ? 0 : 1;
}

/* path synth --scene: an automatic path through the scene's free space into one file. */
static int path_synth_scene(const char* spec, const char* kind_name, int seed, const char* out)
{
    tv_auto_path_kind kind;
    if (!tv_auto_path_kind_from_name(kind_name, &kind)) {
        tv_log(TV_LOG_ERROR, "--kind: expected walk, run or lookaround, got '%s'", kind_name);
        return 2;
    }
    char err[512] = "scene name too long", file[4096];
    scn_scene scene;
    if (!tv_resolve_scene_spec(spec, file, sizeof file) || !scn_load(file, &scene, err, sizeof err)) {
        tv_log(TV_LOG_ERROR, "%s", err);
        return 1;
    }
    pred_path path = {0};
    bool ok = tv_auto_path(spec, &scene, kind, (uint64_t)seed, &path, err, sizeof err) &&
              pred_path_save(&path, out, "generated by: trimvr path synth (automatic, docs/scenes.md)", err, sizeof err);
    if (ok)
        printf("trimvr path synth: %s: %s, %zu samples over %.2f s -> %s\n", spec, path.description, path.count,
               pred_path_duration(&path), out);
    else
        tv_log(TV_LOG_ERROR, "%s", err);
    pred_path_free(&path);
    scn_scene_free(&scene);
    return ok ? 0 : 1;
}

static int path_synth(int argc, char** argv)
{
    const char *out = NULL, *scene = NULL, *kind = "walk";
    bool list = false;
    int seed = 1;
    const tv_arg args[] = {
        {"list", TV_ARG_FLAG, &list, NULL, "print the bundled paths' recipes as CSV"},
        {"out", TV_ARG_STRING, &out, "DIR|FILE", "synthesise every bundled path into DIR (created); with --scene: the file"},
        {"scene", TV_ARG_STRING, &scene, "S", "a path through S's walkable free space instead (docs/scenes.md)"},
        {"kind", TV_ARG_STRING, &kind, "K", "with --scene: walk (1.4 m/s), run (3 m/s) or lookaround (default walk)"},
        {"seed", TV_ARG_INT, &seed, "N", "with --scene: head-motion seed (default 1)"},
    };
    tv_args_result r = tv_args_parse("path synth",
                                     "Writes or lists the bundled synthetic paths (paths/), or synthesises a walk, run\n"
                                     "or look-around through any scene's free space (--scene S --out FILE).",
                                     args, ARG_COUNT(args), argc, argv);
    if (r != TV_ARGS_OK)
        return r == TV_ARGS_HELP ? 0 : 2;
    if (list == (out != NULL) || (scene && list)) {
        tv_log(TV_LOG_ERROR, "give exactly one of --list and --out (--scene needs --out)");
        return 2;
    }
    if (scene)
        return path_synth_scene(scene, kind, seed, out);
    char err[512];
    if (list) {
        if (pred_bundled_path_print_list(stdout, err, sizeof err))
            return 0;
        tv_log(TV_LOG_ERROR, "%s", err);
        return 1;
    }
    if (!tv_mkdirs(out)) {
        tv_log(TV_LOG_ERROR, "%s: cannot create the output folder", out);
        return 1;
    }
    for (int i = 0; i < pred_bundled_path_count(); i++)
        if (!pred_bundled_path_write(i, out, err, sizeof err)) {
            tv_log(TV_LOG_ERROR, "%s", err);
            return 1;
        }
    printf("trimvr path synth: %d paths written to %s\n", pred_bundled_path_count(), out);
    return 0;
}

static int path_info(int argc, char** argv)
{
    if (argc == 1 && (strcmp(argv[0], "--help") == 0 || strcmp(argv[0], "-h") == 0)) {
        printf("usage: trimvr path info FILE\n\nPrints a path's duration, sampling, speeds and angular speeds\n"
               "(per sample interval: p50, p99) and how level its gaze is.\n");
        return 0;
    }
    if (argc != 1) {
        tv_log(TV_LOG_ERROR, "expected one path file (see trimvr path info --help)");
        return 2;
    }
    char err[512];
    pred_path path;
    if (!pred_path_load(argv[0], &path, err, sizeof err)) {
        tv_log(TV_LOG_ERROR, "%s", err);
        return 1;
    }
    pred_path_stats st;
    bool ok = pred_path_stats_compute(&path, &st, err, sizeof err);
    if (ok) {
        printf("path              %s\n", argv[0]);
        printf("scene             %s\n", path.scene[0] ? path.scene : "(none)");
        printf("samples           %zu over %.2f s (interval median %.2f ms, max %.2f ms)\n", st.samples,
               st.duration_s, st.dt_median_s * 1e3, st.dt_max_s * 1e3);
        printf("speed             mean %.3f, p50 %.3f, p99 %.3f m/s\n", st.speed_mean, st.speed_p50, st.speed_p99);
        printf("angular speed     mean %.1f, p50 %.1f, p99 %.1f deg/s\n", st.ang_speed_mean, st.ang_speed_p50,
               st.ang_speed_p99);
        printf("gaze              mean |forward y| %.3f (0 = level)\n", st.forward_y_mean_abs);
    } else {
        tv_log(TV_LOG_ERROR, "%s: %s", argv[0], err);
    }
    pred_path_free(&path);
    return ok ? 0 : 1;
}

static int path_check(int argc, char** argv)
{
    const char *file = NULL, *scene_spec = NULL;
    float near = 0.2f, radius = 1.0f, min_required = -1.0f;
    const tv_arg args[] = {
        {"path", TV_ARG_STRING, &file, "FILE", "path to check (required)"},
        {"scene", TV_ARG_STRING, &scene_spec, "S", "scene (default: the path's '# scene:' line)"},
        {"near", TV_ARG_FLOAT, &near, "M", "count the samples closer than M to geometry (default 0.2)"},
        {"radius", TV_ARG_FLOAT, &radius, "M", "search radius; farther geometry reads as M (default 1.0)"},
        {"min", TV_ARG_FLOAT, &min_required, "M", "exit 1 when the head comes closer than M"},
    };
    const char* summary =
        "Measures, at every sample of a path, the distance from the head (the path's position, between the\n"
        "eyes) to the nearest triangle of the scene: a placed recorded trace must keep the head out of walls.";
    tv_args_result r = tv_args_parse("path check", summary, args, ARG_COUNT(args), argc, argv);
    if (r != TV_ARGS_OK)
        return r == TV_ARGS_HELP ? 0 : 2;
    if (!file || !(near > 0.0f) || !(radius >= near)) {
        tv_log(TV_LOG_ERROR, "--path is required, and 0 < --near <= --radius");
        return 2;
    }
    char err[512], spec[4096];
    pred_path path;
    if (!pred_path_load(file, &path, err, sizeof err)) {
        tv_log(TV_LOG_ERROR, "%s", err);
        return 1;
    }
    if (!scene_spec && !path.scene[0]) {
        tv_log(TV_LOG_ERROR, "%s names no scene: give --scene", file);
        pred_path_free(&path);
        return 2;
    }
    scn_scene scene;
    if (!tv_resolve_scene_spec(scene_spec ? scene_spec : path.scene, spec, sizeof spec) ||
        !scn_load(spec, &scene, err, sizeof err)) {
        tv_log(TV_LOG_ERROR, "%s", err);
        pred_path_free(&path);
        return 1;
    }
    tv_clearance* cl = tv_clearance_create(&scene, &(tv_clearance_desc){.radius_m = radius}, err, sizeof err);
    if (!cl) {
        tv_log(TV_LOG_ERROR, "%s", err);
        scn_scene_free(&scene);
        pred_path_free(&path);
        return 1;
    }
    size_t closest = 0, close_count = 0;
    float dmin = radius;
    uint32_t dmin_tri = UINT32_MAX;
    for (size_t i = 0; i < path.count; i++) {
        const double* p = path.poses[i].p;
        uint32_t tri;
        float d = tv_clearance_query(cl, (const float[3]){(float)p[0], (float)p[1], (float)p[2]}, &tri);
        close_count += d < near;
        if (d < dmin) {
            dmin = d;
            dmin_tri = tri;
            closest = i;
        }
    }
    const pred_pose* at = &path.poses[closest];
    printf("path              %s\n", file);
    printf("scene             %s (%u triangles)\n", spec, scene.triangle_count);
    printf("samples           %zu\n", path.count);
    if (dmin_tri == UINT32_MAX)
        printf("head clearance    no geometry within %.2f m of any sample\n", radius);
    else
        printf("head clearance    min %.3f m at t = %.2f s, head (%.2f, %.2f, %.2f), triangle %u\n", dmin, at->t,
               at->p[0], at->p[1], at->p[2], dmin_tri);
    printf("closer than %.2f  %zu samples (%.2f%%)\n", near, close_count,
           path.count ? 100.0 * (double)close_count / (double)path.count : 0.0);
    bool ok = !(min_required >= 0.0f && dmin < min_required);
    if (!ok)
        tv_log(TV_LOG_ERROR, "%s: the head comes within %.3f m of %s (--min %.3f)", file,
               dmin, spec, min_required);
    tv_clearance_destroy(cl);
    scn_scene_free(&scene);
    pred_path_free(&path);
    return ok ? 0 : 1;
}

int tv_cmd_path(int argc, char** argv)
{
    static const struct {
        const char* name;
        int (*run)(int, char**);
        const char* summary;
    } verbs[] = {
        {"import", path_import, "convert a recorded trace (HoloLens, OptiTrack, Quest) and place it in a scene"},
        {"synth", path_synth, "write or list the bundled synthetic paths"},
        {"info", path_info, "duration, sampling and speed statistics of a path file"},
        {"check", path_check, "how close the head comes to a scene's geometry (placed traces in walls)"},
    };
    if (argc >= 1)
        for (int i = 0; i < ARG_COUNT(verbs); i++)
            if (strcmp(argv[0], verbs[i].name) == 0) {
                char program[64];
                snprintf(program, sizeof program, "trimvr path %s", verbs[i].name);
                tv_log_set_program(program);
                return verbs[i].run(argc - 1, argv + 1);
            }
    bool help = argc >= 1 && (strcmp(argv[0], "--help") == 0 || strcmp(argv[0], "-h") == 0);
    if (!help && argc >= 1)
        tv_log(TV_LOG_ERROR, "unknown verb '%s'", argv[0]);
    FILE* f = help ? stdout : stderr;
    fprintf(f, "usage: trimvr path <verb> [options]\n\nverbs:\n");
    for (int i = 0; i < ARG_COUNT(verbs); i++)
        fprintf(f, "  %-8s %s\n", verbs[i].name, verbs[i].summary);
    return help ? 0 : 2;
}
