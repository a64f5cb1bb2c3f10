/* json_read.h - a small JSON reader: parses a whole document into a tree
 * (bench part files, OpenArena .pvs.json; in base/ so any module may read JSON with it). Numbers are doubles
 * (strtod, so a value written with %.17g reads back bit-exact); strings are
 * UTF-8 with the standard escapes (\uXXXX above ASCII becomes '?'). Nesting
 * is limited to 64 levels. Vulkan-free. */
#ifndef TRIMVR_BASE_JSON_READ_H
#define TRIMVR_BASE_JSON_READ_H

#include <stdbool.h>
#include <stddef.h>

typedef enum tv_json_type {
    TV_JSON_NULL,
    TV_JSON_BOOL,
    TV_JSON_NUMBER,
    TV_JSON_STRING,
    TV_JSON_ARRAY,
    TV_JSON_OBJECT
} tv_json_type;

typedef struct tv_json {
    tv_json_type type;
    double num;             /* NUMBER; BOOL as 0 or 1 */
    char* str;              /* STRING */
    int count;              /* ARRAY items, OBJECT members */
    struct tv_json* items;  /* ARRAY items, OBJECT values */
    char** keys;            /* OBJECT member names */
} tv_json;

/* Parses text[0..len) into *out (free with tv_json_free). False with
 * "NAME: byte N: expected ..." in err on a syntax error or trailing bytes. */
bool tv_json_parse(const char* text, size_t len, const char* name, tv_json* out, char* err, size_t err_size);

void tv_json_free(tv_json* j);

/* The member `key` of an object, or NULL (also when j is not an object). */
const tv_json* tv_json_get(const tv_json* j, const char* key);

#endif
