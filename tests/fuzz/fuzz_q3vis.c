/* fuzz_q3vis.c - libFuzzer target for the q3 vis JSON parser
 * (eval/q3vis_parse.c), straight from memory (the input is not
 * NUL-terminated). A parsed table has visdata for every cluster pair and
 * leaves whose cluster is in range. */
#include "fuzz_common.h"
#include "q3vis.h"

#include <assert.h>

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    tv_log_set_sink(_fuzz_quiet, NULL);
    pvs_q3vis vis;
    char err[512];
    if (pvs_q3vis_parse((const char*)data, size, "fuzz.pvs.json", &vis, err, sizeof err)) {
        assert(vis.bytes_per_cluster * 8 >= vis.n_clusters);
        for (uint32_t i = 0; i < vis.leaf_count; i++)
            assert(vis.leaves[i].cluster >= -1 && vis.leaves[i].cluster < (int32_t)vis.n_clusters);
        for (uint32_t c = 0; c < vis.n_clusters; c++)
            (void)pvs_q3vis_sees(&vis, c, vis.n_clusters - 1 - c);
        pvs_q3vis_free(&vis);
    } else {
        assert(strchr(err, '\n') == NULL);
    }
    return 0;
}
