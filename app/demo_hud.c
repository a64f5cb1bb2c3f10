/* demo_hud.c - status text and help overlay. */
#include "demo_hud.h"

#include <math.h>
#include <stdio.h>

const char tv_demo_controls[] =
    "W A S D / arrows  move (walking)      mouse drag  look\n"
    "E / Space  up     Q / Ctrl  down      Shift  x4 speed\n"
    "+ / -  speed x1.25 / x0.8             R  reset pose and speed\n"
    "T  follow the path again (movement keys take over)\n"
    "P  render PVS / full scene            C  colour: off / false negatives red\n"
    "V  show the viewcell (double cone)    F  freeze the PVS (no new requests)\n"
    "O  overview: right half from behind and above, Figure 1 colours\n"
    "   (seen now: shaded, rest of the PVS: blue, culled: grey)\n"
    "U  HUD on/off    H / F1  this help    F12  screenshot (PNG)    Esc  quit";

static const uint8_t k_text[3] = {235, 235, 235};
static const uint8_t k_panel[3] = {0, 0, 0};

void tv_hud_draw(const tv_canvas* c, const tv_hud_info* in, int scale)
{
    char check[160];
    char movers[64] = "";
    if (in->movers)
        snprintf(movers, sizeof movers, " (%llu on %u movers)", (unsigned long long)in->dynamic_fn_pixels,
                 in->movers);
    if (in->have_check)
        snprintf(check, sizeof check, "check @%llu (every %d): PSNR %s%.1f dB, FN %llu px%s",
                 (unsigned long long)in->check_frame, in->check_every, isinf(in->psnr_db) ? "inf " : "",
                 isinf(in->psnr_db) ? 0.0 : in->psnr_db, (unsigned long long)in->fn_pixels, movers);
    else
        snprintf(check, sizeof check, "check: none yet (every %d frames)", in->check_every);
    char frusta[48] = "";
    if (in->frusta > 1)
        snprintf(frusta, sizeof frusta, " in %d frusta (all directions)", in->frusta);
    char text[1024];
    snprintf(text, sizeof text,
             "%.1f fps (%.0f ms)  view %s%s  head %s %.1f m/s%s%s\n"
             "PVS #%u (%s): age %.0f ms, compute %.0f ms\n"
             "delta %.3f m  PVS FOV %.1f deg%s  PVS %.1f%% of %u tris\n"
             "%s\n"
             "viewcell misses %llu / %llu frames  now %s\n"
             "H: help",
             in->fps, in->frame_ms, in->view, in->overview ? " + overview" : "", in->head, in->speed, in->frozen ? "  FROZEN" : "",
             in->viewcell_shown ? "  viewcell" : "", in->pvs_id, in->method, in->pvs_age_ms, in->pvs_compute_ms,
             in->delta_m, in->fov_pvs_deg, frusta,
             in->scene_tris ? 100.0 * in->pvs_tris / in->scene_tris : 0.0,
             in->scene_tris, check, (unsigned long long)in->misses, (unsigned long long)in->frames,
             in->inside ? "inside" : "OUTSIDE");
    int w, h, pad = 3 * scale;
    tv_text_size(text, scale, &w, &h);
    tv_draw_panel(c, 0, 0, w + 2 * pad, h + pad, k_panel, 150);
    tv_draw_text(c, pad, pad, scale, text, k_text);
}

void tv_hud_draw_help(const tv_canvas* c, int scale)
{
    int w, h, pad = 6 * scale;
    tv_text_size(tv_demo_controls, scale, &w, &h);
    int x = (c->width - w) / 2, y = (c->height - h) / 2;
    tv_draw_panel(c, x - pad, y - pad, w + 2 * pad, h + 2 * pad, k_panel, 210);
    tv_draw_text(c, x, y, scale, tv_demo_controls, k_text);
}
