#define _POSIX_C_SOURCE 200809L
#include "replay_plots.h"

#include "gnuplot.h"
#include "image_io.h"
#include "log.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

bool tv_worst_frame_init(tv_worst_frame* w, unsigned width, unsigned height)
{
    memset(w, 0, sizeof *w);
    size_t pixels = (size_t)width * height;
    w->width = width;
    w->height = height;
    w->full = malloc(pixels * 4);
    w->pvs = malloc(pixels * 4);
    w->fn = malloc(pixels);
    return w->full && w->pvs && w->fn;
}

void tv_worst_frame_free(tv_worst_frame* w)
{
    free(w->full);
    free(w->pvs);
    free(w->fn);
    memset(w, 0, sizeof *w);
}

void tv_worst_frame_offer(tv_worst_frame* w, double psnr_db, uint64_t frame, int eye, const uint8_t* full,
                          const uint8_t* pvs, const uint32_t* full_ids, const uint8_t* tri_in_set,
                          uint32_t triangle_count)
{
    if (w->have && !(psnr_db < w->psnr_db))
        return;
    size_t pixels = (size_t)w->width * w->height;
    w->have = true;
    w->psnr_db = psnr_db;
    w->frame = frame;
    w->eye = eye;
    memcpy(w->full, full, pixels * 4);
    memcpy(w->pvs, pvs, pixels * 4);
    for (size_t i = 0; i < pixels; i++)
        w->fn[i] = full_ids[i] < triangle_count && !tri_in_set[full_ids[i]];
}

/* Every file a replay writes: the log, the worst frame's images (in this
 * order, which tv_worst_frame_write relies on), the plot script and plots. */
static const char* const k_outputs[] = {
    "frames.csv",    "summary.json",   "worst_full.png",   "worst_pvs.png",      "worst_diff.png",
    "plots.gp",      "plot_psnr.png",  "plot_fn_pixels.png", "plot_pvs_size.png", "plot_delta.png",
    "plot_prediction_error.png", "plot_timings.png", "pvs.csv"};

void tv_replay_remove_outputs(const char* dir)
{
    char name[4200];
    for (size_t i = 0; i < sizeof k_outputs / sizeof k_outputs[0]; i++) {
        snprintf(name, sizeof name, "%s/%s", dir, k_outputs[i]);
        remove(name); /* absent is the usual case */
    }
}

bool tv_worst_frame_write(const tv_worst_frame* w, const char* dir, char* err, size_t err_size)
{
    if (!w->have)
        return true;
    size_t pixels = (size_t)w->width * w->height;
    uint8_t* diff = malloc(pixels * 3);
    if (!diff) {
        snprintf(err, err_size, "out of memory");
        return false;
    }
    for (size_t i = 0; i < pixels; i++) {
        const uint8_t* a = &w->full[4 * i];
        const uint8_t* b = &w->pvs[4 * i];
        int d = 0;
        for (int c = 0; c < 3; c++) {
            int x = abs((int)a[c] - (int)b[c]);
            d = x > d ? x : d;
        }
        uint8_t* o = &diff[3 * i];
        if (w->fn[i]) {
            o[0] = 255, o[1] = 0, o[2] = 0;
        } else if (d > 0) {
            /* yellow for the faintest difference to orange at full scale */
            o[0] = 255, o[1] = (uint8_t)(255 - (d * 155) / 255), o[2] = 0;
        } else {
            uint8_t g = (uint8_t)((a[0] + a[1] + a[2]) / 12 + 32); /* dimmed context */
            o[0] = o[1] = o[2] = g;
        }
    }
    char name[4200];
    bool ok = true;
    const char* const* files = k_outputs + 2;
    const uint8_t* images[3] = {w->full, w->pvs, diff};
    const uint32_t channels[3] = {4, 4, 3};
    for (int k = 0; k < 3 && ok; k++) {
        snprintf(name, sizeof name, "%s/%s", dir, files[k]);
        ok = scn_image_write_png(name, images[k], w->width, w->height, channels[k], err, err_size);
    }
    free(diff);
    if (ok)
        tv_log(TV_LOG_INFO, "worst frame: %llu (%s eye), PSNR %.2f dB -> %s/worst_*.png",
               (unsigned long long)w->frame, w->eye == 0 ? "left" : "right", w->psnr_db, dir);
    return ok;
}

/* Column numbers in frames.csv (1-based, gnuplot's convention); keep in step
 * with the header in replay_log.c. */
enum { COL_T = 2, COL_POSE_AGE = 11, COL_PRED_POS = 19, COL_PRED_ROT = 20, COL_DELTA = 22, COL_FOV = 23,
       COL_INSIDE = 26, COL_PVS_FRACTION = 29, COL_PSNR = 30, COL_FN = 31, COL_PVS_MS = 33,
       COL_RENDER_PVS = 34, COL_RENDER_FULL = 35 };

void tv_replay_plots(const char* dir)
{
    FILE* f = tv_gnuplot_begin(dir, "plots.gp", "trimvr replay");
    if (!f)
        return;
    fprintf(f,
            "set terminal pngcairo size 1000,360 font ',10'\n"
            "set datafile separator ','\n"
            "set key top right\nset grid\nset xlabel 'time (s)'\n"
            "csv = 'frames.csv'\n"
            "set output 'plot_psnr.png'\nset ylabel 'PSNR (dB)'\n"
            "plot csv using %d:(column(%d) > 200 ? 1/0 : column(%d)) skip 1 with points pt 7 ps 0.3 title 'PSNR PVS vs full', "
            "csv using %d:(column(%d) > 200 ? 100 : 1/0) skip 1 with points pt 1 ps 0.5 lc rgb 'grey' title 'identical (drawn at 100 dB)'\n"
            "set output 'plot_fn_pixels.png'\nset ylabel 'pixels'\n"
            "plot csv using %d:%d skip 1 with impulses title 'false-negative pixels', "
            "csv using %d:(column(%d) == 0 ? (valid(%d) ? column(%d) : 0) : 1/0) skip 1 with points pt 6 ps 0.8 lc rgb 'red' "
            "title 'viewcell miss (at 0 when not rendered)'\n"
            "set output 'plot_pvs_size.png'\nset ylabel '%% of scene'\n"
            "plot csv using %d:(100 * column(%d)) skip 1 with steps title 'PVS size'\n"
            "set output 'plot_delta.png'\nset ylabel 'delta (m)'\nset y2label 'PVS FOV (deg)'\nset y2tics\n"
            "plot csv using %d:%d skip 1 with steps title 'delta', csv using %d:%d skip 1 axes x1y2 with steps title 'PVS FOV'\n"
            "set output 'plot_prediction_error.png'\nset ylabel 'position error (m)'\nset y2label 'rotation error (deg)'\n"
            "plot csv using %d:%d skip 1 with lines title 'position', csv using %d:%d skip 1 axes x1y2 with lines title 'rotation'\n"
            "unset y2tics\nunset y2label\n"
            "set output 'plot_timings.png'\nset ylabel 'ms'\n"
            "plot csv using %d:%d skip 1 with steps title 'PVS compute (wall)', csv using %d:%d skip 1 with lines title 'render full', "
            "csv using %d:%d skip 1 with lines title 'render PVS', csv using %d:%d skip 1 with lines title 'pose age'\n",
            COL_T, COL_PSNR, COL_PSNR, COL_T, COL_PSNR, COL_T, COL_FN, COL_T, COL_INSIDE, COL_FN, COL_FN, COL_T, COL_PVS_FRACTION, COL_T, COL_DELTA,
            COL_T, COL_FOV, COL_T, COL_PRED_POS, COL_T, COL_PRED_ROT, COL_T, COL_PVS_MS, COL_T, COL_RENDER_FULL,
            COL_T, COL_RENDER_PVS, COL_T, COL_POSE_AGE);
    tv_gnuplot_finish(f, dir, "plots.gp", "frames.csv and summary.json");
}
