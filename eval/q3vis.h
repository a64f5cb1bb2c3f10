/* q3vis.h - an OpenArena level's own offline PVS (<level>.pvs.json, format in
 * ../shared/scenes/README.md) as a reusable structure, and the triangle set it
 * implies for a viewcell.
 *
 * The Quake 3 compiler ("vis") splits the level's empty space into BSP leaves
 * grouped into clusters and stores, per cluster, the bitset of clusters
 * potentially visible from anywhere in it. The file gives every leaf's cluster
 * and bounding box in glTF coordinates, so a point (or a viewcell) finds its
 * clusters by box tests, and a scene triangle belongs to every cluster whose
 * leaf box it touches. The result is coarse and conservative by construction:
 * the reference the online PVS methods are compared with on these levels.
 *
 * Vulkan-free (part of tv_pvs_cpu, tested under the sanitizers). The parser
 * takes any bytes: malformed input gives a one-line "FILE: problem" error and
 * an empty structure, never a crash.
 */
#ifndef TRIMVR_EVAL_Q3VIS_H
#define TRIMVR_EVAL_Q3VIS_H

#include "scene.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pvs_q3vis_leaf {
    int32_t cluster;       /* -1: solid or outside the level */
    float min[3], max[3];  /* bounding box, glTF coordinates (metres) */
} pvs_q3vis_leaf;

typedef struct pvs_q3vis {
    uint32_t n_clusters;
    uint32_t bytes_per_cluster; /* >= ceil(n_clusters / 8) */
    /* Row-major bitsets: bit j (byte j / 8, bit j % 8, LSB first) of row i
     * set = cluster j potentially visible from cluster i. */
    uint8_t* visdata;           /* n_clusters * bytes_per_cluster bytes */
    uint32_t leaf_count;
    pvs_q3vis_leaf* leaves;
} pvs_q3vis;

/* Parses `len` bytes of JSON (need not be NUL-terminated) into `out` (zeroed
 * first). `name` is the file name used in error messages. Requires the keys
 * n_clusters, bytes_per_cluster, visdata_b64 and leafs (each leaf an object
 * with cluster, min, max), each once; other keys are ignored. Fails with
 * "NAME: problem" (byte offset for syntax errors) on malformed JSON, bad
 * base64, a visdata size other than n_clusters * bytes_per_cluster, a leaf
 * cluster outside [-1, n_clusters) or a non-finite or inverted box. */
bool pvs_q3vis_parse(const char* text, size_t len, const char* name, pvs_q3vis* out, char* err,
                     size_t err_size);

/* Reads and parses the file `path` (see pvs_q3vis_parse). */
bool pvs_q3vis_load(const char* path, pvs_q3vis* out, char* err, size_t err_size);

/* Releases the arrays and zeroes the structure. Safe on a zeroed one. */
void pvs_q3vis_free(pvs_q3vis* vis);

/* True when cluster `to` is potentially visible from cluster `from` (both < n_clusters). */
bool pvs_q3vis_sees(const pvs_q3vis* vis, uint32_t from, uint32_t to);

/* Marks in cluster_mask (n_clusters bytes, caller-owned, cleared first) the
 * clusters of every leaf whose box (grown by PVS_Q3VIS_EPS_M) meets the ball
 * of `radius` metres around `centre`. Returns how many were marked: 0 when
 * the ball lies in solid space or outside the level. Leaves with an empty box
 * (the compiler's placeholder leaf 0) are ignored. */
uint32_t pvs_q3vis_clusters_near(const pvs_q3vis* vis, const float centre[3], float radius,
                                 uint8_t* cluster_mask);

/* Leaf boxes are rounded to whole Quake units by the compiler and scaled to
 * metres in float; level geometry lies on their faces. Growing them by 1 cm
 * (under half a Quake unit, 2.54 cm) keeps "touching" robust to that rounding. */
#define PVS_Q3VIS_EPS_M 0.01f

/* Triangle -> cluster incidence of a scene: the clusters of triangle t are
 * clusters[offsets[t] .. offsets[t + 1]), each once. */
typedef struct pvs_q3vis_tri_map {
    uint32_t triangle_count;
    uint32_t* offsets;       /* triangle_count + 1 */
    uint32_t* clusters;
    uint32_t unclustered;    /* triangles touching no leaf of any cluster */
} pvs_q3vis_tri_map;

/* Builds the incidence for `scene`: a triangle belongs to a cluster when its
 * bounding box meets one of the cluster's leaf boxes grown by
 * PVS_Q3VIS_EPS_M. False (map empty, "q3vis: out of memory") only when memory
 * runs out. */
bool pvs_q3vis_map_triangles(const pvs_q3vis* vis, const scn_scene* scene, pvs_q3vis_tri_map* map, char* err,
                             size_t err_size);

void pvs_q3vis_tri_map_free(pvs_q3vis_tri_map* map);

/* The PVS of the source clusters marked in `sources` (n_clusters bytes): the
 * ascending ids of every triangle belonging to a cluster visible from any
 * source. `ids` holds map->triangle_count entries (the bound). Returns the
 * count. `scratch` holds n_clusters bytes. */
uint32_t pvs_q3vis_triangles(const pvs_q3vis* vis, const pvs_q3vis_tri_map* map, const uint8_t* sources,
                             uint8_t* scratch, uint32_t* ids);

#ifdef __cplusplus
}
#endif

#endif
