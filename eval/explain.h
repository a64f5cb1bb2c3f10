/* explain.h - `trimvr eval --explain`: which rule of the trim-region PVS put
 * each false positive (a triangle in the PVS but not in the sampled ground
 * truth) into the PVS, from the TV_REASON_* masks of pvs_desc.explain
 * (docs/evaluation.md, "Explaining false positives").
 *
 * A triangle that several rules output counts for each under "any" and for
 * none under "alone"; a rule's "alone" count is what the PVS would lose if
 * that rule alone output nothing there. "first" partitions them by the
 * first of their rules in TV_REASON_* order (P4, P2, P3, overflow), as the
 * picture colours them. */
#ifndef TRIMVR_EVAL_EXPLAIN_H
#define TRIMVR_EVAL_EXPLAIN_H

#include "pvs_shared.h"
#include "render.h"
#include "scene.h"
#include "viewcell.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

typedef struct tv_explain {
    uint64_t fp;                      /* false-positive triangles, summed over viewcells */
    uint64_t any[TV_REASON_COUNT];    /* of them, output by rule i (among others) */
    uint64_t alone[TV_REASON_COUNT];  /* output by rule i only */
    uint64_t first[TV_REASON_COUNT];  /* rule i is the first of its rules (a partition) */
    uint64_t unexplained;             /* no rule recorded: a defect when non-zero */
    /* the viewcell with the most false positives, for the picture */
    pred_viewcell vc;
    uint32_t* ids;                    /* its false positives */
    uint32_t* first_rule;             /* and the index of each one's first rule */
    uint32_t count;
} tv_explain;

/* Short name of rule i < TV_REASON_COUNT ("P4 vis", "P3 overflow", ...). */
const char* tv_explain_rule_name(int i);

/* Adds one viewcell: reasons per triangle (pvs_method_reasons), its PVS and
 * GT masks (one byte per triangle). False when out of memory. */
bool tv_explain_add(tv_explain* e, const pred_viewcell* vc, const uint32_t* reasons, const uint8_t* pvs,
                    const uint8_t* gt, uint32_t triangle_count);

/* The table (markdown) of rules with their counts and shares. */
void tv_explain_print(FILE* f, const tv_explain* e, const char* scene, float delta_m);

/* "explain": {...} with the same figures, no trailing comma. */
void tv_explain_json(FILE* f, const tv_explain* e, const char* indent);

/* DIR/explain_overview.png and DIR/explain_eye.png: only the false positives
 * of the kept viewcell, drawn from the overview camera of Figure 1 and from
 * its centre, each coloured by its first rule. */
bool tv_explain_write_pictures(const tv_explain* e, rnd_context* ctx, const rnd_gpu_scene* gpu,
                               const scn_scene* scene, uint32_t width, uint32_t height, const char* dir, char* err,
                               size_t err_size);

void tv_explain_free(tv_explain* e);

#endif
