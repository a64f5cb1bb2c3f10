/* method.c - the method table, defaults, request checks and the helpers the
 * rendering methods share (id-buffer union, cameras). */
#include "method_internal.h"

#include "clock.h"

#include <assert.h>
#include <cglm/cglm.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const struct {
    const char* name;
    const pvs_method_ops* ops;
} _methods[PVS_METHOD_COUNT] = {
    [PVS_METHOD_TR] = {"tr", &pvs_method_tr_ops},
    [PVS_METHOD_GT] = {"gt", &pvs_method_gt_ops},
    [PVS_METHOD_SAS] = {"sas", &pvs_method_sas_ops},
    [PVS_METHOD_FROMPOINT] = {"frompoint", &pvs_method_frompoint_ops},
    [PVS_METHOD_Q3VIS] = {"q3vis", &pvs_method_q3vis_ops},
};

const char* pvs_method_name(pvs_method_kind kind)
{
    return (unsigned)kind < PVS_METHOD_COUNT ? _methods[kind].name : "unknown";
}

bool pvs_method_from_name(const char* name, pvs_method_kind* kind)
{
    for (int k = 0; name && k < PVS_METHOD_COUNT; k++)
        if (strcmp(name, _methods[k].name) == 0) {
            *kind = (pvs_method_kind)k;
            return true;
        }
    return false;
}

static pvs_method_desc _resolve(const pvs_method_desc* in)
{
    pvs_method_desc d = *in;
    if (!d.width || !d.height) {
        d.width = 640;
        d.height = 360;
    }
    if (!d.gt_samples)
        d.gt_samples = 200;
    if (!(d.sas_spacing_m > 0.0f))
        d.sas_spacing_m = 0.05f;
    if (!(d.near_m > 0.0f))
        d.near_m = 0.05f;
    if (!(d.far_m > d.near_m))
        d.far_m = 500.0f;
    /* one resolution option for every method unless tr's is set explicitly */
    if (!d.tr.width || !d.tr.height) {
        d.tr.width = d.width;
        d.tr.height = d.height;
    }
    return d;
}

pvs_method* pvs_method_create(const pvs_method_desc* desc, rnd_context* rnd, const scn_scene* scene,
                              const rnd_gpu_scene* gpu, char* err, size_t err_size)
{
    assert(desc && rnd && scene && gpu);
    if ((unsigned)desc->kind >= PVS_METHOD_COUNT) {
        snprintf(err, err_size, "pvs method: unknown kind %d", (int)desc->kind);
        return NULL;
    }
    pvs_method* m = calloc(1, sizeof *m);
    if (!m) {
        snprintf(err, err_size, "pvs method: out of memory");
        return NULL;
    }
    m->kind = desc->kind;
    m->ops = _methods[desc->kind].ops;
    m->desc = _resolve(desc);
    m->rnd = rnd;
    m->gpu = gpu;
    m->triangle_count = scene->triangle_count;
    m->mask = calloc(scene->triangle_count ? scene->triangle_count : 1, 1);
    bool explain = desc->kind == PVS_METHOD_TR && desc->tr.explain;
    m->reasons = explain ? calloc(scene->triangle_count ? scene->triangle_count : 1, sizeof(uint32_t)) : NULL;
    bool ok = m->mask != NULL && (!explain || m->reasons);
    if (!ok)
        snprintf(err, err_size, "pvs method: out of memory");
    if (ok && m->ops->renders) {
        m->pixels = malloc((size_t)m->desc.width * m->desc.height * sizeof(uint32_t));
        m->target = rnd_target_create(rnd, m->desc.width, m->desc.height, err, err_size);
        ok = m->pixels && m->target;
        if (!m->pixels)
            snprintf(err, err_size, "pvs method: out of memory for a %ux%u id buffer", m->desc.width,
                     m->desc.height);
    }
    ok = ok && (!m->ops->create || m->ops->create(m, scene, err, err_size));
    m->desc.q3vis_file = NULL; /* the caller's string need not outlive the call */
    if (!ok) {
        pvs_method_destroy(m);
        return NULL;
    }
    return m;
}

void pvs_method_destroy(pvs_method* m)
{
    if (!m)
        return;
    if (m->impl && m->ops->destroy)
        m->ops->destroy(m);
    if (m->target)
        rnd_target_destroy(m->rnd, m->target);
    free(m->pixels);
    free(m->mask);
    free(m->reasons);
    free(m);
}

const uint32_t* pvs_method_reasons(const pvs_method* m)
{
    return m->reasons;
}

pvs_method_kind pvs_method_kind_of(const pvs_method* m)
{
    assert(m);
    return m->kind;
}

static bool _check_request(const pvs_method* m, const pvs_request* req, char* err, size_t err_size)
{
    const pred_viewcell* vc = &req->vc;
    const char* name = pvs_method_name(m->kind);
    pvs_viewcell checked;
    char why[256];
    if (!pvs_viewcell_from_pred(vc, m->desc.far_m, &checked, why, sizeof why)) {
        snprintf(err, err_size, "%s: %s", name, why);
        return false;
    }
    float eye = req->eye_fov_h_deg > 0.0f ? req->eye_fov_h_deg : vc->fov_target_deg;
    if (!(eye > 0.0f && eye < 180.0f)) {
        snprintf(err, err_size, "%s: eye fov %g deg outside (0, 180)", name, eye);
        return false;
    }
    return true;
}

/* A whole-scene viewcell (its apex beyond what a PVS resolves): every
 * triangle, no method call. */
static bool _whole_scene(const pvs_method* m, uint32_t** ids, uint32_t* count, pvs_method_stats* stats, char* err,
                         size_t err_size)
{
    double t0 = tv_now_ms();
    uint32_t* list = malloc((m->triangle_count ? m->triangle_count : 1) * sizeof *list);
    if (!list) {
        snprintf(err, err_size, "%s: out of memory for the whole scene's %u ids", pvs_method_name(m->kind),
                 m->triangle_count);
        return false;
    }
    for (uint32_t t = 0; t < m->triangle_count; t++)
        list[t] = t;
    *ids = list;
    *count = m->triangle_count;
    if (stats)
        *stats = (pvs_method_stats){.total_ms = tv_now_ms() - t0};
    return true;
}

uint32_t pvs_method_proxies(const scn_scene* scene, double t0, double t1, pvs_proxy* out)
{
    for (uint32_t i = 0; i < scene->mover_count; i++) {
        scn_mover_bounds(scene, i, t0, t1, out[i].box_min, out[i].box_max);
        out[i].first_id = scene->movers[i].first_triangle;
        out[i].id_count = scene->movers[i].triangle_count;
    }
    return scene->mover_count;
}

bool pvs_method_compute(pvs_method* m, const pvs_request* in, uint32_t** ids, uint32_t* count,
                        pvs_method_stats* stats, char* err, size_t err_size)
{
    assert(m && in && ids && count);
    *ids = NULL;
    *count = 0;
    if (in->vc.whole_scene)
        return _whole_scene(m, ids, count, stats, err, err_size);
    if (in->vc.frusta > 1)
        return pvs_method_compute_frusta(m, in, ids, count, stats, err, err_size);
    double t0 = tv_now_ms();
    pvs_method_stats st = {.frusta = 1};
    if (!_check_request(m, in, err, err_size))
        return false;
    pvs_request req = *in;
    if (!(req.eye_fov_h_deg > 0.0f))
        req.eye_fov_h_deg = req.vc.fov_target_deg;
    memset(m->mask, 0, m->triangle_count);
    if (m->reasons && !m->joining)
        memset(m->reasons, 0, sizeof(uint32_t) * m->triangle_count);
    uint32_t* list = NULL;
    uint32_t n = 0;
    if (!m->ops->compute(m, &req, &list, &n, &st, err, err_size))
        return false;
    if (m->kind != PVS_METHOD_TR && req.proxy_count) { /* only tr sorts movers in: the rest take them all */
        for (uint32_t i = 0; list && i < n; i++)
            m->mask[list[i]] = 1;
        for (uint32_t i = 0; i < req.proxy_count; i++)
            memset(m->mask + req.proxies[i].first_id, 1, req.proxies[i].id_count);
        free(list);
        list = NULL;
        n = 0;
    }
    if (!list) {
        for (uint32_t t = 0; t < m->triangle_count; t++)
            n += m->mask[t];
        list = malloc((n ? n : 1) * sizeof(uint32_t));
        if (!list) {
            snprintf(err, err_size, "%s: out of memory for %u ids", pvs_method_name(m->kind), n);
            return false;
        }
        n = 0;
        for (uint32_t t = 0; t < m->triangle_count; t++)
            if (m->mask[t])
                list[n++] = t;
    }
    *ids = list;
    *count = n;
    st.total_ms = tv_now_ms() - t0;
    if (stats)
        *stats = st;
    return true;
}

bool pvs_method_mark_view(pvs_method* m, const rnd_camera* cam, char* err, size_t err_size)
{
    if (!rnd_draw(m->rnd, m->target, m->gpu, cam, NULL, 0, NULL) ||
        !rnd_target_read_ids(m->rnd, m->target, m->pixels)) {
        snprintf(err, err_size, "%s: id render failed (Vulkan error logged)", pvs_method_name(m->kind));
        return false;
    }
    size_t pixels = (size_t)m->desc.width * m->desc.height;
    for (size_t i = 0; i < pixels; i++)
        if (m->pixels[i] < m->triangle_count)
            m->mask[m->pixels[i]] = 1;
    return true;
}

rnd_camera pvs_method_camera(const pvs_method* m, const float pos[3], const float forward[3], const float up[3],
                             float fov_y_deg)
{
    vec3 f = {forward[0], forward[1], forward[2]}, u = {up[0], up[1], up[2]};
    versor q;
    glm_quat_for(f, u, q);
    rnd_camera cam = {.position = {pos[0], pos[1], pos[2]}, .orientation = {q[0], q[1], q[2], q[3]},
                      .fov_y_deg = fov_y_deg, .near_m = m->desc.near_m, .far_m = m->desc.far_m};
    return cam;
}

float pvs_method_fov_y(const pvs_method* m, float fov_deg)
{
    float aspect = (float)m->desc.width / (float)m->desc.height;
    return aspect >= 1.0f ? fov_deg : rnd_fov_y_from_x(fov_deg, aspect);
}
