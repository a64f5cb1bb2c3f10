#include "bench_report.h"

#include "gnuplot.h"

#include "log.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The numeric columns of bench.csv after scene and method, in order; the
 * plots address them by position, so they are looked up here by name. */
static const char* const k_cols[] = {
    "delta_m", "cells", "scene_tris", "pvs_tris", "gt_tris", "pvs_fraction", "gt_fraction", "pvs_over_gt_tris",
    "fp_rate", "fn_rate", "fp_rate_reliable", "fn_rate_reliable", "fng_pixels_mean", "fng_pixels_max",
    "fng_fraction", "fng_reliable_pixels_mean", "psnr_mean_db", "psnr_min_db", "pvs_ms", "gt_ms",
    "full_render_ms", "full_render_pvsres_ms", "pvs_over_full", "pvs_over_gt_ms", "p0_ms", "p1_ms", "p2_ms",
    "p3_ms", "p4_ms", "layers", "active_pixels", "mean_trim_sequence", "kbuffer_alloc_bytes",
    "kbuffer_used_bytes", "overflow_pixels", "views", "fng_fraction_worst_cell", "psnr_worst_cell_db",
    "gt_completeness", "gt_est_tris", "pvs_over_gt_est_tris", "ssim_mean", "ssim_min",
    "fng_pixels_ci95", "pvs_over_gt_ci95", "worst_cell", "fng_pixels_worst_cell", "overflow_share",
    "loop_budget_pixels"};
enum { COL_COUNT = (int)(sizeof k_cols / sizeof k_cols[0]) };

static double ratio(double a, double b)
{
    return b > 0.0 ? a / b : NAN;
}

static void row_values(const tv_bench_row* r, double* v)
{
    const pvs_eval_result* m = &r->mean.m;
    const pvs_stats* tr = &r->mean.st.tr;
    double x[COL_COUNT] = {
        r->delta, r->cells, m->scene_tris, m->pvs_tris, m->gt_tris, m->pvs_fraction, m->gt_fraction,
        ratio(m->pvs_fraction, m->gt_fraction), m->fp_rate, m->fn_rate, m->fp_rate_reliable, m->fn_rate_reliable,
        m->fng_pixels_mean, m->fng_pixels_max, m->fng_fraction_mean, m->fng_reliable_pixels_mean, m->psnr_mean_db,
        m->psnr_min_db, r->mean.pvs_ms, m->gt_ms, m->full_render_ms, r->full_pvsres_ms,
        ratio(r->mean.pvs_ms, r->full_pvsres_ms), ratio(r->mean.pvs_ms, m->gt_ms), tr->ms[0], tr->ms[1], tr->ms[2],
        tr->ms[3], tr->ms[4], tr->layers, (double)tr->active_pixels, tr->mean_sequence, (double)tr->kbuffer_bytes,
        (double)tr->kbuffer_bytes_used, (double)tr->overflow_pixels, r->views, r->fng_fraction_worst_cell,
        r->psnr_worst_cell_db, m->gt_completeness, m->gt_est_tris, ratio(m->pvs_tris, m->gt_est_tris), m->ssim_mean,
        m->ssim_min, r->fng_ci95, r->pvs_over_gt_ci95, r->worst_index, r->worst.m.fng_pixels_mean,
        r->mean.overflow_share, (double)tr->loop_budget_pixels};
    memcpy(v, x, sizeof x);
}

static int col(const char* name)
{
    for (int i = 0; i < COL_COUNT; i++)
        if (strcmp(k_cols[i], name) == 0)
            return i + 3; /* 1-based, after scene and method */
    abort(); /* a name below that is not in k_cols is a programming error */
}

static FILE* open_out(const char* dir, const char* name, char* path, size_t path_size, char* err, size_t err_size)
{
    snprintf(path, path_size, "%s/%s", dir, name);
    FILE* f = fopen(path, "w");
    if (!f)
        snprintf(err, err_size, "%s: cannot write", path);
    return f;
}

static bool close_out(FILE* f, const char* path, char* err, size_t err_size)
{
    if (fclose(f) == 0)
        return true;
    snprintf(err, err_size, "%s: write failed", path);
    return false;
}

static bool write_csv(const char* dir, const tv_bench_row* rows, int n, char* err, size_t err_size)
{
    char path[4200];
    FILE* f = open_out(dir, "bench.csv", path, sizeof path, err, err_size);
    if (!f)
        return false;
    fprintf(f, "scene,method");
    for (int c = 0; c < COL_COUNT; c++)
        fprintf(f, ",%s", k_cols[c]);
    fprintf(f, "\n");
    for (int i = 0; i < n; i++) {
        double v[COL_COUNT];
        row_values(&rows[i], v);
        fprintf(f, "%s,%s", rows[i].scene, pvs_method_name(rows[i].method));
        for (int c = 0; c < COL_COUNT; c++)
            /* "inf": identical images; empty: not a number (no denominator) */
            fprintf(f, isfinite(v[c]) ? ",%.6g" : isinf(v[c]) ? ",inf" : ",", v[c]);
        fprintf(f, "\n");
    }
    return close_out(f, path, err, err_size);
}

static bool write_json(const char* dir, const tv_bench_info* in, const tv_bench_row* rows, int n, char* err,
                       size_t err_size)
{
    char path[4200];
    FILE* f = open_out(dir, "bench.json", path, sizeof path, err, err_size);
    if (!f)
        return false;
    fprintf(f, "{\n  \"command\": \"");
    for (const char* c = in->command_line; *c; c++)
        fprintf(f, *c == '"' || *c == '\\' ? "\\%c" : "%c", *c);
    fprintf(f, "\",\n  \"date\": \"%s\", \"device\": \"%s\", \"version\": \"%s\", \"wall_s\": %.1f,\n", in->date,
            in->device, in->version, in->wall_s);
    if (in->merged)
        fprintf(f, "  \"merged\": \"%s\",\n", in->merged);
    if (in->stopped)
        fprintf(f, "  \"interrupted\": true, \"stopped\": \"%s\",\n", in->stopped);
    fprintf(f, "  \"ci\": \"95 %% t-intervals over viewcells: fng_pixels_ci95 of the mean, pvs_over_gt_ci95 of the "
               "ratio of means by linearisation\",\n");
    fprintf(f, "  \"sample_res\": [%u, %u], \"pvs_res\": [%u, %u], \"samples\": %d, \"fov_deg\": %.2f, "
               "\"fov_pvs_deg\": %.2f,\n  \"rows\": [\n",
            in->res[0], in->res[1], in->pvs_res[0], in->pvs_res[1], in->samples, in->fov, in->fov_pvs);
    for (int i = 0; i < n; i++) {
        const tv_bench_row* r = &rows[i];
        fprintf(f, "    {\"scene\": \"%s\", \"method\": \"%s\", \"delta_m\": %.4f, \"cells\": %d, \"views\": %u,\n     ",
                r->scene, pvs_method_name(r->method), r->delta, r->cells, r->views);
        tv_json_num(f, "full_render_pvsres_ms", r->full_pvsres_ms, ", ");
        tv_json_num(f, "pvs_over_full", ratio(r->mean.pvs_ms, r->full_pvsres_ms), ", ");
        tv_json_num(f, "pvs_over_gt_ms", ratio(r->mean.pvs_ms, r->mean.m.gt_ms), ", ");
        tv_json_num(f, "pvs_over_gt_tris", ratio(r->mean.m.pvs_fraction, r->mean.m.gt_fraction), ", ");
        tv_json_num(f, "fng_fraction_worst_cell", r->fng_fraction_worst_cell, ", ");
        tv_json_num(f, "psnr_worst_cell_db", r->psnr_worst_cell_db, ",\n     ");
        tv_json_num(f, "fng_pixels_ci95", r->fng_ci95, ", ");
        tv_json_num(f, "pvs_over_gt_ci95", r->pvs_over_gt_ci95, ", ");
        fprintf(f, "\"worst_cell\": %d, ", r->worst_index);
        tv_json_num(f, "fng_pixels_worst_cell", r->worst.m.fng_pixels_mean, ",\n");
        tv_eval_json_metrics(f, &r->mean, "     ");
        fprintf(f, "}%s\n", i + 1 < n ? "," : "");
    }
    fprintf(f, "  ]\n}\n");
    return close_out(f, path, err, err_size);
}

/* "v ± ci" with `digits` decimals; just v when there is no interval (one viewcell). */
static const char* plus_minus(char* buf, size_t size, double v, double ci, int digits)
{
    if (isfinite(ci))
        snprintf(buf, size, "%.*f ± %.*f", digits, v, digits, ci);
    else
        snprintf(buf, size, "%.*f", digits, v);
    return buf;
}

/* Per method, the viewcell with the most FN pixels over every Δ (ties: the
 * lower PSNR), where to find it, and what it scored. */
static void md_worst_cells(FILE* f, const tv_bench_row* rows, int first, int end)
{
    fprintf(f, "\nWorst viewcell per method (most FN pixels per view over all Δ):\n\n"
               "| method | Δ cm | cell | centre | looking | FNG px | FNG %% | PSNR dB | SSIM |\n"
               "|---|---:|---:|---|---|---:|---:|---:|---:|\n");
    bool done[PVS_METHOD_COUNT] = {false};
    for (int i = first; i < end; i++) {
        if (done[rows[i].method])
            continue;
        done[rows[i].method] = true;
        const tv_bench_row* w = &rows[i];
        for (int j = i + 1; j < end; j++) {
            const pvs_eval_result *x = &rows[j].worst.m, *y = &w->worst.m;
            if (rows[j].method == w->method &&
                (x->fng_pixels_mean > y->fng_pixels_mean ||
                 (x->fng_pixels_mean == y->fng_pixels_mean && x->psnr_mean_db < y->psnr_mean_db)))
                w = &rows[j];
        }
        const tv_eval_cell* c = &w->worst;
        fprintf(f, "| %s | %.0f | %d | %.2f,%.2f,%.2f | %.2f,%.2f,%.2f | %.1f | %.4f | %.1f | %.4f |\n",
                pvs_method_name(w->method), 100.0 * w->delta, w->worst_index, c->vc.v0[0], c->vc.v0[1], c->vc.v0[2],
                c->vc.forward[0], c->vc.forward[1], c->vc.forward[2], c->m.fng_pixels_mean,
                100.0 * c->m.fng_fraction_mean, c->m.psnr_mean_db, c->m.ssim_mean);
    }
}

static void md_tables(FILE* f, const tv_bench_row* rows, int first, int end)
{
    fprintf(f, "\n### %s (%u triangles, %d viewcells)\n\n", rows[first].scene, rows[first].mean.m.scene_tris,
            rows[first].cells);
    fprintf(f, "| method | Δ cm | PVS %% | GT %% | PVS/GT ± 95%% | GT compl. | PVS/GT est | FP | FN | FP* | FN* | "
               "FNG px ± 95%% | FNG %% | PSNR dB | PSNR min | SSIM | SSIM min | PVS ms | GT ms | full ms | PVS/full | "
               "PVS/GT ms |\n");
    fprintf(f, "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:"
               "|---:|---:|---:|\n");
    bool any_tr = false;
    for (int i = first; i < end; i++) {
        const tv_bench_row* r = &rows[i];
        const pvs_eval_result* m = &r->mean.m;
        char ratio_ci[64], fng_ci[64];
        any_tr = any_tr || r->method == PVS_METHOD_TR;
        fprintf(f,
                "| %s | %.0f | %.2f | %.2f | %s | %.2f | %.2f | %.3f | %.4f | %.3f | %.4f | %s | %.4f | %.1f | "
                "%.1f | %.4f | %.4f | %.0f | %.0f | %.1f | %.1f | %.2f |\n",
                pvs_method_name(r->method), 100.0 * r->delta, 100.0 * m->pvs_fraction, 100.0 * m->gt_fraction,
                plus_minus(ratio_ci, sizeof ratio_ci, ratio(m->pvs_fraction, m->gt_fraction), r->pvs_over_gt_ci95, 2),
                m->gt_completeness, ratio(m->pvs_tris, m->gt_est_tris), m->fp_rate, m->fn_rate, m->fp_rate_reliable,
                m->fn_rate_reliable, plus_minus(fng_ci, sizeof fng_ci, m->fng_pixels_mean, r->fng_ci95, 2),
                100.0 * m->fng_fraction_mean, m->psnr_mean_db, m->psnr_min_db, m->ssim_mean, m->ssim_min,
                r->mean.pvs_ms, m->gt_ms, r->full_pvsres_ms, ratio(r->mean.pvs_ms, r->full_pvsres_ms),
                ratio(r->mean.pvs_ms, m->gt_ms));
    }
    md_worst_cells(f, rows, first, end);
    if (!any_tr)
        return;
    fprintf(f, "\ntr per phase (ms, means over viewcells), layers, resolves and k-buffers:\n\n"
               "| Δ cm | P0 | P1 | P2 | P3 | P4 | layers | active px | trim seq | k-buf MB | used MB | overflow px | "
               "overflow / active |\n"
               "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int i = first; i < end; i++) {
        const pvs_stats* t = &rows[i].mean.st.tr;
        if (rows[i].method != PVS_METHOD_TR)
            continue;
        fprintf(f, "| %.0f | %.1f | %.1f | %.1f | %.1f | %.1f | %u | %llu | %.2f | %.1f | %.1f | %llu | %.2f %% |\n",
                100.0 * rows[i].delta, t->ms[0], t->ms[1], t->ms[2], t->ms[3], t->ms[4], t->layers,
                (unsigned long long)t->active_pixels, t->mean_sequence, t->kbuffer_bytes / 1048576.0,
                t->kbuffer_bytes_used / 1048576.0, (unsigned long long)t->overflow_pixels,
                100.0 * rows[i].mean.overflow_share);
    }
}

static bool write_md(const char* dir, const tv_bench_info* in, const tv_bench_row* rows, int n, char* err,
                     size_t err_size)
{
    char path[4200];
    FILE* f = open_out(dir, "bench.md", path, sizeof path, err, err_size);
    if (!f)
        return false;
    fprintf(f, "# trimvr bench\n\n```\n%s\n```\n\n%s", in->command_line, in->merged ? in->merged : "one run");
    fprintf(f, ", trimvr %s, %s on %s, %.0f s. Ground truth: %d views per viewcell at %ux%u "
               "(eye FOV %.0f°); PVS resolution %ux%u, PVS FOV %.0f°.\n",
            in->version, in->date, in->device, in->wall_s, in->samples, in->res[0], in->res[1], in->fov,
            in->pvs_res[0], in->pvs_res[1], in->fov_pvs);
    if (in->stopped)
        fprintf(f, "\n**Incomplete: %s.** The rows are those completed before it.\n", in->stopped);
    fprintf(f, "\nColumns: PVS/GT = PVS size over ground-truth size; GT compl. = GT size over its Chao2 estimate "
               "from the triangles seen in one and in two views (how complete the sampled GT is), PVS/GT est = "
               "PVS size over that estimate; FP, FN = false-positive and false-negative "
               "rates over the GT size, * without unreliable triangles; FNG = false-negative pixels per GT view "
               "(mean); ± 95 %% = half-width of the 95 %% t-interval over the viewcells (FNG: of the mean; "
               "PVS/GT: of the ratio of means, by linearisation; docs/bench.md); PSNR of PVS renders against full "
               "renders (mean of MSE, and worst view); SSIM likewise (mean over views and worst view; Wang et al. "
               "2004 on Rec. 601 luma, docs/evaluation.md); PVS ms = wall "
               "clock of one PVS; GT ms = the id renders of the ground truth; full ms = one full-scene draw at "
               "the PVS resolution and FOV; the ratios are of those times, measured in the same run.\n");
    for (int first = 0; first < n;) {
        int end = first + 1;
        while (end < n && strcmp(rows[end].scene, rows[first].scene) == 0)
            end++;
        md_tables(f, rows, first, end);
        first = end;
    }
    return close_out(f, path, err, err_size);
}

bool tv_bench_write(const char* dir, const tv_bench_info* info, const tv_bench_row* rows, int n, char* err,
                    size_t err_size)
{
    return write_csv(dir, rows, n, err, err_size) && write_json(dir, info, rows, n, err, err_size) &&
           write_md(dir, info, rows, n, err, err_size);
}

/* One gnuplot `plot` clause per method present for the scene: column y
 * against delta in cm, rows filtered by scene and method. */
static void plot_methods(FILE* f, const tv_bench_row* rows, int first, int end, const char* y, const char* extra)
{
    fprintf(f, "plot");
    bool seen[PVS_METHOD_COUNT] = {false};
    const char* sep = " ";
    for (int i = first; i < end; i++) {
        pvs_method_kind k = rows[i].method;
        if (seen[k])
            continue;
        seen[k] = true;
        fprintf(f, "%scsv using (strcol(1) eq '%s' && strcol(2) eq '%s' ? 100 * column(%d) : 1/0):(%s) "
                   "with linespoints lw 2 title '%s'",
                sep, rows[first].scene, pvs_method_name(k), col("delta_m"), y, pvs_method_name(k));
        sep = ", \\\n     ";
    }
    fprintf(f, "%s\n", extra);
}

void tv_bench_plots(const char* dir, const tv_bench_row* rows, int n)
{
    FILE* f = tv_gnuplot_begin(dir, "bench.gp", "trimvr bench");
    if (!f)
        return;
    fprintf(f, "set terminal pngcairo size 700,420 font ',10'\nset datafile separator ','\n"
               "set key outside right\nset grid\nset xlabel 'Δ (cm)'\ncsv = 'bench.csv'\n"
               "pos(x) = x > 0 ? x : 1/0\n");
    for (int first = 0; first < n;) {
        int end = first + 1;
        while (end < n && strcmp(rows[end].scene, rows[first].scene) == 0)
            end++;
        char tag[64];
        snprintf(tag, sizeof tag, "%s", rows[first].scene);
        for (char* c = tag; *c; c++)
            if (*c == ':' || *c == '/')
                *c = '_';
        char y[128], extra[256];
        fprintf(f, "\nset output 'fig14_runtime_%s.png'\nset title '%s: PVS time'\nset logscale y\n"
                   "set ylabel 'ms (wall clock)'\n", tag, rows[first].scene);
        snprintf(y, sizeof y, "pos(column(%d))", col("pvs_ms"));
        snprintf(extra, sizeof extra,
                 ", csv using (strcol(1) eq '%s' && strcol(2) eq '%s' ? 100 * column(%d) : 1/0):(column(%d)) "
                 "with lines dt 2 lc rgb 'black' title 'full render'",
                 rows[first].scene, pvs_method_name(rows[first].method), col("delta_m"), col("full_render_pvsres_ms"));
        plot_methods(f, rows, first, end, y, extra);
        fprintf(f, "\nset output 'fig15_size_%s.png'\nset terminal pngcairo size 1100,420 font ',10'\n"
                   "set multiplot layout 1,2 title '%s'\nunset logscale y\nset title 'PVS size'\n"
                   "set ylabel '%% of scene'\n", tag, rows[first].scene);
        snprintf(y, sizeof y, "100 * column(%d)", col("pvs_fraction"));
        snprintf(extra, sizeof extra,
                 ", csv using (strcol(1) eq '%s' && strcol(2) eq '%s' ? 100 * column(%d) : 1/0):(100 * column(%d)) "
                 "with lines dt 2 lc rgb 'black' title 'ground truth'",
                 rows[first].scene, pvs_method_name(rows[first].method), col("delta_m"), col("gt_fraction"));
        plot_methods(f, rows, first, end, y, extra);
        fprintf(f, "set title 'false-positive rate'\nset ylabel '|PVS \\ GT| / |GT|'\n");
        snprintf(y, sizeof y, "column(%d)", col("fp_rate"));
        plot_methods(f, rows, first, end, y, "");
        fprintf(f, "unset multiplot\nset terminal pngcairo size 700,420 font ',10'\n");
        fprintf(f, "\nset output 'fig16_fng_%s.png'\nset title '%s: false-negative pixels (FNG)'\nset logscale y\n"
                   "set ylabel '%% of the image (0 not drawn)'\n", tag, rows[first].scene);
        snprintf(y, sizeof y, "pos(100 * column(%d))", col("fng_fraction"));
        plot_methods(f, rows, first, end, y, ", 0.005 with lines dt 3 lc rgb 'red' title '0.005 %'");
        fprintf(f, "unset logscale y\nunset title\n");
        first = end;
    }
    tv_gnuplot_finish(f, dir, "bench.gp", "bench.csv, bench.json and bench.md");
}
