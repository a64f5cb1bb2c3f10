/* view.h - the PVS frustum at the viewcell apex v* (paper section 3.4).
 *
 * Every CPU part of the trim-region PVS that projects or culls works in the
 * frame of this view: depth is the distance along `forward` from the apex,
 * image coordinates are normalised (x = right-offset / depth,
 * y = up-offset / depth), so a point on the frustum's top edge has
 * y = tan(fov_y / 2). Pixels follow by multiplying with the focal length in
 * pixels, (height / 2) / tan(fov_y / 2).
 */
#ifndef TRIMVR_PVS_VIEW_H
#define TRIMVR_PVS_VIEW_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pvs_view {
    float apex[3];    /* v* = v0 - (Δ / tan α) · forward */
    float forward[3]; /* need not be unit length */
    float up[3];      /* any vector not parallel to forward */
    float fov_y_deg;  /* full vertical angle, in (0, 180) */
    float aspect;     /* width / height; 0 means 1 (a square frustum) */
    float near_dist;  /* > 0, measured from the apex along forward */
    float far_dist;   /* > near_dist */
} pvs_view;

/* Orthonormal frame of a view: forward, right = forward x up, up = right x
 * forward (right-handed, +Y up when forward = -Z). */
typedef struct pvs_view_frame {
    float forward[3], right[3], up[3];
    float tan_half_x, tan_half_y;
} pvs_view_frame;

/* Builds the frame. Asserts a valid view (non-zero forward, up not
 * parallel to it, fov in (0, 180), 0 < near < far). */
pvs_view_frame pvs_view_frame_make(const pvs_view* view);

/* Projects world point p from the apex: writes image[2] (normalised image
 * coordinates) and returns the depth along forward. When the returned depth
 * is <= 0 the point is not in front of the apex and image[] is left
 * untouched. */
float pvs_view_project(const pvs_view* view, const pvs_view_frame* frame, const float p[3],
                       float image[2]);

#ifdef __cplusplus
}
#endif

#endif
