#include "json.h"

#include <math.h>

void tv_json_num(FILE* f, const char* key, double v, const char* tail)
{
    if (isfinite(v))
        fprintf(f, "\"%s\": %.6g%s", key, v, tail);
    else if (isinf(v))
        fprintf(f, "\"%s\": \"%s\"%s", key, v > 0 ? "inf" : "-inf", tail);
    else
        fprintf(f, "\"%s\": null%s", key, tail);
}
