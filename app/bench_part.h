/* bench_part.h - part files of a sharded `trimvr bench` (docs/bench.md):
 * DIR/part-<i>.json holds one shard's viewcell results at full precision
 * (doubles as %.17g, non-finite values as the strings "inf", "-inf",
 * "nan"), so rows merged from parts equal a serial run's bit for bit, plus
 * what the merge checks: the code version, the settings (every option that
 * changes a result) and the shard's place among all shards. */
#ifndef TRIMVR_APP_BENCH_PART_H
#define TRIMVR_APP_BENCH_PART_H

#include "bench_report.h"

typedef struct tv_bench_part {
    char version[128];
    char settings[2048];   /* canonical option list, compared as a string */
    char command[4096];
    char device[256];
    char date[64];
    int shard, shards;
    double wall_s;
    unsigned res[2], pvs_res[2];
    int samples;
    float fov, fov_pvs;
    tv_bench_cell* cells;  /* malloc'ed */
    int count;
} tv_bench_part;

/* Writes `p` to `file`. False with "FILE: cannot write" in err. */
bool tv_bench_part_write(const char* file, const tv_bench_part* p, char* err, size_t err_size);

/* Reads `file` into *p (cells malloc'ed; free with tv_bench_part_free).
 * False with a one-line reason naming the file: unreadable, not JSON, not a
 * part file, a field list other than this build's, a bad value. */
bool tv_bench_part_read(const char* file, tv_bench_part* p, char* err, size_t err_size);

void tv_bench_part_free(tv_bench_part* p);

/* `trimvr bench merge --out OUT PART...`: checks that the parts are one
 * sweep (same version, settings and shard count, every shard once) and
 * writes OUT/bench.md, bench.csv, bench.json and plots as the serial run
 * would. Exit status 0, 1 on a bad or mismatched part, 2 on usage. */
int tv_cmd_bench_merge(int argc, char** argv);

#endif
