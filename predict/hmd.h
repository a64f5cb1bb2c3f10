/* hmd.h - a simulated head-mounted display: sensor samples from a path.
 *
 * The sensor samples the path at sensor_rate_hz. Sample i is measured at
 * t_i = t0 + i/rate + jitter_i (jitter Gaussian, sigma jitter_ms) and reports
 * that time exactly with a noisy pose: position + N(0, pos_noise_m) per axis,
 * orientation exp(N(0, rot_noise_deg) per axis) * truth. Jitter can reorder
 * samples when it exceeds half a period; pred_history drops those, like a
 * runtime would. The display refreshes at display_rate_hz from t0.
 * Everything random comes from one PCG32 seeded with `seed`. */
#ifndef TRIMVR_HMD_H
#define TRIMVR_HMD_H

#include "path.h"
#include "rng.h"

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Zero means default. Noise defaults are a consumer inside-out tracker after
 * its own filtering (sub-millimetre jitter); set `noiseless` for exact samples. */
typedef struct hmd_desc {
    double display_rate_hz; /* 90 */
    double sensor_rate_hz;  /* 1000 */
    double ipd_m;           /* 0.063 */
    double pos_noise_m;     /* 0.0002 (0.2 mm) per axis */
    double rot_noise_deg;   /* 0.02 per axis */
    double jitter_ms;       /* 0.05 sample-time jitter (sigma) */
    bool noiseless;         /* no noise, no jitter: samples are the path itself */
    uint64_t seed;
} hmd_desc;

typedef struct hmd_sim {
    hmd_desc desc; /* defaults resolved */
    const pred_path* path;
    tv_rng rng;
    uint64_t next_index;
} hmd_sim;

/* Resolves defaults; the path must outlive the simulator and hold >= 1 sample. */
void hmd_sim_init(hmd_sim* sim, const hmd_desc* desc, const pred_path* path);

/* Next sensor sample; false once its nominal time passes the path's end. */
bool hmd_sim_next(hmd_sim* sim, pred_pose* sample);

/* Eye poses of a head pose with the simulator's ipd (see pred_eye_poses). */
void hmd_eye_poses(const hmd_sim* sim, const pred_pose* head, pred_pose eyes[2]);

/* Display refresh `frame` time: t0 + frame / display_rate. */
double hmd_display_time(const hmd_sim* sim, uint64_t frame);

/* Number of display frames whose time lies within the path. */
uint64_t hmd_display_frame_count(const hmd_sim* sim);

#ifdef __cplusplus
}
#endif

#endif
