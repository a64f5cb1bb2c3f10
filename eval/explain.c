#include "explain.h"

#include "eval_images.h"
#include "image_io.h"

#include <stdlib.h>
#include <string.h>

static const struct {
    const char* name;
    uint8_t rgb[3];
} k_rules[TV_REASON_COUNT] = {
    {"P4 visibility buffer", {160, 160, 160}},
    {"P4 dilated visibility buffer", {90, 90, 90}},
    {"P4 open carried run", {255, 255, 255}},
    {"P2 depth tie", {230, 200, 40}},
    {"P2 partial (sub-pixel)", {240, 130, 30}},
    {"P2 sealed pixel", {150, 90, 40}},
    {"P3 front / terminator", {40, 110, 240}},
    {"P3 candidate (sub-pixel)", {60, 200, 220}},
    {"P3 straddled back", {170, 70, 220}},
    {"P3 crack back", {240, 80, 200}},
    {"overflow (P3 policy, spill)", {230, 40, 40}},
};

const char* tv_explain_rule_name(int i)
{
    return i >= 0 && i < TV_REASON_COUNT ? k_rules[i].name : "?";
}

static int first_rule(uint32_t mask)
{
    for (int i = 0; i < TV_REASON_COUNT; i++)
        if (mask & (1u << i))
            return i;
    return -1;
}

bool tv_explain_add(tv_explain* e, const pred_viewcell* vc, const uint32_t* reasons, const uint8_t* pvs,
                    const uint8_t* gt, uint32_t triangle_count)
{
    uint32_t n = 0;
    for (uint32_t t = 0; t < triangle_count; t++) {
        if (!pvs[t] || gt[t])
            continue;
        n++;
        uint32_t r = reasons[t] & ((1u << TV_REASON_COUNT) - 1u);
        e->unexplained += r == 0;
        if (r)
            e->first[first_rule(r)]++;
        for (int i = 0; i < TV_REASON_COUNT; i++) {
            e->any[i] += (r >> i) & 1u;
            e->alone[i] += r == (1u << i);
        }
    }
    e->fp += n;
    if (e->ids && n <= e->count)
        return true;
    uint32_t* ids = realloc(e->ids, sizeof(uint32_t) * (n ? n : 1));
    if (ids)
        e->ids = ids;
    uint32_t* rules = ids ? realloc(e->first_rule, sizeof(uint32_t) * (n ? n : 1)) : NULL;
    if (!rules)
        return false;
    e->first_rule = rules;
    e->vc = *vc;
    e->count = 0;
    for (uint32_t t = 0; t < triangle_count; t++)
        if (pvs[t] && !gt[t]) {
            int r = first_rule(reasons[t]);
            e->ids[e->count] = t;
            e->first_rule[e->count++] = r < 0 ? TV_REASON_COUNT : (uint32_t)r;
        }
    return true;
}

static double share(uint64_t part, uint64_t whole)
{
    return whole ? 100.0 * (double)part / (double)whole : 0.0;
}

void tv_explain_print(FILE* f, const tv_explain* e, const char* scene, float delta_m)
{
    fprintf(f, "\nFalse positives of %s at delta %.2f m by the rule that output them (%llu FP triangles over the "
               "viewcells, %llu with no rule recorded):\n\n",
            scene, delta_m, (unsigned long long)e->fp, (unsigned long long)e->unexplained);
    fprintf(f, "| rule | FP output by it | %% of FP | by it alone | %% of FP | first rule | %% of FP |\n"
               "|---|---:|---:|---:|---:|---:|---:|\n");
    for (int i = 0; i < TV_REASON_COUNT; i++)
        fprintf(f, "| %s | %llu | %.1f | %llu | %.1f | %llu | %.1f |\n", k_rules[i].name,
                (unsigned long long)e->any[i], share(e->any[i], e->fp), (unsigned long long)e->alone[i],
                share(e->alone[i], e->fp), (unsigned long long)e->first[i], share(e->first[i], e->fp));
}

void tv_explain_json(FILE* f, const tv_explain* e, const char* indent)
{
    fprintf(f, "%s\"explain\": {\"fp_triangles\": %llu, \"unexplained\": %llu, \"rules\": [", indent,
            (unsigned long long)e->fp, (unsigned long long)e->unexplained);
    for (int i = 0; i < TV_REASON_COUNT; i++)
        fprintf(f, "%s\n%s  {\"rule\": \"%s\", \"fp\": %llu, \"fp_alone\": %llu, \"fp_first\": %llu}", i ? "," : "",
                indent, k_rules[i].name, (unsigned long long)e->any[i], (unsigned long long)e->alone[i],
                (unsigned long long)e->first[i]);
    fprintf(f, "]}");
}

/* Draws only the kept false positives from cam, each pixel in its rule's
 * colour shaded by the render's own lighting; empty pixels black. */
static bool draw_rules(const tv_explain* e, const uint8_t* rule_of, uint32_t tris, rnd_context* ctx,
                       rnd_target* target, const rnd_gpu_scene* gpu, const rnd_camera* cam, uint8_t* rgba,
                       uint32_t* ids, uint8_t* rgb, const char* file, char* err, size_t err_size)
{
    uint32_t w = rnd_target_width(target), h = rnd_target_height(target);
    if (!rnd_draw(ctx, target, gpu, cam, e->ids, e->count, NULL) || !rnd_target_read_color(ctx, target, rgba) ||
        !rnd_target_read_ids(ctx, target, ids)) {
        snprintf(err, err_size, "%s: rendering failed (Vulkan error logged)", file);
        return false;
    }
    for (size_t p = 0; p < (size_t)w * h; p++) {
        uint32_t rule = ids[p] < tris ? rule_of[ids[p]] : TV_REASON_COUNT;
        float shade = 0.35f + 0.65f * (float)(rgba[4 * p] + rgba[4 * p + 1] + rgba[4 * p + 2]) / 765.0f;
        for (int c = 0; c < 3; c++)
            rgb[3 * p + c] = rule < TV_REASON_COUNT ? (uint8_t)(shade * k_rules[rule].rgb[c]) : 0;
    }
    return scn_image_write_png(file, rgb, w, h, 3, err, err_size);
}

bool tv_explain_write_pictures(const tv_explain* e, rnd_context* ctx, const rnd_gpu_scene* gpu,
                               const scn_scene* scene, uint32_t width, uint32_t height, const char* dir, char* err,
                               size_t err_size)
{
    if (!e->ids)
        return true;
    size_t pixels = (size_t)width * height;
    uint8_t* rgba = malloc(pixels * 4);
    uint8_t* rgb = malloc(pixels * 3);
    uint32_t* ids = malloc(pixels * sizeof *ids);
    uint32_t tris = scene->triangle_count;
    uint8_t* rule_of = malloc(tris ? tris : 1);
    if (rule_of) {
        memset(rule_of, TV_REASON_COUNT, tris);
        for (uint32_t i = 0; i < e->count; i++)
            rule_of[e->ids[i]] = (uint8_t)e->first_rule[i];
    }
    rnd_target* target = rgba && rgb && ids && rule_of ? rnd_target_create(ctx, width, height, err, err_size) : NULL;
    bool ok = target != NULL;
    if (!ok && !err[0])
        snprintf(err, err_size, "out of memory");
    const pred_viewcell* vc = &e->vc;
    double v0[3] = {vc->v0[0], vc->v0[1], vc->v0[2]}, f[3] = {vc->forward[0], vc->forward[1], vc->forward[2]},
           u[3] = {vc->up[0], vc->up[1], vc->up[2]};
    char file[4200];
    rnd_camera cam;
    tv_overview_camera(scene, v0, f, u, &cam);
    snprintf(file, sizeof file, "%s/explain_overview.png", dir);
    ok = ok && draw_rules(e, rule_of, tris, ctx, target, gpu, &cam, rgba, ids, rgb, file, err, err_size);
    tv_viewcell_centre_camera(vc, (float)width / (float)height, &cam);
    snprintf(file, sizeof file, "%s/explain_eye.png", dir);
    ok = ok && draw_rules(e, rule_of, tris, ctx, target, gpu, &cam, rgba, ids, rgb, file, err, err_size);
    if (target)
        rnd_target_destroy(ctx, target);
    free(rgba);
    free(rgb);
    free(ids);
    free(rule_of);
    return ok;
}

void tv_explain_free(tv_explain* e)
{
    free(e->ids);
    free(e->first_rule);
    memset(e, 0, sizeof *e);
}
