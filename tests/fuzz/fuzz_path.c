/* fuzz_path.c - libFuzzer target for the path CSV reader (predict/path.c). A
 * loaded path must have samples with strictly increasing times within
 * PRED_PATH_MAX_TIME_S, finite
 * positions and unit quaternions; a failure must leave it empty with a
 * one-line message. */
#include "fuzz_common.h"
#include "path.h"

#include <assert.h>
#include <math.h>

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const char* file = fuzz_write_input(data, size, "csv");
    if (!file)
        return 0;
    pred_path path;
    char err[512];
    if (pred_path_load(file, &path, err, sizeof err)) {
        assert(path.count > 0);
        for (size_t i = 0; i < path.count; i++) {
            const pred_pose* p = &path.poses[i];
            assert((i == 0 || p->t > path.poses[i - 1].t) && fabs(p->t) <= PRED_PATH_MAX_TIME_S);
            assert(isfinite(p->p[0]) && isfinite(p->p[1]) && isfinite(p->p[2]));
            double n = p->q[0] * p->q[0] + p->q[1] * p->q[1] + p->q[2] * p->q[2] + p->q[3] * p->q[3];
            assert(fabs(n - 1.0) < 1e-6);
        }
        pred_path_free(&path);
    } else {
        assert(path.count == 0 && path.poses == NULL && strchr(err, '\n') == NULL);
    }
    remove(file);
    return 0;
}
