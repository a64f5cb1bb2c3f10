/* demo_hud.h - the demo's heads-up display and help overlay, drawn into
 * the mirror image with the bitmap font. */
#ifndef TRIMVR_APP_DEMO_HUD_H
#define TRIMVR_APP_DEMO_HUD_H

#include "demo_draw.h"

#include <stdbool.h>
#include <stdint.h>

/* The key list, shown by `trimvr demo --help` and on the help overlay. */
extern const char tv_demo_controls[];

typedef struct tv_hud_info {
    double fps, frame_ms;
    const char* view;       /* "PVS", "FULL" or "FN" (colour) */
    bool overview;          /* the right half shows the Figure 1 overview */
    const char* method;
    const char* head;       /* "path" or "manual" */
    bool viewcell_shown, frozen;
    uint32_t pvs_id;
    double pvs_age_ms, pvs_compute_ms;
    double delta_m, fov_pvs_deg;
    int frusta;              /* of the PVS's viewcell: 1, or 6 for every direction */
    uint32_t pvs_tris, scene_tris;
    bool have_check;
    uint64_t check_frame;
    double psnr_db;         /* of the worse eye */
    uint64_t fn_pixels;     /* both eyes */
    uint32_t movers;        /* the scene's moving objects (0: static scene) */
    uint64_t dynamic_fn_pixels; /* of fn_pixels, those on movers */
    int check_every;
    uint64_t misses, frames;
    double speed;
    bool inside;            /* both eyes covered by the current viewcell */
} tv_hud_info;

/* Lines of status text at the top left, on a translucent panel. */
void tv_hud_draw(const tv_canvas* c, const tv_hud_info* info, int scale);

/* The control list centred on a dark panel. */
void tv_hud_draw_help(const tv_canvas* c, int scale);

#endif
