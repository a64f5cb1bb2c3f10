/* demo.h - `trimvr demo`: the replay's loop live, in a window.
 *
 * Both eyes side by side as a headset's mirror window shows them; the head
 * follows a path (looping) or the keyboard and mouse; PVSs are computed
 * asynchronously for predicted viewcells exactly as in replay.h, and each
 * frame latches the newest head pose just before its eyes are rendered.
 * With `frames` set the clock advances by one display period per frame
 * (reproducible: the fixed latency model on that clock), otherwise it is the
 * wall clock. docs/demo.md describes the controls and the HUD. */
#ifndef TRIMVR_APP_DEMO_H
#define TRIMVR_APP_DEMO_H

#include "demo_view.h"
#include "pvs_pipeline.h"

typedef struct tv_demo_desc {
    const char* scene;       /* scene spec; NULL: the path's '# scene:' */
    const char* path;        /* NULL: keyboard and mouse only */
    tv_pvs_pipeline_desc pvs; /* viewcell.display_fov_* and ipd set from the eyes */
    unsigned width, height;  /* per eye */
    float fov_h_deg;         /* per-eye horizontal FOV */
    float ipd_m;
    float near_m, far_m;
    float start[3];          /* without a path: start position ... */
    float start_yaw_deg;     /* ... and heading (0 looks down -Z) */
    bool have_start;         /* false: the scene's bounds centre, 1.7 m above its floor */
    tv_eye_mode mode;        /* initial view */
    bool hud;
    bool overview;           /* start with the Figure 1 overview in the right half */
    bool mailbox;            /* MAILBOX present mode when offered (else FIFO) */
    int check_every;         /* render the full scene too and compare every Nth frame */
    int frames;              /* > 0: run exactly this many frames on the fixed-step clock, then exit */
    double rate_hz;          /* fixed-step clock rate */
    double seconds;          /* > 0 (real clock only): exit after this long, for timing runs */
    const char* screenshot;  /* with frames: PNG of the last presented frame */
} tv_demo_desc;

/* Runs until the window closes (or `frames` frames). Returns the process
 * exit status; errors are printed as one line. */
int tv_demo_run(const tv_demo_desc* desc);

#endif
