/* args.h - table-driven option parsing shared by every trimvr subcommand.
 *
 * Options are `--name value` or `--name=value`; flags take no value. Each
 * option writes into caller-owned storage whose type follows its kind, so a
 * subcommand declares its defaults in a plain struct and one table. Errors are
 * one line naming the command, the option and the bad value. */
#ifndef TRIMVR_ARGS_H
#define TRIMVR_ARGS_H

#include <stdbool.h>
#include <stdint.h>

typedef enum tv_arg_kind {
    TV_ARG_STRING, /* const char**        */
    TV_ARG_INT,    /* int*                */
    TV_ARG_FLOAT,  /* float*              */
    TV_ARG_FLAG,   /* bool*, no value     */
    TV_ARG_RES,    /* unsigned[2], "WxH"  */
    TV_ARG_VEC3    /* float[3], "X,Y,Z"   */
} tv_arg_kind;

typedef struct tv_arg {
    const char* name; /* without the leading "--" */
    tv_arg_kind kind;
    void* out;
    const char* metavar; /* shown in --help, NULL for flags */
    const char* help;
} tv_arg;

typedef enum tv_args_result {
    TV_ARGS_OK = 0,
    TV_ARGS_ERROR = 1, /* message already printed */
    TV_ARGS_HELP = 2   /* usage already printed   */
} tv_args_result;

/* Option rows several commands share, so that their names, value names and
 * help read the same everywhere. */
#define TV_ARG_METHOD(out) {"method", TV_ARG_STRING, (out), "M", "PVS method: tr, gt, sas, frompoint or q3vis (default tr)"}
#define TV_ARG_K(out) {"k", TV_ARG_INT, (out), "N", "tr: k-buffer slots per pixel and kind, >= 1 (default 16)"}
#define TV_ARG_K_REGIONS(out) {"k-regions", TV_ARG_INT, (out), "N", "tr: entries the region list stores; one longer than k alone resolves with all of them, umbrae included, not as overflow (default 0: k-deep; at most 32)"}
#define TV_ARG_K_DEEP(out) {"k-deep", TV_ARG_INT, (out), "N", "tr: entries each list stores; a pixel with more than k in its front or back list resolves with its umbrae ended at their footprints, not as overflow, up to N (default 0: k; at most 32)"}
#define TV_ARG_PVS_RES(name, out) {(name), TV_ARG_RES, (out), "WxH", "tr: PVS resolution (default 512x512)"}
#define TV_ARG_FOV_PVS(out) {"fov-pvs", TV_ARG_FLOAT, (out), "DEG", "PVS FOV, square frustum (default 90)"}
#define TV_ARG_MAX_LAYERS(out) {"max-layers", TV_ARG_INT, (out), "N", "tr: merge octree layers into at most N (default -1: 14 on a GPU, never on a CPU device; 0: never)"}
#define TV_ARG_GT_CACHE(out) {"gt-cache", TV_ARG_STRING, (out), "DIR", \
    "keep each viewcell's ground truth in DIR and reuse it when scene and settings match (docs/bench.md)"}
#define TV_ARG_KBUFFER_LAYOUT(out) {"kbuffer-layout", TV_ARG_STRING, (out), "L", "tr: k-buffer layout, flat or paged (default: paged on a GPU, flat on a CPU device)"}
#define TV_ARG_SAMPLES(out) {"samples", TV_ARG_INT, (out), "N", "views per viewcell of the sampled ground truth (default 200)"}

/* The defaults those rows state. */
#define TV_ARGS_DEFAULT_K 16
#define TV_ARGS_DEFAULT_SAMPLES 200
#define TV_ARGS_DEFAULT_MAX_LAYERS (-1)

/* pvs_desc.max_layers for a --max-layers value (>= -1; -1: the device's default, 0: the strict order). */
static inline uint32_t tv_arg_max_layers(int n)
{
    return n > 0 ? (uint32_t)n : n == 0 ? UINT32_MAX : 0;
}

/* pvs_desc.kbuffer_layout (pvs_kbuffer_layout) for a --kbuffer-layout value:
 * 0 (the device's default) for NULL, 1 for "flat", 2 for "paged"; otherwise
 * prints the one-line error and returns -1. */
int tv_arg_kbuffer_layout(const char* value);

/* When !ok, prints the one-line error "--NAME VALUE: must be REQUIREMENT"
 * (for example "--frames -3: must be >= 0"). Returns ok. */
bool tv_arg_require(const char* name, double value, bool ok, const char* requirement);

/* --delta, --fov and --fov-pvs of a viewcell given on the command line (pvs,
 * eval): each out of range gives tv_arg_require's line. Returns true when all
 * three are in range. */
bool tv_arg_viewcell(float delta, float fov, float fov_pvs);

/* --k (1..PVS_K_MAX), --k-deep and --k-regions (0..PVS_K_MAX: 0 is the default) of the tr method, checked
 * before any device is made: each out of range gives tv_arg_require's line. */
bool tv_arg_k(int k, int k_deep, int k_regions);

/* --gt-cache DIR: creates the folder (NULL: no cache, true). When it cannot,
 * prints "--gt-cache DIR: cannot create the folder" and returns false. */
bool tv_arg_gt_cache(const char* dir);

/* Parses argv[0..argc) (argv[0] is the first option, not the command name).
 * Prints usage for --help/-h. `summary` is the one-paragraph description. */
tv_args_result tv_args_parse(const char* command, const char* summary, const tv_arg* args,
                             int arg_count, int argc, char** argv);

void tv_args_usage(const char* command, const char* summary, const tv_arg* args, int arg_count);

#endif
