/* replay_plots.h - the replay's pictures: plots of frames.csv over time
 * (gnuplot, PNG) and the worst-PSNR frame as PVS render, full render and a
 * difference heat map. */
#ifndef TRIMVR_APP_REPLAY_PLOTS_H
#define TRIMVR_APP_REPLAY_PLOTS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* The worst frame seen so far (lowest PSNR), kept as copies of its images. */
typedef struct tv_worst_frame {
    unsigned width, height;
    bool have;
    double psnr_db;
    uint64_t frame;
    int eye;
    uint8_t *full, *pvs; /* RGBA8 */
    uint8_t* fn;         /* 1 where the pixel's full-render triangle is not in the PVS */
} tv_worst_frame;

bool tv_worst_frame_init(tv_worst_frame* w, unsigned width, unsigned height);
void tv_worst_frame_free(tv_worst_frame* w);

/* Keeps the images if psnr_db is lower than the worst so far (ties keep the
 * earlier frame). tri_in_set is the PVS mask indexed by triangle id. */
void tv_worst_frame_offer(tv_worst_frame* w, double psnr_db, uint64_t frame, int eye, const uint8_t* full,
                          const uint8_t* pvs, const uint32_t* full_ids, const uint8_t* tri_in_set,
                          uint32_t triangle_count);

/* Writes DIR/worst_full.png, worst_pvs.png and worst_diff.png (grey image,
 * differing pixels coloured by magnitude from yellow to red, false-negative
 * pixels pure red). Nothing is written when no frame was offered. */
bool tv_worst_frame_write(const tv_worst_frame* w, const char* dir, char* err, size_t err_size);

/* Removes what an earlier replay wrote into DIR (frames.csv, summary.json,
 * plots, worst-frame images), so that a run never leaves its outputs mixed
 * with an older run's. */
void tv_replay_remove_outputs(const char* dir);

/* Plots DIR/frames.csv into DIR/plot_*.png with gnuplot. A missing gnuplot is
 * reported as a warning, not a failure: the log and summary are the results. */
void tv_replay_plots(const char* dir);

#endif
