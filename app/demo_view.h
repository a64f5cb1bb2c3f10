/* demo_view.h - what the demo draws per eye: the PVS or the full scene, the
 * false-negative colouring, the periodic check against the full render, and
 * the viewcell outline. Eye images are rendered offscreen with rnd_draw and
 * read back (the HUD and overlays are CPU drawing, see demo_draw.h). */
#ifndef TRIMVR_APP_DEMO_VIEW_H
#define TRIMVR_APP_DEMO_VIEW_H

#include "demo_draw.h"
#include "render.h"
#include "viewcell.h"

#include <stdbool.h>
#include <stdint.h>

typedef enum tv_eye_mode {
    TV_EYE_PVS = 0, /* the PVS only: what a headset using it shows */
    TV_EYE_FULL,    /* every triangle */
    TV_EYE_FN,      /* the full render with false-negative pixels (triangles visible but not in the PVS) red */
} tv_eye_mode;

/* Per-eye offscreen target and read-back buffers. */
typedef struct tv_eye_renderer {
    rnd_target* target;
    uint32_t width, height;
    uint8_t *rgba, *rgba_full;
    uint32_t* ids;
} tv_eye_renderer;

/* The last check: PVS render versus full render of one eye. */
typedef struct tv_eye_check {
    double psnr_db;     /* INFINITY when identical */
    uint64_t fn_pixels; /* pixels whose visible triangle is missing from the PVS */
    uint64_t dynamic_fn_pixels; /* those on moving triangles (ids from first_dynamic on) */
} tv_eye_check;

bool tv_eye_renderer_init(tv_eye_renderer* r, rnd_context* ctx, uint32_t width, uint32_t height, char* err,
                          size_t err_size);
void tv_eye_renderer_free(tv_eye_renderer* r, rnd_context* ctx);

/* Renders one eye in `mode` into r->rgba (width*height RGBA8). pvs_ids and
 * pvs_mask (triangle_count bytes) describe the PVS in use. With `check`,
 * the PVS and the full scene are both rendered and compared into *check
 * whatever the mode. False (logged by render/) on a Vulkan failure. */
bool tv_eye_render(tv_eye_renderer* r, rnd_context* ctx, const rnd_gpu_scene* gpu, const rnd_camera* cam,
                   tv_eye_mode mode, const uint32_t* pvs_ids, uint32_t pvs_count, const uint8_t* pvs_mask,
                   uint32_t triangle_count, uint32_t first_dynamic, bool check, tv_eye_check* out);

/* Marks the triangles of r's last full render (its id buffer, filled by a
 * check or the FN view) in `seen` (triangle_count bytes). */
void tv_mark_seen(const tv_eye_renderer* r, uint8_t* seen, uint32_t triangle_count);

/* The overview in the paper's Figure 1 colours: the full scene from cam
 * (tv_overview_camera) with the triangles the eyes see now (`seen`) shaded,
 * the rest of the PVS blue, everything else grey, into r->rgba. */
bool tv_overview_render(tv_eye_renderer* r, rnd_context* ctx, const rnd_gpu_scene* gpu, const rnd_camera* cam,
                        const uint8_t* seen, const uint8_t* pvs_mask, uint32_t triangle_count);

/* Draws the double cone's outline (base circle, and generators from it to
 * both apexes) as seen by cam into an eye image. */
void tv_draw_viewcell(const tv_canvas* eye, const rnd_camera* cam, const pred_viewcell* vc, const uint8_t rgb[3]);

#endif
