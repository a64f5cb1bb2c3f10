/* demo.c - the live loop of `trimvr demo` (see demo.h). */
#define _POSIX_C_SOURCE 200809L
#include "demo.h"

#include "app_scene.h"
#include "clock.h"
#include "demo_hud.h"
#include "demo_window.h"
#include "eval_images.h"
#include "image_io.h"
#include "path.h"
#include "swapchain.h"
#include "log.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct demo {
    const tv_demo_desc* d;
    tv_window* win;
    tv_app_scene s;
    rnd_swapchain* sc;
    tv_pvs_pipeline pvs;
    tv_eye_renderer eye;
    pred_path path;
    bool follow; /* the head follows the path (else the keyboard and mouse) */
    tv_head head;
    uint8_t *mirror, *shot;
    uint32_t mirror_w, mirror_h;
    float fov_v_deg;
    /* toggles */
    tv_eye_mode mode;
    bool viewcell, frozen, help, hud, shot_requested, resize;
    bool overview;  /* right half: Figure 1 overview of the head, its PVS and viewcell */
    uint8_t* seen;  /* overview: triangles both eyes' full renders show this frame */
    /* statistics */
    uint64_t frame, misses, check_frame;
    bool inside, have_check;
    tv_eye_check check[2];
    double frame_ms, t_prev, wall0;
    int shots;
} demo;

static bool fixed_clock(const demo* m) { return m->d->frames > 0; }

/* The head at demo time t: the path loops, so a walk can be watched forever. */
static void head_at(const demo* m, double t, pred_pose* out)
{
    if (m->follow) {
        double duration = pred_path_duration(&m->path);
        double u = duration > 0.0 ? fmod(t, duration) : 0.0;
        pred_path_sample(&m->path, m->path.poses[0].t + u, out);
        out->t = t;
    } else {
        tv_head_pose(&m->head, t, out);
    }
}

/* The head as a sensor at this rate: the display loop only knows it once per
 * frame, so the samples in between are interpolated, linear in position,
 * shortest arc in orientation. */
#define DEMO_SENSOR_RATE_HZ 1000.0

static void feed_head(demo* m, const pred_pose* head)
{
    pred_pose last = m->pvs.last;
    int n = (int)((head->t - last.t) * DEMO_SENSOR_RATE_HZ);
    for (int i = 1; i <= n; i++) {
        pred_pose s;
        pred_pose_lerp(&last, head, (double)i / (n + 1), &s);
        s.t = last.t + (head->t - last.t) * i / (n + 1);
        tv_pvs_pipeline_observe(&m->pvs, &s);
    }
    if (head->t > last.t)
        tv_pvs_pipeline_observe(&m->pvs, head);
    tv_pvs_pipeline_track(&m->pvs, head->t);
}

static double now_s(const demo* m) { return (tv_now_ms() - m->wall0) * 1e-3; }

static void start_pose(const demo* m, pred_pose* out)
{
    memset(out, 0, sizeof *out);
    const tv_demo_desc* d = m->d;
    if (m->path.count) {
        *out = m->path.poses[0];
        return;
    }
    const scn_scene* sc = &m->s.scene;
    for (int k = 0; k < 3; k++)
        out->p[k] = d->have_start ? d->start[k] : 0.5 * (sc->bounds_min[k] + sc->bounds_max[k]);
    if (!d->have_start)
        out->p[1] = sc->bounds_min[1] + 1.7;
    pred_quat_from_ypr(d->start_yaw_deg * PRED_DEG, 0.0, 0.0, out->q);
}

static void take_screenshot(demo* m) { m->shot_requested = true; }

/* Key presses; false on quit. */
static bool handle_actions(demo* m)
{
    for (tv_action a; (a = tv_window_next_action(m->win)) != TV_ACTION_NONE;) {
        switch (a) {
        case TV_ACTION_TOGGLE_PVS: m->mode = m->mode == TV_EYE_PVS ? TV_EYE_FULL : TV_EYE_PVS; break;
        case TV_ACTION_CYCLE_COLOUR: m->mode = m->mode == TV_EYE_FN ? TV_EYE_PVS : TV_EYE_FN; break;
        case TV_ACTION_TOGGLE_OVERVIEW: m->overview = !m->overview; break;
        case TV_ACTION_TOGGLE_VIEWCELL: m->viewcell = !m->viewcell; break;
        case TV_ACTION_TOGGLE_FREEZE: m->frozen = !m->frozen; break;
        case TV_ACTION_SCREENSHOT: take_screenshot(m); break;
        case TV_ACTION_TOGGLE_HELP: m->help = !m->help; break;
        case TV_ACTION_TOGGLE_HUD: m->hud = !m->hud; break;
        case TV_ACTION_RESET: tv_head_reset(&m->head); break;
        case TV_ACTION_FOLLOW_PATH: m->follow = m->path.count > 0; break;
        case TV_ACTION_FASTER: tv_head_scale_speed(&m->head, 1.25); break;
        case TV_ACTION_SLOWER: tv_head_scale_speed(&m->head, 0.8); break;
        case TV_ACTION_QUIT: return false;
        case TV_ACTION_NONE: break;
        }
    }
    return true;
}

/* Moves the manual head by the input of the last dt seconds; any movement
 * while following the path takes over from the pose shown. */
static void steer(demo* m, double t, double dt)
{
    tv_head_input in;
    tv_window_head_input(m->win, &in);
    bool moving = in.forward || in.back || in.left || in.right || in.up || in.down || in.look_dx != 0.0 ||
                  in.look_dy != 0.0;
    if (m->follow && moving) {
        pred_pose here;
        head_at(m, t, &here);
        double speed = m->head.speed;
        tv_head_init(&m->head, &here);
        m->head.speed = speed;
        m->follow = false;
    }
    if (!m->follow)
        tv_head_step(&m->head, &in, dt);
}

/* The viewcell outline: yellow while both eyes are inside it, red when not. */
static const uint8_t* viewcell_colour(bool inside)
{
    static const uint8_t yellow[3] = {255, 220, 40}, red[3] = {255, 60, 40};
    return inside ? yellow : red;
}

static void copy_to_mirror(demo* m, int half)
{
    const tv_demo_desc* d = m->d;
    for (uint32_t y = 0; y < d->height; y++)
        memcpy(m->mirror + ((size_t)y * m->mirror_w + (size_t)half * d->width) * 4,
               m->eye.rgba + (size_t)y * d->width * 4, (size_t)d->width * 4);
}

/* Figure 1 seen from behind and above the head (horizontal heading, world
 * up, so looking up or down does not tip the overview). */
static bool render_overview(demo* m, const pred_pose* head, const rnd_gpu_scene* gpu)
{
    const tv_pvs_result* cur = &m->pvs.current.r;
    double f[3], up[3] = {0.0, 1.0, 0.0};
    pred_pose_forward(head->q, f);
    double len = hypot(f[0], f[2]);
    double flat[3] = {len > 1e-6 ? f[0] / len : 0.0, 0.0, len > 1e-6 ? f[2] / len : -1.0};
    rnd_camera cam;
    tv_overview_camera(&m->s.scene, head->p, flat, up, &cam);
    cam.fov_y_deg = m->fov_v_deg;
    if (!tv_overview_render(&m->eye, m->s.ctx, gpu, &cam, m->seen, m->pvs.current.mask, m->s.scene.triangle_count))
        return false;
    tv_canvas c = {m->eye.rgba, (int)m->d->width, (int)m->d->height};
    tv_draw_viewcell(&c, &cam, &cur->vc, viewcell_colour(m->inside));
    copy_to_mirror(m, 1);
    return true;
}

/* Both eyes of the latched head into the mirror image (the right one
 * replaced by the overview when it is on). */
static bool render_eyes(demo* m, const pred_pose* head)
{
    const tv_demo_desc* d = m->d;
    /* the overview's shaded set is what the eyes see now: it needs both full renders every frame */
    bool check = m->overview || m->frame % (uint64_t)d->check_every == 0;
    pred_pose eyes[2];
    pred_eye_poses(head, d->ipd_m, eyes);
    const tv_pvs_result* cur = &m->pvs.current.r;
    uint32_t n = m->s.scene.triangle_count;
    char err[512] = "";
    const rnd_gpu_scene* gpu = tv_app_scene_at(&m->s, head->t, err, sizeof err); /* movers at the head's time */
    if (!gpu) {
        tv_log(TV_LOG_ERROR, "%s", err);
        return false;
    }
    if (m->overview)
        memset(m->seen, 0, n ? n : 1);
    m->inside = true;
    for (int e = 0; e < 2; e++) {
        rnd_camera cam = tv_camera_at_pose(&eyes[e], m->fov_v_deg, m->d->near_m, m->d->far_m);
        if (!tv_eye_render(&m->eye, m->s.ctx, gpu, &cam, m->mode, cur->ids, cur->count, m->pvs.current.mask, n,
                           n - m->s.scene.dynamic_triangle_count, check, &m->check[e]))
            return false;
        bool in = pred_viewcell_contains(&cur->vc, eyes[e].p, eyes[e].q, d->fov_h_deg, m->fov_v_deg, NULL);
        m->inside = m->inside && in;
        if (m->overview)
            tv_mark_seen(&m->eye, m->seen, n);
        if (m->overview && e == 1)
            break;
        tv_canvas eye = {m->eye.rgba, (int)d->width, (int)d->height};
        if (m->viewcell)
            tv_draw_viewcell(&eye, &cam, &cur->vc, viewcell_colour(in));
        copy_to_mirror(m, e);
    }
    if (m->overview && !render_overview(m, head, gpu))
        return false;
    if (check) {
        m->have_check = true;
        m->check_frame = m->frame;
    }
    m->misses += !m->inside;
    return true;
}

static void draw_overlays(demo* m, double t)
{
    tv_canvas c = {m->mirror, (int)m->mirror_w, (int)m->mirror_h};
    int scale = m->mirror_h >= 320 ? 2 : 1;
    const tv_pvs_result* cur = &m->pvs.current.r;
    if (m->hud) {
        tv_hud_info info = {
            .fps = m->frame_ms > 0.0 ? 1e3 / m->frame_ms : 0.0,
            .frame_ms = m->frame_ms,
            .view = m->mode == TV_EYE_PVS ? "PVS" : m->mode == TV_EYE_FULL ? "FULL" : "FN-red",
            .overview = m->overview,
            .method = pvs_method_name(m->d->pvs.method.kind),
            .head = m->follow ? "path" : "manual",
            .viewcell_shown = m->viewcell,
            .frozen = m->frozen,
            .pvs_id = cur->id,
            .pvs_age_ms = (t - cur->t_request) * 1e3,
            .pvs_compute_ms = cur->compute_ms,
            .delta_m = cur->vc.delta,
            .fov_pvs_deg = cur->vc.fov_pvs_deg,
            .frusta = cur->vc.frusta,
            .pvs_tris = cur->count,
            .scene_tris = m->s.scene.triangle_count,
            .have_check = m->have_check,
            .check_frame = m->check_frame,
            .psnr_db = m->check[0].psnr_db < m->check[1].psnr_db ? m->check[0].psnr_db : m->check[1].psnr_db,
            .fn_pixels = m->check[0].fn_pixels + m->check[1].fn_pixels,
            .movers = m->s.scene.mover_count,
            .dynamic_fn_pixels = m->check[0].dynamic_fn_pixels + m->check[1].dynamic_fn_pixels,
            .check_every = m->d->check_every,
            .misses = m->misses,
            .frames = m->frame + 1,
            .speed = m->head.speed,
            .inside = m->inside,
        };
        tv_hud_draw(&c, &info, scale);
    }
    if (m->help)
        tv_hud_draw_help(&c, scale);
}

static bool write_shot(demo* m, const char* file)
{
    uint32_t w, h;
    char err[512];
    rnd_swapchain_extent(m->sc, &w, &h);
    if (!scn_image_write_png(file, m->shot, w, h, 4, err, sizeof err)) {
        tv_log(TV_LOG_ERROR, "%s", err);
        return false;
    }
    printf("trimvr demo: screenshot %s (%ux%u)\n", file, w, h);
    return true;
}

/* Presents the mirror image, rebuilding the swapchain when the window
 * changed; a requested screenshot reads the presented image back. */
static bool present(demo* m, const char* shot_file)
{
    char err[512] = "";
    for (int attempt = 0; attempt < 4; attempt++) {
        int fw, fh;
        tv_window_framebuffer(m->win, &fw, &fh);
        uint32_t sw, sh;
        rnd_swapchain_extent(m->sc, &sw, &sh);
        if (fw <= 0 || fh <= 0)
            return true; /* minimised: nothing to show */
        if (m->resize || (uint32_t)fw != sw || (uint32_t)fh != sh) {
            if (!rnd_swapchain_resize(m->s.ctx, m->sc, (uint32_t)fw, (uint32_t)fh, err, sizeof err))
                break;
            m->resize = false;
            rnd_swapchain_extent(m->sc, &sw, &sh);
        }
        bool shot = shot_file || m->shot_requested;
        if (shot) {
            free(m->shot);
            m->shot = malloc((size_t)sw * sh * 4);
            if (!m->shot) {
                snprintf(err, sizeof err, "out of memory for a screenshot");
                break;
            }
        }
        rnd_present_result r = rnd_swapchain_present(m->s.ctx, m->sc, m->mirror, m->mirror_w, m->mirror_h,
                                                     shot ? m->shot : NULL, err, sizeof err);
        if (r == RND_PRESENT_ERROR)
            break;
        m->resize = r != RND_PRESENT_OK;
        if (r == RND_PRESENT_RECREATE)
            continue;
        if (m->shot_requested) {
            char name[64];
            snprintf(name, sizeof name, "trimvr-shot-%03d.png", m->shots++);
            m->shot_requested = false;
            if (!write_shot(m, name))
                return false;
        }
        return !shot_file || write_shot(m, shot_file);
    }
    tv_log(TV_LOG_ERROR, "presenting frame %llu: %s", (unsigned long long)m->frame,
           err[0] ? err : "the window kept changing size");
    return false;
}

static void update_title(demo* m)
{
    char title[256];
    snprintf(title, sizeof title, "trimvr demo - %s - %.1f fps", m->s.scene.name,
             m->frame_ms > 0.0 ? 1e3 / m->frame_ms : 0.0);
    tv_window_set_title(m->win, title);
}

/* One display frame at demo time t. */
static bool frame(demo* m, double t)
{
    const tv_demo_desc* d = m->d;
    double dt = t - m->t_prev;
    steer(m, t, dt);
    pred_pose head;
    head_at(m, t, &head);
    char err[768] = "";
    double frame_s = fixed_clock(m) ? 1.0 / d->rate_hz : m->frame_ms * 1e-3;
    feed_head(m, &head);
    if (tv_pvs_pipeline_step(&m->pvs, head.t, frame_s, !m->frozen, err, sizeof err) < 0) {
        tv_log(TV_LOG_ERROR, "%s", err);
        return false;
    }
    if (!fixed_clock(m)) { /* late latch: the newest input and clock right before rendering */
        tv_window_poll(m->win);
        double t_latch = now_s(m);
        steer(m, t_latch, t_latch - t);
        head_at(m, t_latch, &head);
    }
    if (!render_eyes(m, &head)) {
        tv_log(TV_LOG_ERROR, "rendering frame %llu failed (Vulkan error logged)",
               (unsigned long long)m->frame);
        return false;
    }
    draw_overlays(m, t);
    bool last = fixed_clock(m) && m->frame + 1 == (uint64_t)d->frames;
    return present(m, last ? d->screenshot : NULL);
}

static bool run(demo* m)
{
    const tv_demo_desc* d = m->d;
    m->wall0 = tv_now_ms();
    double wall_prev = m->wall0;
    for (m->frame = 0; !fixed_clock(m) || m->frame < (uint64_t)d->frames; m->frame++) {
        tv_window_poll(m->win);
        if (tv_window_should_close(m->win) || !handle_actions(m) || (d->seconds > 0.0 && now_s(m) >= d->seconds))
            break;
        int fw, fh;
        tv_window_framebuffer(m->win, &fw, &fh);
        while ((fw <= 0 || fh <= 0) && !tv_window_should_close(m->win)) { /* minimised: sleep on events */
            tv_window_wait(m->win);
            tv_window_framebuffer(m->win, &fw, &fh);
        }
        double t = fixed_clock(m) ? m->frame / d->rate_hz : now_s(m);
        if (!frame(m, t))
            return false;
        m->t_prev = t;
        double wall = tv_now_ms();
        m->frame_ms = m->frame == 0 ? wall - wall_prev : 0.9 * m->frame_ms + 0.1 * (wall - wall_prev);
        wall_prev = wall;
        if (m->frame % 10 == 0)
            update_title(m);
    }
    return true;
}

static bool setup(demo* m, char* err, size_t err_size)
{
    const tv_demo_desc* d = m->d;
    m->mirror_w = 2 * d->width;
    m->mirror_h = d->height;
    m->mirror = calloc((size_t)m->mirror_w * m->mirror_h, 4);
    m->seen = malloc(m->s.scene.triangle_count ? m->s.scene.triangle_count : 1);
    m->win = tv_window_open("trimvr demo", (int)m->mirror_w, (int)m->mirror_h, err, err_size);
    if (!m->mirror || !m->seen) {
        snprintf(err, err_size, "out of memory for the mirror image");
        return false;
    }
    if (!m->win)
        return false;
    int fw, fh;
    tv_window_framebuffer(m->win, &fw, &fh);
    rnd_swapchain_desc sd = {.create_surface = tv_window_create_surface, .user = m->win,
                             .width = fw > 0 ? (uint32_t)fw : m->mirror_w, .height = fh > 0 ? (uint32_t)fh : m->mirror_h,
                             .mailbox = d->mailbox};
    m->sc = rnd_swapchain_create(m->s.ctx, &sd, err, err_size);
    if (!m->sc || !tv_eye_renderer_init(&m->eye, m->s.ctx, d->width, d->height, err, err_size))
        return false;
    pred_pose start;
    start_pose(m, &start);
    tv_head_init(&m->head, &start);
    m->follow = d->path != NULL;
    start.t = 0.0;
    if (!tv_pvs_pipeline_start(&m->pvs, &d->pvs, m->s.ctx, &m->s.scene, m->s.gpu, err, err_size))
        return false;
    /* a resting head: the predictor needs two samples for a velocity */
    pred_pose before = start;
    before.t -= 0.05;
    tv_pvs_pipeline_observe(&m->pvs, &before);
    feed_head(m, &start);
    return tv_pvs_pipeline_first(&m->pvs, start.t, 0.0, err, err_size);
}

static void teardown(demo* m)
{
    tv_pvs_pipeline_stop(&m->pvs);
    tv_eye_renderer_free(&m->eye, m->s.ctx);
    rnd_swapchain_destroy(m->s.ctx, m->sc);
    tv_window_close(m->win);
    free(m->mirror);
    free(m->seen);
    free(m->shot);
}

static void summary(const demo* m, double wall_s)
{
    printf("trimvr demo: %s, %llu frames in %.1f s (%.1f fps at %ux%u per eye on %s), %u PVSs (%s), "
           "viewcell misses %llu, eye FOV %.6f x %.6f deg\n",
           m->s.scene.name, (unsigned long long)m->frame, wall_s, wall_s > 0.0 ? m->frame / wall_s : 0.0,
           m->d->width, m->d->height, rnd_device_name(m->s.ctx), m->pvs.adopted,
           pvs_method_name(m->d->pvs.method.kind), (unsigned long long)m->misses, m->d->fov_h_deg, m->fov_v_deg);
}

/* Without a path, start position or heading the head starts where the scene's
 * bundled walk does (paths/NAME-walk.csv for builtin:NAME or NAME), looking
 * into the scene: its bounds centre may be inside a wall. The walk stays
 * loaded for T (follow the path). */
static void bundled_walk(const char* spec, pred_path* out)
{
    const char* name = strncmp(spec, "builtin:", 8) == 0 ? spec + 8 : spec;
    char rel[256], buf[4096], err[512];
    if (strpbrk(name, "/:.") || snprintf(rel, sizeof rel, "paths/%s-walk.csv", name) >= (int)sizeof rel)
        return;
    const char* file = tv_bundled_file(rel, buf, sizeof buf);
    if (access(file, R_OK) != 0 || !pred_path_load(file, out, err, sizeof err))
        return;
    if (strcmp(out->scene, spec) != 0)
        pred_path_free(out);
}

int tv_demo_run(const tv_demo_desc* d)
{
    char err[768] = "";
    demo m;
    memset(&m, 0, sizeof m);
    m.d = d;
    m.mode = d->mode;
    m.hud = d->hud;
    m.overview = d->overview;
    m.fov_v_deg = rnd_fov_y_from_x(d->fov_h_deg, (float)d->width / (float)d->height);
    if (d->path && !pred_path_load(d->path, &m.path, err, sizeof err)) {
        tv_log(TV_LOG_ERROR, "%s", err);
        return 1;
    }
    const char* spec = d->scene ? d->scene : m.path.scene[0] ? m.path.scene : "builtin:interior";
    if (!d->path && !d->have_start && d->start_yaw_deg == 0.0f)
        bundled_walk(spec, &m.path);
    if (!tv_window_system_init(err, sizeof err)) {
        tv_log(TV_LOG_ERROR, "%s; the demo needs a display: run 'trimvr replay' for the headless "
               "loop, or run it under Xvfb: xvfb-run -a build/trimvr demo ...", err);
        pred_path_free(&m.path);
        return 1;
    }
    uint32_t ext_count = 0;
    const char* const* exts = tv_window_instance_extensions(&ext_count);
    rnd_desc rd = {.instance_extensions = exts, .instance_extension_count = ext_count, .swapchain = true};
    bool ok = exts && tv_app_scene_open_desc(spec, &rd, &m.s);
    if (!exts)
        tv_log(TV_LOG_ERROR, "GLFW lists no Vulkan surface extensions for this display");
    if (ok && !(setup(&m, err, sizeof err) && run(&m))) {
        if (err[0])
            tv_log(TV_LOG_ERROR, "%s", err);
        ok = false;
    }
    if (ok)
        summary(&m, (tv_now_ms() - m.wall0) * 1e-3);
    if (m.s.ctx) {
        teardown(&m);
        ok = tv_app_scene_close(&m.s) && ok;
    }
    tv_window_system_shutdown();
    pred_path_free(&m.path);
    return ok ? 0 : 1;
}
