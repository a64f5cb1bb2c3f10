/* json.h - the JSON number writer every results file uses (eval.json,
 * bench.json, summary.json), so that they agree on the format. */
#ifndef TRIMVR_JSON_H
#define TRIMVR_JSON_H

#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Writes "key": value and then tail (such as ",\n"). JSON has no infinity:
 * a non-finite value (an infinite PSNR of identical images) is written as
 * null. */
void tv_json_num(FILE* f, const char* key, double v, const char* tail);

#ifdef __cplusplus
}
#endif

#endif
