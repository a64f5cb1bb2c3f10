/* trace_import.h - importers for recorded head-motion traces of real people.
 *
 * Three CSV formats (../shared/traces; docs/paths.md "Recorded traces"):
 *
 *   hololens   timestamp,x,y,z,qx,qy,qz,qw: .NET ticks (100 ns), metres, the
 *              Unity frame (left-handed, +Y up, the head looks down local +Z).
 *   optitrack  t_header_s,t_bag_s,x,y,z,qx,qy,qz,qw: seconds, metres, Motive's
 *              frame (right-handed, +Y up); the head rigid body's local +Z
 *              points forward (measured: docs/paths.md).
 *   quest      Questset movement files: many columns, of which HeadPosX/Y/Z,
 *              HeadOrientationW/X/Y/Z and time (seconds); the Oculus frame
 *              (right-handed, +Y up, the head looks down local -Z).
 *
 * Every importer converts to trimvr's frame (pose.h: right-handed, +Y up, the
 * head looks down local -Z): the left-handed HoloLens frame is mirrored in z,
 * p' = (x, y, -z), q' = (-qx, -qy, qz, qw); the OptiTrack rigid body is turned
 * half a turn about its local +Y, q' = q * (0, 1, 0, 0). Times are shifted so
 * the first kept sample is at t = 0. Extra columns are ignored; column order
 * is free. Samples whose time is not after the previous kept sample are
 * dropped and counted; gaps are counted and left to interpolation. */
#ifndef TRIMVR_PRED_TRACE_IMPORT_H
#define TRIMVR_PRED_TRACE_IMPORT_H

#include "path.h"

#include <stdbool.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum pred_trace_format {
    PRED_TRACE_AUTO = 0, /* from the header line */
    PRED_TRACE_HOLOLENS,
    PRED_TRACE_OPTITRACK,
    PRED_TRACE_QUEST,
    PRED_TRACE_FORMAT_COUNT
} pred_trace_format;

/* "auto", "hololens", "optitrack", "quest" <-> format; from_name returns
 * false for an unknown name. */
const char* pred_trace_format_name(pred_trace_format format);
bool pred_trace_format_from_name(const char* name, pred_trace_format* format);

/* Zero means default. */
typedef struct pred_trace_desc {
    pred_trace_format format; /* PRED_TRACE_AUTO */
    double gap_s;             /* sample intervals longer than this count as gaps: 0.1 s */
} pred_trace_desc;

/* What the import met. */
typedef struct pred_trace_report {
    pred_trace_format format; /* the format read (resolved when auto) */
    size_t rows;              /* data rows */
    size_t dropped;           /* rows whose time was not after the previous kept row */
    size_t first_dropped_line; /* 0 when none */
    size_t cut_line;          /* a last data line without a newline, dropped (logged as a warning): 0 when none */
    size_t gaps;              /* kept intervals longer than gap_s */
    double max_gap_s;         /* longest kept interval */
} pred_trace_report;

/* Reads `file` into `out` (zeroed first; out->description names the source
 * and format). On failure returns false, leaves `out` empty and writes one
 * line "FILE:LINE: problem" or "FILE: problem" into err: unreadable file, a
 * header matching no format (or not the requested one), a row with a missing
 * or unparsable field, a non-finite value, a quaternion whose norm is not
 * near 1, or fewer than two kept samples. `report` may be NULL. */
bool pred_trace_import(const char* file, const pred_trace_desc* desc, pred_path* out,
                       pred_trace_report* report, char* err, size_t err_size);

#ifdef __cplusplus
}
#endif

#endif
