#include "hmd.h"

#include <assert.h>
#include <math.h>

static double _def(double v, double def)
{
    return v == 0.0 ? def : v;
}

void hmd_sim_init(hmd_sim* sim, const hmd_desc* desc, const pred_path* path)
{
    assert(sim && desc && path && path->count >= 1);
    hmd_desc d = *desc;
    d.display_rate_hz = _def(d.display_rate_hz, 90.0);
    d.sensor_rate_hz = _def(d.sensor_rate_hz, 1000.0);
    d.ipd_m = _def(d.ipd_m, 0.063);
    d.pos_noise_m = d.noiseless ? 0.0 : _def(d.pos_noise_m, 0.0002);
    d.rot_noise_deg = d.noiseless ? 0.0 : _def(d.rot_noise_deg, 0.02);
    d.jitter_ms = d.noiseless ? 0.0 : _def(d.jitter_ms, 0.05);
    assert(d.display_rate_hz > 0.0 && d.sensor_rate_hz > 0.0);
    sim->desc = d;
    sim->path = path;
    sim->next_index = 0;
    tv_rng_seed(&sim->rng, d.seed, 0x686d64ull);
}

bool hmd_sim_next(hmd_sim* sim, pred_pose* sample)
{
    const hmd_desc* d = &sim->desc;
    double t0 = sim->path->poses[0].t;
    double nominal = t0 + (double)sim->next_index / d->sensor_rate_hz;
    if (nominal > t0 + pred_path_duration(sim->path))
        return false;
    sim->next_index++;
    /* draw every variate even when its sigma is zero: the sequence, and so
     * every other component, stays the same when one noise term is changed */
    double g[7];
    for (int i = 0; i < 7; i++)
        g[i] = tv_rng_gauss(&sim->rng);
    double t = nominal + g[0] * d->jitter_ms * 1e-3;
    pred_path_sample(sim->path, t, sample);
    for (int i = 0; i < 3; i++)
        sample->p[i] += g[1 + i] * d->pos_noise_m;
    double r[3] = {g[4], g[5], g[6]}, dq[4];
    for (int i = 0; i < 3; i++)
        r[i] *= d->rot_noise_deg * PRED_DEG;
    pred_quat_exp(r, dq);
    pred_quat_mul(dq, sample->q, sample->q);
    pred_quat_normalize(sample->q);
    return true;
}

double hmd_display_time(const hmd_sim* sim, uint64_t frame)
{
    return sim->path->poses[0].t + (double)frame / sim->desc.display_rate_hz;
}

uint64_t hmd_display_frame_count(const hmd_sim* sim)
{
    return (uint64_t)floor(pred_path_duration(sim->path) * sim->desc.display_rate_hz + 1e-9) + 1;
}

void hmd_eye_poses(const hmd_sim* sim, const pred_pose* head, pred_pose eyes[2])
{
    pred_eye_poses(head, sim->desc.ipd_m, eyes);
}
