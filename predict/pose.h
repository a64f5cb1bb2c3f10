/* pose.h - head/eye poses and the double-precision quaternion math predict/ uses.
 *
 * Conventions (shared by every module): metres, right-handed, +Y up. A pose is
 * a position and a unit quaternion (x, y, z, w) rotating head-local vectors to
 * world; the head looks down its local -Z with +Y up and +X right.
 *
 * predict/ works in double precision: sensor samples are 1 ms apart, and
 * finite differences of float positions tens of metres from the origin lose
 * about three significant digits of velocity. cglm is float-only, hence these
 * few helpers. */
#ifndef TRIMVR_PRED_POSE_H
#define TRIMVR_PRED_POSE_H

#ifdef __cplusplus
extern "C" {
#endif

#define PRED_PI 3.14159265358979323846
#define PRED_DEG (PRED_PI / 180.0) /* radians per degree */

typedef struct pred_pose {
    double t;    /* seconds */
    double p[3]; /* metres, world */
    double q[4]; /* x, y, z, w; unit; head-local -> world */
} pred_pose;

/* out = a * b (apply b first). out may alias a or b. */
void pred_quat_mul(const double a[4], const double b[4], double out[4]);
/* Conjugate (= inverse of a unit quaternion). */
void pred_quat_conj(const double q[4], double out[4]);
/* Returns the norm before normalising; a zero quaternion becomes identity. */
double pred_quat_normalize(double q[4]);
/* Rotates v by unit q. out may alias v. */
void pred_quat_rotate(const double q[4], const double v[3], double out[3]);
/* Unit quaternion of the rotation vector r (axis * angle in radians). */
void pred_quat_exp(const double r[3], double out[4]);
/* Rotation vector of unit q, angle in [0, pi] (the shortest arc). */
void pred_quat_log(const double q[4], double out[3]);
/* Spherical interpolation along the shortest arc (q and -q are the same
 * rotation): u = 0 gives a, u = 1 gives b or -b. */
void pred_quat_slerp(const double a[4], const double b[4], double u, double out[4]);
/* Angle in degrees of the rotation taking a to b, in [0, 180]. */
double pred_quat_angle_deg(const double a[4], const double b[4]);
/* Head orientation from yaw about +Y, then pitch about local +X (positive
 * looks up), then roll about local -Z; radians. Yaw 0 looks down world -Z. */
void pred_quat_from_ypr(double yaw, double pitch, double roll, double out[4]);

/* Orientation that looks down `forward` with its +Y towards `up` (both
 * world vectors, any length; up must not be parallel to forward): the
 * rotation whose columns are right, up and -forward. */
void pred_quat_look(const double forward[3], const double up[3], double out[4]);

/* World directions of the head's local -Z (forward), +Y (up) and +X (right). */
void pred_pose_forward(const double q[4], double out[3]);
void pred_pose_up(const double q[4], double out[3]);
void pred_pose_right(const double q[4], double out[3]);

/* Eye poses for a head pose: same orientation, positions offset by -ipd/2
 * (eyes[0], left) and +ipd/2 (eyes[1], right) along the head-local +X. */
void pred_eye_poses(const pred_pose* head, double ipd, pred_pose eyes[2]);

/* Linear position and shortest-arc orientation interpolation, u in [0, 1]. */
void pred_pose_lerp(const pred_pose* a, const pred_pose* b, double u, pred_pose* out);

double pred_vec3_dist(const double a[3], const double b[3]);

#ifdef __cplusplus
}
#endif

#endif
