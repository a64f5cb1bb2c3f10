/* eval_common.h - what `trimvr eval` and `trimvr bench` share: the viewcells
 * they evaluate (along a path, or at floor points of an OpenArena level),
 * one PVS method run plus its ground-truth evaluation per viewcell, means
 * over viewcells, and the JSON keys of one result. */
#ifndef TRIMVR_EVAL_EVAL_COMMON_H
#define TRIMVR_EVAL_EVAL_COMMON_H

#include "ground_truth.h"
#include "json.h"
#include "method.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

/* Layers whose figures a cell keeps; later ones are added to the last. */
#define TV_EVAL_MAX_LAYERS 96

typedef struct tv_eval_cell {
    pred_viewcell vc;
    double motion[3];   /* the sas samples' segment: 2 delta along the direction of travel */
    pvs_eval_result m;
    pvs_method_stats st; /* st.tr.per_layer is NULL: the figures are in layers */
    double pvs_ms;
    /* tr: overflowing pixels over active pixels, both summed over layers and,
     * in a mean, over viewcells (the issue-17 target is a share; the two
     * counts above are a sum and a mean, so their ratio is not) */
    double overflow_share;
    /* tr: per-layer figures summed over layer_cells viewcells (1 for one
     * cell; tv_eval_mean sums), layer_count entries */
    pvs_layer_stats layers[TV_EVAL_MAX_LAYERS];
    uint32_t layer_count;
    int layer_cells;
} tv_eval_cell;

/* The most viewcells tv_eval_path_cells gives (at seconds each, a million take weeks). */
#define TV_EVAL_MAX_PATH_CELLS 1000000

/* One viewcell every `every` display frames (90 Hz) of the path in `file`
 * (every <= 0: max_cells of them spread evenly), at most max_cells (0:
 * all), of radius delta and the given FOVs, into a malloc'ed array (*out).
 * When scene_spec is empty it receives the path's '# scene:' line. Returns the count, or -1 with a one-line
 * reason (also when that is more than TV_EVAL_MAX_PATH_CELLS). */
int tv_eval_path_cells(const char* file, int every, int max_cells, float delta, float fov_deg, float fov_pvs_deg,
                       tv_eval_cell** out, char* scene_spec, size_t spec_size, char* err, size_t err_size);

/* Up to max_cells eye positions at floor points of `scene`: the largest
 * upward-facing triangles (normal y > 0.9), taken in order of area, with the
 * eye 1.4 m above the centroid (the Quake 3 standing eye height, 56 units).
 * A point is kept when the 0.3 m ball around the eye meets a vis cluster's
 * leaf in the level's PVS file, no triangle crosses the vertical segment
 * from the floor to 0.3 m above the eye (so it is the empty space above that
 * floor), and it is at least 4 m from every point already kept. Each looks
 * horizontally towards the level's bounding-box centre. Writes pos[3 * i],
 * dir[3 * i]. Returns the count (0 when the level has no such point), -1 on
 * a bad file. */
int tv_eval_floor_points(const scn_scene* scene, const char* pvs_json, int max_cells, float* pos, float* dir,
                         char* err, size_t err_size);

/* The request of a viewcell: its motion, and as current pose the centre
 * looking along the axis (what frompoint renders from). */
pvs_request tv_eval_request(const tv_eval_cell* c, float eye_fov_deg);

/* Computes c's PVS with m, marks it in mask (triangle_count bytes) and
 * evaluates it against ground truth in `scene` (uploaded as `gpu` on `rnd`;
 * gt receives the GT mask). Fills c->st,
 * c->pvs_ms and c->m. False with a one-line reason on failure. */
bool tv_eval_cell_run(pvs_method* m, rnd_context* rnd, const scn_scene* scene, const rnd_gpu_scene* gpu,
                      const pvs_eval_desc* ed, float eye_fov_deg, tv_eval_cell* c, uint8_t* mask, uint8_t* gt,
                      char* err, size_t err_size);

/* Means over n viewcells: PSNR as the PSNR of the mean squared error,
 * minima and maxima as extremes, k-buffer use as the largest, overflow
 * pixels summed, so one bad viewcell is never averaged away. */
tv_eval_cell tv_eval_mean(const tv_eval_cell* c, int n);

/* The metric keys of one result (see docs/evaluation.md), no trailing comma. */
void tv_eval_json_metrics(FILE* f, const tv_eval_cell* c, const char* indent);

#endif
