/* json.h - the JSON number writer every results file uses (eval.json,
 * bench.json, summary.json), so that they agree on the format. */
#ifndef TRIMVR_JSON_H
#define TRIMVR_JSON_H

#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Writes "key": value and then tail (such as ",\n"). JSON has no infinity:
 * an infinite value (the PSNR of identical images) is written as the string
 * "inf" (or "-inf"), and null means not a number (a broken metric), so that
 * no reader can take one for the other. */
void tv_json_num(FILE* f, const char* key, double v, const char* tail);

#ifdef __cplusplus
}
#endif

#endif
