#define _POSIX_C_SOURCE 200809L
#include "args.h"
#include "cli_viewcell.h"
#include "fs.h"
#include "log.h"
#include "pvs.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static bool parse_float(const char* s, float* out)
{
    char* end;
    errno = 0;
    double v = strtod(s, &end);
    /* finite as a float too: 1e300 would pass a range check like ">= 0" as inf */
    if (end == s || *end != '\0' || errno != 0 || !isfinite(v) || !isfinite((float)v))
        return false;
    *out = (float)v;
    return true;
}

static bool parse_value(const tv_arg* a, const char* value)
{
    switch (a->kind) {
    case TV_ARG_STRING:
        *(const char**)a->out = value;
        return true;
    case TV_ARG_INT: {
        char* end;
        errno = 0;
        long v = strtol(value, &end, 10);
        if (end == value || *end != '\0' || errno != 0 || v < -2147483647L || v > 2147483647L)
            return false;
        *(int*)a->out = (int)v;
        return true;
    }
    case TV_ARG_FLOAT:
        return parse_float(value, (float*)a->out);
    case TV_ARG_RES: {
        unsigned w, h;
        char tail;
        if (sscanf(value, "%ux%u%c", &w, &h, &tail) != 2 || w == 0 || h == 0 || w > 16384 || h > 16384)
            return false;
        ((unsigned*)a->out)[0] = w;
        ((unsigned*)a->out)[1] = h;
        return true;
    }
    case TV_ARG_VEC3: {
        char buf[128];
        if (strlen(value) >= sizeof buf)
            return false;
        strcpy(buf, value);
        float* v = (float*)a->out;
        char* save = NULL;
        char* tok = strtok_r(buf, ",", &save);
        for (int i = 0; i < 3; i++) {
            if (!tok || !parse_float(tok, &v[i]))
                return false;
            tok = strtok_r(NULL, ",", &save);
        }
        return tok == NULL;
    }
    case TV_ARG_FLAG:
        break;
    }
    return false;
}

static const char* kind_expectation(tv_arg_kind kind)
{
    switch (kind) {
    case TV_ARG_INT: return "an integer";
    case TV_ARG_FLOAT: return "a finite number";
    case TV_ARG_RES: return "WIDTHxHEIGHT, e.g. 640x360";
    case TV_ARG_VEC3: return "three numbers X,Y,Z";
    default: return "a value";
    }
}

tv_args_result tv_args_parse(const char* command, const char* summary, const tv_arg* args,
                             int arg_count, int argc, char** argv)
{
    for (int i = 0; i < argc; i++) {
        const char* tok = argv[i];
        if (strcmp(tok, "--help") == 0 || strcmp(tok, "-h") == 0) {
            tv_args_usage(command, summary, args, arg_count);
            return TV_ARGS_HELP;
        }
        if (strncmp(tok, "--", 2) != 0) {
            tv_log(TV_LOG_ERROR, "unexpected argument '%s' (see trimvr %s --help)",
                   tok, command);
            return TV_ARGS_ERROR;
        }
        const char* name = tok + 2;
        const char* eq = strchr(name, '=');
        size_t name_len = eq ? (size_t)(eq - name) : strlen(name);
        const tv_arg* a = NULL;
        for (int k = 0; k < arg_count; k++)
            if (strlen(args[k].name) == name_len && strncmp(args[k].name, name, name_len) == 0)
                a = &args[k];
        if (!a) {
            tv_log(TV_LOG_ERROR, "unknown option '--%.*s' (see trimvr %s --help)",
                   (int)name_len, name, command);
            return TV_ARGS_ERROR;
        }
        if (a->kind == TV_ARG_FLAG) {
            if (eq) {
                tv_log(TV_LOG_ERROR, "--%s takes no value", a->name);
                return TV_ARGS_ERROR;
            }
            *(bool*)a->out = true;
            continue;
        }
        const char* value = eq ? eq + 1 : (i + 1 < argc ? argv[++i] : NULL);
        if (!value) {
            tv_log(TV_LOG_ERROR, "--%s needs %s", a->name, kind_expectation(a->kind));
            return TV_ARGS_ERROR;
        }
        if (!parse_value(a, value)) {
            tv_log(TV_LOG_ERROR, "--%s: expected %s, got '%s'", a->name,
                   kind_expectation(a->kind), value);
            return TV_ARGS_ERROR;
        }
    }
    return TV_ARGS_OK;
}

void tv_args_usage(const char* command, const char* summary, const tv_arg* args, int arg_count)
{
    printf("usage: trimvr %s [options]\n\n%s\n\noptions:\n", command, summary);
    for (int k = 0; k < arg_count; k++) {
        char left[64];
        snprintf(left, sizeof left, "--%s%s%s", args[k].name, args[k].metavar ? " " : "",
                 args[k].metavar ? args[k].metavar : "");
        printf("  %-24s %s\n", left, args[k].help);
    }
    printf("  %-24s %s\n", "--help", "show this help");
}

int tv_arg_kbuffer_layout(const char* value)
{
    if (!value)
        return 0;
    if (strcmp(value, "flat") == 0 || strcmp(value, "paged") == 0)
        return value[0] == 'f' ? 1 : 2;
    tv_log(TV_LOG_ERROR, "--kbuffer-layout %s: must be flat or paged", value);
    return -1;
}

bool tv_arg_require(const char* name, double value, bool ok, const char* requirement)
{
    if (!ok)
        tv_log(TV_LOG_ERROR, "--%s %g: must be %s", name, value, requirement);
    return ok;
}

bool tv_arg_k(int k, int k_deep, int k_regions)
{
    _Static_assert(PVS_K_MAX == 32, "the messages below say 32");
    const int max = (int)PVS_K_MAX;
    return tv_arg_require("k", k, k >= 1 && k <= max, "in [1, 32]") &&
           tv_arg_require("k-deep", k_deep, k_deep >= 0 && k_deep <= max, "in [0, 32]") &&
           tv_arg_require("k-regions", k_regions, k_regions >= 0 && k_regions <= max, "in [0, 32]");
}

bool tv_arg_viewcell(float delta, float fov, float fov_pvs)
{
    return tv_arg_require("delta", delta, delta >= 0.0f, ">= 0") &&
           tv_arg_require("fov", fov, fov > 0.0f && fov < 180.0f, "in (0, 180) degrees") &&
           tv_arg_require("fov-pvs", fov_pvs, fov_pvs > 0.0f && fov_pvs < TV_VIEWCELL_MAX_FOV_PVS,
                          "in (0, 179) degrees");
}

bool tv_arg_gt_cache(const char* dir)
{
    if (dir && !tv_mkdirs(dir)) {
        tv_log(TV_LOG_ERROR, "--gt-cache %s: cannot create the folder", dir);
        return false;
    }
    return true;
}
