/* fuzz_trace.c - libFuzzer target for the recorded-trace importers
 * (predict/trace_import.c, HoloLens, OptiTrack and Quest CSV, format
 * detected from the header). An imported trace has at least two samples
 * with strictly increasing times within PRED_PATH_MAX_TIME_S. */
#include "fuzz_common.h"
#include "trace_import.h"

#include <assert.h>
#include <math.h>

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const char* file = fuzz_write_input(data, size, "csv");
    if (!file)
        return 0;
    pred_path path;
    pred_trace_report rep;
    pred_trace_desc desc = {.format = PRED_TRACE_AUTO};
    char err[512];
    if (pred_trace_import(file, &desc, &path, &rep, err, sizeof err)) {
        assert(path.count >= 2 && rep.format != PRED_TRACE_AUTO);
        for (size_t i = 1; i < path.count; i++)
            assert(fabs(path.poses[i].t) <= PRED_PATH_MAX_TIME_S && path.poses[i].t > path.poses[i - 1].t);
        pred_path_free(&path);
    } else {
        assert(path.count == 0 && path.poses == NULL && strchr(err, '\n') == NULL);
    }
    remove(file);
    return 0;
}
