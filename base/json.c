#include "json.h"

#include <math.h>

void tv_json_num(FILE* f, const char* key, double v, const char* tail)
{
    if (isfinite(v))
        fprintf(f, "\"%s\": %.6g%s", key, v, tail);
    else
        fprintf(f, "\"%s\": null%s", key, tail);
}
