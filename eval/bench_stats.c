/* Rows of `trimvr bench` from viewcell results: the means of
 * tv_eval_mean, 95 % t-intervals over the viewcells and the worst cell. A
 * serial run and a merge of part files both come through here, so their
 * tables are computed by the same code from the same numbers. */
#include "bench_report.h"

#include "stats.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* More FN pixels per view, then the lower PSNR. */
static bool worse(const tv_eval_cell* a, const tv_eval_cell* b)
{
    if (a->m.fng_pixels_mean != b->m.fng_pixels_mean)
        return a->m.fng_pixels_mean > b->m.fng_pixels_mean;
    return a->m.psnr_mean_db < b->m.psnr_mean_db;
}

static void fill_row(const tv_bench_cell* cells, int k, tv_eval_cell* ec, double* scratch, tv_bench_row* r)
{
    double *fng = scratch, *pvs = scratch + k, *gt = scratch + 2 * k, *ms = scratch + 3 * k;
    int draws = 0;
    for (int i = 0; i < k; i++) {
        ec[i] = cells[i].c;
        fng[i] = ec[i].m.fng_pixels_mean;
        pvs[i] = ec[i].m.pvs_fraction;
        gt[i] = ec[i].m.gt_fraction;
        for (int d = 0; d < 3; d++)
            if (isfinite(cells[i].full_ms[d]))
                ms[draws++] = cells[i].full_ms[d];
    }
    memset(r, 0, sizeof *r);
    memcpy(r->scene, cells[0].scene, sizeof r->scene);
    r->method = cells[0].method;
    r->delta = cells[0].delta;
    r->cells = k;
    r->mean = tv_eval_mean(ec, k);
    r->views = ec[0].st.views;
    r->full_pvsres_ms = draws ? tv_percentile(ms, (size_t)draws, 50.0) : NAN;
    r->fng_ci95 = tv_mean_ci95(fng, (size_t)k);
    r->pvs_over_gt_ci95 = tv_ratio_ci95(pvs, gt, (size_t)k);
    r->psnr_worst_cell_db = INFINITY;
    int w = 0;
    for (int i = 0; i < k; i++) {
        r->fng_fraction_worst_cell = fmax(r->fng_fraction_worst_cell, ec[i].m.fng_fraction_mean);
        r->psnr_worst_cell_db = fmin(r->psnr_worst_cell_db, ec[i].m.psnr_mean_db);
        if (worse(&ec[i], &ec[w]))
            w = i;
    }
    r->worst = ec[w];
    r->worst_index = cells[w].index;
}

int tv_bench_rows(const tv_bench_cell* cells, int n, tv_bench_row** rows)
{
    int groups = 0;
    for (int i = 0; i < n; i++)
        groups += i == 0 || cells[i].row != cells[i - 1].row;
    *rows = calloc((size_t)groups + 1, sizeof **rows);
    tv_eval_cell* ec = malloc(((size_t)n + 1) * sizeof *ec);
    double* scratch = malloc(((size_t)n + 1) * 6 * sizeof *scratch);
    if (!*rows || !ec || !scratch) {
        free(*rows);
        *rows = NULL;
        groups = -1;
    }
    for (int first = 0, g = 0; groups > 0 && first < n; g++) {
        int end = first + 1;
        while (end < n && cells[end].row == cells[first].row)
            end++;
        fill_row(&cells[first], end - first, ec, scratch, &(*rows)[g]);
        first = end;
    }
    free(ec);
    free(scratch);
    return groups;
}
