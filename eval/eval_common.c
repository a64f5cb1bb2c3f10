#include "eval_common.h"

#include "cli_viewcell.h"
#include "path.h"
#include "q3vis.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int tv_eval_path_cells(const char* file, int every, int max_cells, float delta, float fov_deg, float fov_pvs_deg,
                       tv_eval_cell** out, char* scene_spec, size_t spec_size, char* err, size_t err_size)
{
    pred_path path;
    if (!pred_path_load(file, &path, err, err_size))
        return -1;
    if (!scene_spec[0])
        snprintf(scene_spec, spec_size, "%s", path.scene);
    /* counted in double: a long path's frames, or frames + a huge --every, passed INT_MAX */
    double frames = floor(pred_path_duration(&path) * 90.0) + 1.0;
    double step = every > 0                              ? every
                  : max_cells > 0 && frames > max_cells ? floor(frames / max_cells) /* spread evenly */
                                                         : 1.0;
    double cells = ceil(frames / step);
    if (max_cells > 0 && cells > max_cells)
        cells = max_cells;
    if (cells > TV_EVAL_MAX_PATH_CELLS) {
        snprintf(err, err_size, "%s: %.0f s gives %.3g viewcells at one every %.0f frames, more than %d; pass "
                 "--max-cells", file, pred_path_duration(&path), cells, step, TV_EVAL_MAX_PATH_CELLS);
        pred_path_free(&path);
        *out = NULL;
        return -1;
    }
    int n = (int)cells;
    *out = calloc((size_t)n, sizeof **out);
    for (int i = 0; *out && i < n; i++) {
        double t = path.poses[0].t + (double)i * step / 90.0;
        pred_pose head, before, after;
        pred_path_sample(&path, t, &head);
        pred_path_sample(&path, t - 0.05, &before);
        pred_path_sample(&path, t + 0.05, &after);
        tv_viewcell_at_pose(&head, delta, fov_deg, fov_pvs_deg, &(*out)[i].vc);
        /* sas gets its best case: a correctly predicted straight line through
         * the whole cell along the direction of travel (the axis when still). */
        double v[3], len = 0.0;
        for (int k = 0; k < 3; k++) {
            v[k] = after.p[k] - before.p[k];
            len += v[k] * v[k];
        }
        len = sqrt(len);
        for (int k = 0; k < 3; k++)
            (*out)[i].motion[k] = 2.0 * delta * (len > 1e-6 ? v[k] / len : (*out)[i].vc.forward[k]);
    }
    pred_path_free(&path);
    if (!*out) {
        snprintf(err, err_size, "%s: out of memory for %d viewcells", file, n);
        return -1;
    }
    return n;
}

/* True when some scene triangle crosses the vertical segment from `from`
 * up by `height` (Möller-Trumbore with the ray fixed to +Y). */
static bool vertical_blocked(const scn_scene* scene, const float from[3], float height)
{
    for (uint32_t t = 0; t < scene->triangle_count; t++) {
        const float* a = &scene->positions[3 * scene->indices[3 * t]];
        const float* b = &scene->positions[3 * scene->indices[3 * t + 1]];
        const float* c = &scene->positions[3 * scene->indices[3 * t + 2]];
        float e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        /* p = dir x e2 with dir = (0, 1, 0) */
        float p[3] = {e2[2], 0.0f, -e2[0]};
        float det = e1[0] * p[0] + e1[2] * p[2];
        if (fabsf(det) < 1e-12f)
            continue;
        float s[3] = {from[0] - a[0], from[1] - a[1], from[2] - a[2]};
        float u = (s[0] * p[0] + s[2] * p[2]) / det;
        if (u < 0.0f || u > 1.0f)
            continue;
        float q[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]};
        float v = q[1] / det, d = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
        if (v >= 0.0f && u + v <= 1.0f && d > 0.0f && d < height)
            return true;
    }
    return false;
}

typedef struct floor_tri {
    float area;
    float centroid[3];
} floor_tri;

static int by_area_desc(const void* a, const void* b)
{
    float x = ((const floor_tri*)a)->area, y = ((const floor_tri*)b)->area;
    return (x < y) - (x > y);
}

int tv_eval_floor_points(const scn_scene* scene, const char* pvs_json, int max_cells, float* pos, float* dir,
                         char* err, size_t err_size)
{
    pvs_q3vis vis;
    if (!pvs_q3vis_load(pvs_json, &vis, err, err_size))
        return -1;
    floor_tri* tris = malloc((scene->triangle_count + 1) * sizeof *tris);
    uint8_t* clusters = malloc(vis.n_clusters + 1);
    if (!tris || !clusters) {
        snprintf(err, err_size, "%s: out of memory for floor points", pvs_json);
        free(tris);
        free(clusters);
        pvs_q3vis_free(&vis);
        return -1;
    }
    uint32_t n = 0;
    for (uint32_t t = 0; t < scene->triangle_count; t++) {
        const float* p[3];
        for (int c = 0; c < 3; c++)
            p[c] = &scene->positions[3 * scene->indices[3 * t + c]];
        float e1[3], e2[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = p[1][k] - p[0][k];
            e2[k] = p[2][k] - p[0][k];
        }
        float nx = e1[1] * e2[2] - e1[2] * e2[1], ny = e1[2] * e2[0] - e1[0] * e2[2], nz = e1[0] * e2[1] - e1[1] * e2[0];
        float len = sqrtf(nx * nx + ny * ny + nz * nz);
        if (!(len > 0.0f) || ny / len < 0.9f)
            continue;
        tris[n].area = 0.5f * len;
        for (int k = 0; k < 3; k++)
            tris[n].centroid[k] = (p[0][k] + p[1][k] + p[2][k]) / 3.0f;
        n++;
    }
    qsort(tris, n, sizeof *tris, by_area_desc);
    float centre[3];
    for (int k = 0; k < 3; k++)
        centre[k] = 0.5f * (scene->bounds_min[k] + scene->bounds_max[k]);
    int kept = 0;
    for (uint32_t i = 0; i < n && kept < max_cells; i++) {
        float eye[3] = {tris[i].centroid[0], tris[i].centroid[1] + 1.4f, tris[i].centroid[2]};
        bool far_enough = true;
        for (int j = 0; j < kept && far_enough; j++) {
            float dx = eye[0] - pos[3 * j], dy = eye[1] - pos[3 * j + 1], dz = eye[2] - pos[3 * j + 2];
            far_enough = dx * dx + dy * dy + dz * dz >= 16.0f;
        }
        /* Rising from a visible floor face without crossing another face
         * keeps the eye (and 0.3 m of head room for the viewcell) in the
         * empty space above it; the cluster test alone is not enough, since
         * leaf boxes of empty leaves also cover solid corners. */
        float start[3] = {tris[i].centroid[0], tris[i].centroid[1] + 0.02f, tris[i].centroid[2]};
        if (!far_enough || pvs_q3vis_clusters_near(&vis, eye, 0.3f, clusters) == 0 ||
            vertical_blocked(scene, start, 1.4f + 0.3f - 0.02f))
            continue;
        float dx = centre[0] - eye[0], dz = centre[2] - eye[2], len = sqrtf(dx * dx + dz * dz);
        memcpy(&pos[3 * kept], eye, sizeof eye);
        dir[3 * kept] = len > 1.0f ? dx / len : 0.0f;
        dir[3 * kept + 1] = 0.0f;
        dir[3 * kept + 2] = len > 1.0f ? dz / len : -1.0f;
        kept++;
    }
    free(tris);
    free(clusters);
    pvs_q3vis_free(&vis);
    return kept;
}

pvs_request tv_eval_request(const tv_eval_cell* c, float eye_fov_deg)
{
    pvs_request req = {.vc = c->vc, .eye_fov_h_deg = eye_fov_deg};
    double f[3], u[3];
    for (int k = 0; k < 3; k++) {
        req.motion[k] = c->motion[k];
        req.current.p[k] = c->vc.v0[k];
        f[k] = c->vc.forward[k];
        u[k] = c->vc.up[k];
    }
    pred_quat_look(f, u, req.current.q);
    return req;
}

static void add_layer(pvs_layer_stats* sum, const pvs_layer_stats* x)
{
    sum->triangles += x->triangles;
    sum->fronts += x->fronts;
    sum->backs += x->backs;
    sum->silhouettes += x->silhouettes;
    sum->active_pixels += x->active_pixels;
    sum->sequence_entries += x->sequence_entries;
    sum->overflow_pixels += x->overflow_pixels;
    sum->kbuffer_bytes_used += x->kbuffer_bytes_used;
    for (int p = 0; p < 3; p++)
        sum->ms[p] += x->ms[p];
}

/* The method's per-layer figures live until its next computation: the cell
 * keeps a copy. */
static void keep_layers(tv_eval_cell* c)
{
    const pvs_stats* t = &c->st.tr;
    memset(c->layers, 0, sizeof c->layers);
    c->layer_count = 0;
    c->layer_cells = 1;
    for (uint32_t l = 0; t->per_layer && l < t->layers; l++) {
        uint32_t i = l < TV_EVAL_MAX_LAYERS ? l : TV_EVAL_MAX_LAYERS - 1;
        add_layer(&c->layers[i], &t->per_layer[l]);
        c->layer_count = i + 1;
    }
    c->st.tr.per_layer = NULL;
}

static double share(uint64_t part, uint64_t whole)
{
    return whole ? (double)part / (double)whole : 0.0;
}

bool tv_eval_cell_run(pvs_method* m, rnd_context* rnd, const scn_scene* scene, const rnd_gpu_scene* gpu,
                      const pvs_eval_desc* ed, float eye_fov_deg, tv_eval_cell* c, uint8_t* mask, uint8_t* gt,
                      char* err, size_t err_size)
{
    pvs_request req = tv_eval_request(c, eye_fov_deg);
    uint32_t* ids = NULL;
    uint32_t count = 0;
    pvs_proxy* proxies = calloc(scene->mover_count ? scene->mover_count : 1, sizeof *proxies);
    if (!proxies) {
        snprintf(err, err_size, "out of memory");
        return false;
    }
    req.proxies = proxies;
    req.proxy_count = pvs_method_proxies(scene, c->vc.t_begin, c->vc.t_end, proxies);
    bool computed = pvs_method_compute(m, &req, &ids, &count, &c->st, err, err_size);
    free(proxies);
    if (!computed)
        return false;
    keep_layers(c);
    c->pvs_ms = c->st.total_ms;
    c->overflow_share = share(c->st.tr.overflow_pixels, c->st.tr.active_pixels);
    memset(mask, 0, scene->triangle_count);
    for (uint32_t t = 0; t < count; t++)
        mask[ids[t]] = 1;
    bool ok = pvs_evaluate(rnd, gpu, scene, &c->vc, mask, ids, count, ed, gt, &c->m, err, err_size);
    free(ids);
    return ok;
}

tv_eval_cell tv_eval_mean(const tv_eval_cell* c, int n)
{
    tv_eval_cell r;
    memset(&r, 0, sizeof r);
    pvs_eval_result* m = &r.m;
    pvs_stats* tr = &r.st.tr;
    double mse = 0.0;
    uint64_t active_sum = 0;
    m->psnr_min_db = INFINITY;
    m->ssim_min = INFINITY;
    for (int i = 0; i < n; i++) {
        const pvs_eval_result* x = &c[i].m;
        const pvs_stats* xt = &c[i].st.tr;
        m->samples = x->samples;
        m->scene_tris = x->scene_tris;
        m->pvs_tris += x->pvs_tris / (uint32_t)n;
        m->gt_tris += x->gt_tris / (uint32_t)n;
        m->pvs_fraction += x->pvs_fraction / n;
        m->gt_fraction += x->gt_fraction / n;
        m->fp_rate += x->fp_rate / n;
        m->fn_rate += x->fn_rate / n;
        m->fp_rate_reliable += x->fp_rate_reliable / n;
        m->fn_rate_reliable += x->fn_rate_reliable / n;
        m->gt_once += x->gt_once / (uint32_t)n;
        m->gt_twice += x->gt_twice / (uint32_t)n;
        m->gt_est_tris += x->gt_est_tris / n;
        m->gt_completeness += x->gt_completeness / n;
        m->fng_pixels_mean += x->fng_pixels_mean / n;
        m->fng_pixels_max = fmax(m->fng_pixels_max, x->fng_pixels_max);
        m->fng_fraction_mean += x->fng_fraction_mean / n;
        m->fng_reliable_pixels_mean += x->fng_reliable_pixels_mean / n;
        m->fng_dynamic_pixels_mean += x->fng_dynamic_pixels_mean / n;
        if (isfinite(x->psnr_mean_db))
            mse += 255.0 * 255.0 / pow(10.0, x->psnr_mean_db / 10.0) / n;
        m->psnr_min_db = fmin(m->psnr_min_db, x->psnr_min_db);
        m->ssim_mean += x->ssim_mean / n;
        m->ssim_min = fmin(m->ssim_min, x->ssim_min);
        m->gt_ms += x->gt_ms / n;
        m->full_render_ms += x->full_render_ms / n;
        m->pvs_render_ms += x->pvs_render_ms / n;
        r.pvs_ms += c[i].pvs_ms / n;
        for (int p = 0; p < 5; p++)
            tr->ms[p] += xt->ms[p] / n;
        tr->kbuffer_bytes = xt->kbuffer_bytes;
        if (xt->kbuffer_bytes_used > tr->kbuffer_bytes_used)
            tr->kbuffer_bytes_used = xt->kbuffer_bytes_used;
        tr->overflow_pixels += xt->overflow_pixels;
        tr->loop_budget_pixels += xt->loop_budget_pixels;
        tr->layers += xt->layers / (uint32_t)n;
        tr->active_pixels += xt->active_pixels / (uint64_t)n;
        active_sum += xt->active_pixels;
        tr->mean_sequence += xt->mean_sequence / n;
        for (uint32_t l = 0; l < c[i].layer_count; l++)
            add_layer(&r.layers[l], &c[i].layers[l]);
        r.layer_count = c[i].layer_count > r.layer_count ? c[i].layer_count : r.layer_count;
        r.layer_cells += c[i].layer_cells;
    }
    m->psnr_mean_db = mse > 0.0 ? 10.0 * log10(255.0 * 255.0 / mse) : INFINITY;
    r.overflow_share = share(tr->overflow_pixels, active_sum);
    return r;
}

void tv_eval_json_metrics(FILE* f, const tv_eval_cell* c, const char* indent)
{
    const pvs_eval_result* m = &c->m;
    const pvs_stats* tr = &c->st.tr;
    fprintf(f, "%s", indent);
    tv_json_num(f, "scene_tris", m->scene_tris, ", ");
    tv_json_num(f, "pvs_tris", m->pvs_tris, ", ");
    tv_json_num(f, "gt_tris", m->gt_tris, ",\n");
    fprintf(f, "%s", indent);
    tv_json_num(f, "pvs_fraction", m->pvs_fraction, ", ");
    tv_json_num(f, "gt_fraction", m->gt_fraction, ", ");
    tv_json_num(f, "fp_rate", m->fp_rate, ", ");
    tv_json_num(f, "fn_rate", m->fn_rate, ",\n");
    fprintf(f, "%s", indent);
    tv_json_num(f, "fp_rate_reliable", m->fp_rate_reliable, ", ");
    tv_json_num(f, "fn_rate_reliable", m->fn_rate_reliable, ",\n");
    fprintf(f, "%s", indent);
    tv_json_num(f, "gt_once", m->gt_once, ", ");
    tv_json_num(f, "gt_twice", m->gt_twice, ", ");
    tv_json_num(f, "gt_est_tris", m->gt_est_tris, ", ");
    tv_json_num(f, "gt_completeness", m->gt_completeness, ",\n");
    fprintf(f, "%s", indent);
    tv_json_num(f, "fng_pixels_mean", m->fng_pixels_mean, ", ");
    tv_json_num(f, "fng_pixels_max", m->fng_pixels_max, ", ");
    tv_json_num(f, "fng_fraction_mean", m->fng_fraction_mean, ", ");
    tv_json_num(f, "fng_reliable_pixels_mean", m->fng_reliable_pixels_mean, ", ");
    tv_json_num(f, "fng_dynamic_pixels_mean", m->fng_dynamic_pixels_mean, ",\n");
    fprintf(f, "%s", indent);
    tv_json_num(f, "psnr_mean_db", m->psnr_mean_db, ", ");
    tv_json_num(f, "psnr_min_db", m->psnr_min_db, ", ");
    tv_json_num(f, "ssim_mean", m->ssim_mean, ", ");
    tv_json_num(f, "ssim_min", m->ssim_min, ",\n");
    fprintf(f, "%s", indent);
    tv_json_num(f, "pvs_ms", c->pvs_ms, ", ");
    tv_json_num(f, "gt_ms", m->gt_ms, ", ");
    tv_json_num(f, "full_render_ms", m->full_render_ms, ", ");
    tv_json_num(f, "pvs_render_ms", m->pvs_render_ms, ",\n");
    fprintf(f, "%s", indent);
    for (int p = 0; p < 5; p++) {
        char key[8];
        snprintf(key, sizeof key, "p%d_ms", p);
        tv_json_num(f, key, tr->ms[p], ", ");
    }
    fprintf(f, "\n%s", indent);
    tv_json_num(f, "kbuffer_alloc_bytes", (double)tr->kbuffer_bytes, ", ");
    tv_json_num(f, "kbuffer_used_bytes", (double)tr->kbuffer_bytes_used, ", ");
    tv_json_num(f, "overflow_pixels", (double)tr->overflow_pixels, ", ");
    tv_json_num(f, "overflow_share", c->overflow_share, ", ");
    tv_json_num(f, "loop_budget_pixels", (double)tr->loop_budget_pixels, ", ");
    tv_json_num(f, "layers", tr->layers, ", ");
    tv_json_num(f, "active_pixels", (double)tr->active_pixels, ", ");
    tv_json_num(f, "mean_trim_sequence", tr->mean_sequence, ",\n");
    /* means per viewcell, a layer a viewcell does not have counting as zero */
    fprintf(f, "%s\"per_layer\": {\"columns\": [\"triangles\", \"fronts\", \"backs\", \"trim_regions\", "
               "\"active_pixels\", \"sequence_entries\", \"overflow_pixels\", \"kbuffer_used_bytes\", \"p1_ms\", "
               "\"p2_ms\", \"p3_ms\"],\n%s  \"rows\": [",
            indent, indent);
    const double n = c->layer_cells > 0 ? c->layer_cells : 1;
    for (uint32_t l = 0; l < c->layer_count; l++) {
        const pvs_layer_stats* p = &c->layers[l];
        fprintf(f, "%s[%.6g, %.6g, %.6g, %.6g, %.6g, %.6g, %.6g, %.6g, %.6g, %.6g, %.6g]", l ? ", " : "",
                p->triangles / n, p->fronts / n, p->backs / n, p->silhouettes / n, (double)p->active_pixels / n,
                (double)p->sequence_entries / n, (double)p->overflow_pixels / n, (double)p->kbuffer_bytes_used / n,
                p->ms[0] / n, p->ms[1] / n, p->ms[2] / n);
    }
    fprintf(f, "]}");
}
