#include "bench_part.h"

#include "json_read.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FORMAT "trimvr-bench-part 1"

typedef enum field_type { F32, F64, U32, U64 } field_type;

typedef struct field {
    const char* name;
    field_type type;
    size_t offset; /* in tv_bench_cell */
} field;

#define M(f) offsetof(tv_bench_cell, c.m.f)
#define T(f) offsetof(tv_bench_cell, c.st.tr.f)
/* Every value a row, its interval or its worst-cell line is computed from. */
static const field k_fields[] = {
    {"v0_x", F32, offsetof(tv_bench_cell, c.vc.v0[0])}, {"v0_y", F32, offsetof(tv_bench_cell, c.vc.v0[1])},
    {"v0_z", F32, offsetof(tv_bench_cell, c.vc.v0[2])}, {"fwd_x", F32, offsetof(tv_bench_cell, c.vc.forward[0])},
    {"fwd_y", F32, offsetof(tv_bench_cell, c.vc.forward[1])}, {"fwd_z", F32, offsetof(tv_bench_cell, c.vc.forward[2])},
    {"samples", U32, M(samples)}, {"scene_tris", U32, M(scene_tris)}, {"pvs_tris", U32, M(pvs_tris)},
    {"gt_tris", U32, M(gt_tris)}, {"fp_tris", U32, M(fp_tris)}, {"fn_tris", U32, M(fn_tris)},
    {"pvs_fraction", F64, M(pvs_fraction)}, {"gt_fraction", F64, M(gt_fraction)}, {"fp_rate", F64, M(fp_rate)},
    {"fn_rate", F64, M(fn_rate)}, {"gt_tris_reliable", U32, M(gt_tris_reliable)},
    {"fp_rate_reliable", F64, M(fp_rate_reliable)}, {"fn_rate_reliable", F64, M(fn_rate_reliable)},
    {"gt_once", U32, M(gt_once)}, {"gt_twice", U32, M(gt_twice)}, {"gt_est_tris", F64, M(gt_est_tris)},
    {"gt_completeness", F64, M(gt_completeness)}, {"fng_pixels_mean", F64, M(fng_pixels_mean)},
    {"fng_pixels_max", F64, M(fng_pixels_max)}, {"fng_fraction_mean", F64, M(fng_fraction_mean)},
    {"fng_reliable_pixels_mean", F64, M(fng_reliable_pixels_mean)}, {"psnr_mean_db", F64, M(psnr_mean_db)},
    {"psnr_min_db", F64, M(psnr_min_db)}, {"worst_view", U32, M(worst_view)}, {"ssim_mean", F64, M(ssim_mean)},
    {"ssim_min", F64, M(ssim_min)}, {"gt_ms", F64, M(gt_ms)}, {"eval_ms", F64, M(eval_ms)},
    {"full_render_ms", F64, M(full_render_ms)}, {"pvs_render_ms", F64, M(pvs_render_ms)},
    {"pvs_ms", F64, offsetof(tv_bench_cell, c.pvs_ms)}, {"method_ms", F64, offsetof(tv_bench_cell, c.st.total_ms)},
    {"views", U32, offsetof(tv_bench_cell, c.st.views)}, {"p0_ms", F64, T(ms[0])}, {"p1_ms", F64, T(ms[1])},
    {"p2_ms", F64, T(ms[2])}, {"p3_ms", F64, T(ms[3])}, {"p4_ms", F64, T(ms[4])}, {"tr_ms", F64, T(total_ms)},
    {"layers", U32, T(layers)}, {"layer_triangles", U32, T(layer_triangles)}, {"silhouettes", U32, T(silhouettes)},
    {"active_pixels", U64, T(active_pixels)}, {"mean_sequence", F64, T(mean_sequence)},
    {"kbuffer_bytes", U64, T(kbuffer_bytes)}, {"kbuffer_bytes_used", U64, T(kbuffer_bytes_used)},
    {"overflow_pixels", U64, T(overflow_pixels)}, {"overflow_fronts", U64, T(overflow_fronts)},
    {"coop_pixels", U64, T(coop_pixels)},
    {"loop_budget_pixels", U64, T(loop_budget_pixels)}, {"overflow_share", F64, offsetof(tv_bench_cell, c.overflow_share)},
    {"full_ms_0", F64, offsetof(tv_bench_cell, full_ms[0])},
    {"full_ms_1", F64, offsetof(tv_bench_cell, full_ms[1])}, {"full_ms_2", F64, offsetof(tv_bench_cell, full_ms[2])},
};
#undef M
#undef T
enum { FIELD_COUNT = (int)(sizeof k_fields / sizeof k_fields[0]) };

static void put_string(FILE* f, const char* s)
{
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"' || *s == '\\')
            fprintf(f, "\\%c", *s);
        else if ((unsigned char)*s < 0x20)
            fprintf(f, "\\u%04x", (unsigned char)*s);
        else
            fputc(*s, f);
    }
    fputc('"', f);
}

static void put_double(FILE* f, double v)
{
    if (isfinite(v))
        fprintf(f, "%.17g", v);
    else
        fprintf(f, "\"%s\"", isnan(v) ? "nan" : v > 0 ? "inf" : "-inf");
}

static void put_field(FILE* f, const tv_bench_cell* c, const field* d)
{
    const char* at = (const char*)c + d->offset;
    switch (d->type) {
    case F32: put_double(f, *(const float*)at); break;
    case F64: put_double(f, *(const double*)at); break;
    case U32: fprintf(f, "%u", *(const uint32_t*)at); break;
    case U64: fprintf(f, "%llu", (unsigned long long)*(const uint64_t*)at); break;
    }
}

bool tv_bench_part_write(const char* file, const tv_bench_part* p, char* err, size_t err_size)
{
    FILE* f = fopen(file, "w");
    if (!f) {
        snprintf(err, err_size, "%s: cannot write", file);
        return false;
    }
    fprintf(f, "{\n  \"format\": \"" FORMAT "\",\n  \"version\": ");
    put_string(f, p->version);
    fprintf(f, ",\n  \"settings\": ");
    put_string(f, p->settings);
    fprintf(f, ",\n  \"command\": ");
    put_string(f, p->command);
    fprintf(f, ",\n  \"device\": ");
    put_string(f, p->device);
    fprintf(f, ",\n  \"date\": ");
    put_string(f, p->date);
    fprintf(f, ",\n  \"shard\": %d, \"shards\": %d, \"wall_s\": %.3f,\n", p->shard, p->shards, p->wall_s);
    fprintf(f, "  \"sample_res\": [%u, %u], \"pvs_res\": [%u, %u], \"samples\": %d, \"fov_deg\": %.9g, "
               "\"fov_pvs_deg\": %.9g,\n  \"fields\": [",
            p->res[0], p->res[1], p->pvs_res[0], p->pvs_res[1], p->samples, p->fov, p->fov_pvs);
    for (int i = 0; i < FIELD_COUNT; i++)
        fprintf(f, "%s\"%s\"", i ? ", " : "", k_fields[i].name);
    fprintf(f, "],\n  \"cells\": [");
    for (int i = 0; i < p->count; i++) {
        const tv_bench_cell* c = &p->cells[i];
        fprintf(f, "%s\n    {\"row\": %d, \"index\": %d, \"scene\": ", i ? "," : "", c->row, c->index);
        put_string(f, c->scene);
        fprintf(f, ", \"method\": \"%s\", \"delta\": %.9g, \"v\": [", pvs_method_name(c->method), c->delta);
        for (int k = 0; k < FIELD_COUNT; k++) {
            fprintf(f, k ? ", " : "");
            put_field(f, c, &k_fields[k]);
        }
        fprintf(f, "]}");
    }
    fprintf(f, "\n  ]\n}\n");
    if (fclose(f) != 0) {
        snprintf(err, err_size, "%s: write failed", file);
        return false;
    }
    return true;
}

/* A number, or one of the strings put_double writes for non-finite values. */
static bool get_double(const tv_json* j, double* v)
{
    if (j && j->type == TV_JSON_NUMBER) {
        *v = j->num;
        return true;
    }
    if (!j || j->type != TV_JSON_STRING)
        return false;
    if (strcmp(j->str, "nan") == 0)
        *v = NAN;
    else if (strcmp(j->str, "inf") == 0 || strcmp(j->str, "-inf") == 0)
        *v = j->str[0] == '-' ? -INFINITY : INFINITY;
    else
        return false;
    return true;
}

static bool get_field(const tv_json* j, tv_bench_cell* c, const field* d)
{
    double v;
    if (!get_double(j, &v))
        return false;
    char* at = (char*)c + d->offset;
    bool whole = isfinite(v) && v >= 0.0 && v == floor(v);
    switch (d->type) {
    case F32: *(float*)at = (float)v; return true;
    case F64: *(double*)at = v; return true;
    case U32: *(uint32_t*)at = (uint32_t)v; return whole && v <= UINT32_MAX;
    case U64: *(uint64_t*)at = (uint64_t)v; return whole && v < 18446744073709551616.0;
    }
    return false;
}

static bool copy_string(const tv_json* j, char* out, size_t size)
{
    if (!j || j->type != TV_JSON_STRING || strlen(j->str) >= size)
        return false;
    memcpy(out, j->str, strlen(j->str) + 1);
    return true;
}

static bool get_int(const tv_json* j, int* out)
{
    if (!j || j->type != TV_JSON_NUMBER || j->num != floor(j->num) || fabs(j->num) > 1e9)
        return false;
    *out = (int)j->num;
    return true;
}

static bool get_pair(const tv_json* j, unsigned out[2])
{
    int v[2];
    if (!j || j->type != TV_JSON_ARRAY || j->count != 2 || !get_int(&j->items[0], &v[0]) ||
        !get_int(&j->items[1], &v[1]) || v[0] < 0 || v[1] < 0)
        return false;
    out[0] = (unsigned)v[0];
    out[1] = (unsigned)v[1];
    return true;
}

static bool read_cell(const tv_json* j, tv_bench_cell* c)
{
    const tv_json* v = tv_json_get(j, "v");
    double delta;
    if (!get_int(tv_json_get(j, "row"), &c->row) || !get_int(tv_json_get(j, "index"), &c->index) ||
        c->row < 0 || c->index < 0 || !copy_string(tv_json_get(j, "scene"), c->scene, sizeof c->scene) ||
        !get_double(tv_json_get(j, "delta"), &delta) || !tv_json_get(j, "method") ||
        tv_json_get(j, "method")->type != TV_JSON_STRING ||
        !pvs_method_from_name(tv_json_get(j, "method")->str, &c->method) || !v || v->type != TV_JSON_ARRAY ||
        v->count != FIELD_COUNT)
        return false;
    c->delta = (float)delta;
    for (int k = 0; k < FIELD_COUNT; k++)
        if (!get_field(&v->items[k], c, &k_fields[k]))
            return false;
    return true;
}

static bool read_header(const tv_json* doc, tv_bench_part* p)
{
    const tv_json* fmt = tv_json_get(doc, "format");
    double fov, fov_pvs;
    bool ok = fmt && fmt->type == TV_JSON_STRING && strcmp(fmt->str, FORMAT) == 0 &&
           copy_string(tv_json_get(doc, "version"), p->version, sizeof p->version) &&
           copy_string(tv_json_get(doc, "settings"), p->settings, sizeof p->settings) &&
           copy_string(tv_json_get(doc, "command"), p->command, sizeof p->command) &&
           copy_string(tv_json_get(doc, "device"), p->device, sizeof p->device) &&
           copy_string(tv_json_get(doc, "date"), p->date, sizeof p->date) &&
           get_int(tv_json_get(doc, "shard"), &p->shard) && get_int(tv_json_get(doc, "shards"), &p->shards) &&
           p->shards >= 1 && p->shard >= 0 && p->shard < p->shards &&
           get_double(tv_json_get(doc, "wall_s"), &p->wall_s) && get_pair(tv_json_get(doc, "sample_res"), p->res) &&
           get_pair(tv_json_get(doc, "pvs_res"), p->pvs_res) && get_int(tv_json_get(doc, "samples"), &p->samples) &&
           get_double(tv_json_get(doc, "fov_deg"), &fov) && get_double(tv_json_get(doc, "fov_pvs_deg"), &fov_pvs);
    p->fov = ok ? (float)fov : 0.0f;
    p->fov_pvs = ok ? (float)fov_pvs : 0.0f;
    return ok;
}

static bool same_fields(const tv_json* names)
{
    if (!names || names->type != TV_JSON_ARRAY || names->count != FIELD_COUNT)
        return false;
    for (int k = 0; k < FIELD_COUNT; k++)
        if (names->items[k].type != TV_JSON_STRING || strcmp(names->items[k].str, k_fields[k].name) != 0)
            return false;
    return true;
}

bool tv_bench_part_read(const char* file, tv_bench_part* p, char* err, size_t err_size)
{
    memset(p, 0, sizeof *p);
    FILE* f = fopen(file, "rb");
    if (!f) {
        snprintf(err, err_size, "%s: cannot open", file);
        return false;
    }
    char* text = NULL;
    size_t len = 0, cap = 0, got;
    do {
        if (len + 65536 > cap) {
            char* grown = realloc(text, cap = 2 * cap + 65536);
            if (!grown)
                break;
            text = grown;
        }
        got = fread(text + len, 1, cap - len, f);
        len += got;
    } while (got > 0);
    bool read_ok = !ferror(f) && text;
    fclose(f);
    tv_json doc;
    if (!read_ok || !tv_json_parse(text, len, file, &doc, err, err_size)) {
        if (!read_ok)
            snprintf(err, err_size, "%s: cannot read", file);
        free(text);
        return false;
    }
    free(text);
    const tv_json* cells = tv_json_get(&doc, "cells");
    bool ok = read_header(&doc, p);
    if (!ok)
        snprintf(err, err_size, "%s: not a trimvr bench part file (%s) or a header value is missing or bad", file,
                 FORMAT);
    else if (!(ok = same_fields(tv_json_get(&doc, "fields"))))
        snprintf(err, err_size, "%s: its field list differs from this trimvr's (written by version %s)", file,
                 p->version);
    else if (!(ok = cells && cells->type == TV_JSON_ARRAY))
        snprintf(err, err_size, "%s: no \"cells\" array", file);
    if (ok && cells->count > 0 && !(p->cells = calloc((size_t)cells->count, sizeof *p->cells))) {
        snprintf(err, err_size, "%s: out of memory", file);
        ok = false;
    }
    for (int i = 0; ok && i < cells->count; i++) {
        ok = read_cell(&cells->items[i], &p->cells[i]);
        if (!ok)
            snprintf(err, err_size, "%s: cell %d: a missing or bad value", file, i);
        p->count += ok;
    }
    tv_json_free(&doc);
    if (!ok)
        tv_bench_part_free(p);
    return ok;
}

void tv_bench_part_free(tv_bench_part* p)
{
    free(p->cells);
    p->cells = NULL;
    p->count = 0;
}
