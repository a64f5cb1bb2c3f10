/* mover.h - moving objects of a scene: rigid bodies on keyframed tracks.
 *
 * A mover owns a contiguous vertex range and a contiguous triangle range of
 * its scene; the movers' triangles are the scene's last
 * `dynamic_triangle_count` triangles, so every id below
 * triangle_count - dynamic_triangle_count is static geometry; movers follow
 * each other in the order of their ranges, vertices too. A mover keeps
 * its rest geometry in its own (local) frame; its world transform at time t
 * is parent * T(t) * R(t) * S(t) (glTF node semantics), with each of T, R, S
 * read from a keyframe track (LINEAR: lerp, slerp for R; STEP: the last key
 * at or before t) or the node's fixed value when it has no track. Tracks loop
 * with the mover's period (its last key time); before the first key a track
 * holds its first value. The scene's positions/normals of a mover are its
 * pose at the time of the last scn_scene_pose (t = 0 after loading).
 */
#ifndef TRIMVR_SCENE_MOVER_H
#define TRIMVR_SCENE_MOVER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct scn_scene scn_scene;

typedef enum scn_interp { SCN_INTERP_LINEAR = 0, SCN_INTERP_STEP = 1 } scn_interp;

enum { SCN_TRACK_TRANSLATION = 0, SCN_TRACK_ROTATION = 1, SCN_TRACK_SCALE = 2, SCN_TRACK_COUNT = 3 };

/* Keys of one property: `count` increasing times (seconds, >= 0) and 3
 * (translation, scale) or 4 (rotation quaternion x, y, z, w) floats per key.
 * count 0: the property keeps the mover's base value. */
typedef struct scn_track {
    uint32_t count;
    float* times;
    float* values;
    scn_interp interp;
} scn_track;

typedef struct scn_mover {
    char name[64];
    uint32_t first_vertex, vertex_count;
    uint32_t first_triangle, triangle_count;
    float* rest;                  /* 6 floats per vertex: local position, local normal */
    float local_min[3], local_max[3]; /* box of the rest positions */
    float parent[16];             /* column-major, fixed: the frame the tracks move in */
    float base_t[3], base_r[4], base_s[3]; /* values of properties without a track */
    scn_track track[SCN_TRACK_COUNT];
    float period_s;               /* loop length: the last key time of any track (0: static) */
} scn_mover;

/* Takes the mover's vertex range of `scene` (already holding its local
 * geometry) as its rest geometry, checks its tracks (increasing finite
 * times, finite values, unit-normalisable rotations) and sets local box and
 * period. The vertex range must be used by the mover's triangles only.
 * False with a one-line problem in err (no file name) when a track is bad or
 * memory runs out. */
bool scn_mover_init(scn_mover* m, const scn_scene* scene, char* err, size_t err_size);

/* Releases the mover's arrays and zeroes it. */
void scn_mover_free(scn_mover* m);

/* Column-major local-to-world matrix of the mover at time t. */
void scn_mover_matrix(const scn_mover* m, double t, float out[16]);

/* Writes every mover's world positions and normals at time t into the
 * scene's arrays (static geometry untouched). */
void scn_scene_pose(scn_scene* scene, double t);

/* A box holding mover `index` of the scene at every time of [t0, t1]
 * (t0 <= t1). Exact (the hull of the swept box) for translation-only
 * LINEAR motion; for rotation and scale it adds, per sub-interval, half the
 * bound on how far a box corner can travel in it (docs/scenes.md, "Movers"). */
void scn_mover_bounds(const scn_scene* scene, uint32_t index, double t0, double t1, float out_min[3],
                      float out_max[3]);

#ifdef __cplusplus
}
#endif

#endif
