/* trimvr predict-eval: prediction error versus horizon of each predictor on
 * head-motion paths, as the markdown table of docs/prediction.md. The logic
 * is pred_eval_run() (predict/eval.h). */
#include "args.h"
#include "commands.h"
#include "eval.h"
#include "log.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_PATHS = 256 };

typedef struct eval_opts {
    const char* paths[MAX_PATHS];
    int path_count;
    const char* predictor;
    const char* horizons;
    const char* noise;
    int seed;
} eval_opts;

/* "10,20,50,100" (ms) into desc; false on a bad list. */
static bool parse_horizons(const char* s, pred_error_tracker_desc* desc)
{
    desc->horizon_count = 0;
    for (const char* c = s;;) {
        char* end = NULL;
        double ms = strtod(c, &end);
        if (end == c || !(ms > 0.0 && ms <= 10000.0) || desc->horizon_count == PRED_MAX_HORIZONS ||
            (desc->horizon_count && ms * 1e-3 <= desc->horizons_s[desc->horizon_count - 1]))
            return false;
        desc->horizons_s[desc->horizon_count++] = ms * 1e-3;
        if (*end == '\0')
            return true;
        if (*end != ',')
            return false;
        c = end + 1;
    }
}

/* "on" (the HMD's default sensor noise), "off", or "POS_M,ROT_DEG". */
static bool parse_noise(const char* s, hmd_desc* hmd)
{
    if (strcmp(s, "on") == 0)
        return true;
    if (strcmp(s, "off") == 0) {
        hmd->noiseless = true;
        return true;
    }
    char* end = NULL;
    hmd->pos_noise_m = strtod(s, &end);
    if (end == s || *end != ',' || !(hmd->pos_noise_m > 0.0)) /* zero would mean the default */
        return false;
    const char* rot = end + 1;
    hmd->rot_noise_deg = strtod(rot, &end);
    return end != rot && *end == '\0' && hmd->rot_noise_deg > 0.0;
}

/* --path may repeat, which tv_args does not do: collect its values and pass the rest on. */
static bool take_paths(int argc, char** argv, eval_opts* o, int* rest_argc, char** rest)
{
    *rest_argc = 0;
    for (int i = 0; i < argc; i++) {
        const char* value = NULL;
        if (strcmp(argv[i], "--path") == 0) {
            if (i + 1 == argc) {
                tv_log(TV_LOG_ERROR, "--path needs a FILE");
                return false;
            }
            value = argv[++i];
        } else if (strncmp(argv[i], "--path=", 7) == 0) {
            value = argv[i] + 7;
        } else {
            rest[(*rest_argc)++] = argv[i];
            continue;
        }
        if (o->path_count == MAX_PATHS) {
            tv_log(TV_LOG_ERROR, "more than %d --path options", MAX_PATHS);
            return false;
        }
        o->paths[o->path_count++] = value;
    }
    return true;
}

static int eval_path(const char* file, const pred_eval_desc* base, int kind_first, int kind_last)
{
    char err[512];
    pred_path path;
    if (!pred_path_load(file, &path, err, sizeof err)) {
        tv_log(TV_LOG_ERROR, "%s", err);
        return 1;
    }
    const char* name = strrchr(file, '/') ? strrchr(file, '/') + 1 : file;
    pred_eval_desc desc = *base;
    desc.path = &path;
    int status = 0;
    for (int k = kind_first; k <= kind_last && status == 0; k++) {
        desc.predictor.kind = (pred_kind)k;
        pred_eval_result r;
        if (pred_eval_run(&desc, &r, err, sizeof err)) {
            pred_eval_print_rows(stdout, name, (pred_kind)k, &r);
        } else {
            tv_log(TV_LOG_ERROR, "%s: %s", file, err);
            status = 1;
        }
    }
    pred_path_free(&path);
    return status;
}

int tv_cmd_predict_eval(int argc, char** argv)
{
    eval_opts o = {.predictor = "all", .horizons = "10,20,50,100", .noise = "on"};
    const char* path_help = NULL; /* listed for --help; take_paths() consumes --path */
    const tv_arg args[] = {
        {"path", TV_ARG_STRING, &path_help, "FILE", "head-motion path CSV (required; repeat for several)"},
        {"predictor", TV_ARG_STRING, &o.predictor, "P", "cv, ca, kalman or all (default all)"},
        {"horizons", TV_ARG_STRING, &o.horizons, "MS,...", "increasing prediction horizons in ms (default 10,20,50,100)"},
        {"noise", TV_ARG_STRING, &o.noise, "N", "sensor noise: on (HMD default), off, or POS_M,ROT_DEG, both > 0 (default on)"},
        {"seed", TV_ARG_INT, &o.seed, "N", "sensor noise seed (default 0)"},
    };
    const char* summary =
        "Replays each path through the simulated HMD into the predictors and prints the position and\n"
        "rotation error p50/p99 per horizon as a markdown table (docs/prediction.md).";
    char** rest = malloc(sizeof(char*) * (size_t)(argc ? argc : 1));
    if (!rest) {
        tv_log(TV_LOG_ERROR, "out of memory");
        return 1;
    }
    int rest_argc = 0;
    bool taken = take_paths(argc, argv, &o, &rest_argc, rest);
    tv_args_result r = taken ? tv_args_parse("predict-eval", summary, args, (int)(sizeof args / sizeof args[0]),
                                              rest_argc, rest)
                             : TV_ARGS_ERROR;
    free(rest);
    if (r != TV_ARGS_OK)
        return r == TV_ARGS_HELP ? 0 : 2;
    pred_eval_desc desc = {.hmd = {.seed = (uint64_t)o.seed}};
    int kind_first = 0, kind_last = PRED_KIND_COUNT - 1;
    pred_kind kind;
    if (strcmp(o.predictor, "all") != 0) {
        if (!pred_kind_from_name(o.predictor, &kind)) {
            tv_log(TV_LOG_ERROR, "--predictor: expected cv, ca, kalman or all, got '%s'",
                   o.predictor);
            return 2;
        }
        kind_first = kind_last = (int)kind;
    }
    if (!parse_horizons(o.horizons, &desc.horizons)) {
        tv_log(TV_LOG_ERROR, "--horizons: expected up to %d increasing values in (0, 10000] "
               "ms, got '%s'", PRED_MAX_HORIZONS, o.horizons);
        return 2;
    }
    if (!parse_noise(o.noise, &desc.hmd)) {
        tv_log(TV_LOG_ERROR, "--noise: expected on, off or POS_M,ROT_DEG, got '%s'", o.noise);
        return 2;
    }
    if (!o.path_count) {
        tv_log(TV_LOG_ERROR, "--path is required (see trimvr predict-eval --help)");
        return 2;
    }
    pred_eval_print_header(stdout);
    for (int i = 0; i < o.path_count; i++)
        if (eval_path(o.paths[i], &desc, kind_first, kind_last) != 0)
            return 1;
    return 0;
}
