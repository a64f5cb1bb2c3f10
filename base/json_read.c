#include "json_read.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_DEPTH 64

typedef struct reader {
    const char* s;
    size_t len, pos;
    const char* name;
    char* err;
    size_t err_size;
    bool failed;
} reader;

static bool fail(reader* r, const char* what)
{
    if (!r->failed)
        snprintf(r->err, r->err_size, "%s: byte %zu: %s", r->name, r->pos,
                 r->pos >= r->len ? "unexpected end of file" : what);
    r->failed = true;
    return false;
}

static void ws(reader* r)
{
    while (r->pos < r->len && strchr(" \t\r\n", r->s[r->pos]) && r->s[r->pos])
        r->pos++;
}

static bool eat(reader* r, char c)
{
    ws(r);
    if (r->pos < r->len && r->s[r->pos] == c) {
        r->pos++;
        return true;
    }
    return false;
}

static bool string(reader* r, char** out)
{
    if (!eat(r, '"'))
        return fail(r, "expected a string");
    /* The decoded string is never longer than its raw span: size the buffer by
     * the span, not by the rest of the file (documents hold many strings). */
    size_t end = r->pos;
    while (end < r->len && r->s[end] != '"')
        end += r->s[end] == '\\' ? 2 : 1;
    char* buf = malloc((end < r->len ? end : r->len) - r->pos + 1);
    size_t n = 0;
    while (buf && r->pos < r->len && r->s[r->pos] != '"') {
        char c = r->s[r->pos++];
        if ((unsigned char)c < 0x20) {
            free(buf);
            return fail(r, "control character in a string");
        }
        if (c == '\\' && r->pos < r->len) {
            char e = r->s[r->pos++];
            const char* from = "\"\\/bfnrt";
            const char* to = "\"\\/\b\f\n\r\t";
            const char* at = strchr(from, e);
            if (e == 'u' && r->pos + 4 <= r->len) {
                unsigned v;
                char hex[5] = {0};
                memcpy(hex, &r->s[r->pos], 4);
                /* Four hex digits exactly: "%4x" alone would accept "12\"4" and run past
                 * the closing quote the buffer was sized by. */
                bool hex4 = strspn(hex, "0123456789abcdefABCDEF") == 4;
                if (!hex4 || sscanf(hex, "%4x", &v) != 1) {
                    free(buf);
                    return fail(r, "bad \\u escape");
                }
                r->pos += 4;
                c = v < 0x80 ? (char)v : '?';
            } else if (e && at) {
                c = to[at - from];
            } else {
                free(buf);
                return fail(r, "bad escape in a string");
            }
        }
        buf[n++] = c;
    }
    if (!buf)
        return fail(r, "out of memory");
    if (r->pos >= r->len) {
        free(buf);
        return fail(r, "unterminated string");
    }
    r->pos++;
    buf[n] = 0;
    *out = buf;
    return true;
}

static bool value(reader* r, tv_json* out, int depth);

/* Arrays and objects: items separated by ',' up to `close`; objects read a
 * key and ':' before each value. */
static bool container(reader* r, tv_json* out, int depth, char close)
{
    out->type = close == ']' ? TV_JSON_ARRAY : TV_JSON_OBJECT;
    if (depth >= MAX_DEPTH)
        return fail(r, "nested too deeply");
    if (eat(r, close))
        return true;
    int cap = 0;
    do {
        if (out->count == cap) {
            cap = cap ? 2 * cap : 8;
            tv_json* items = realloc(out->items, (size_t)cap * sizeof *items);
            char** keys = close == '}' ? realloc(out->keys, (size_t)cap * sizeof *keys) : NULL;
            if (items)
                out->items = items;
            if (keys)
                out->keys = keys;
            if (!items || (close == '}' && !keys))
                return fail(r, "out of memory");
        }
        tv_json* item = &out->items[out->count];
        memset(item, 0, sizeof *item);
        if (close == '}') {
            out->keys[out->count] = NULL;
            out->count++;
            if (!string(r, &out->keys[out->count - 1]) || (!eat(r, ':') && !fail(r, "expected ':'")) ||
                !value(r, item, depth + 1))
                return false;
        } else {
            out->count++;
            if (!value(r, item, depth + 1))
                return false;
        }
    } while (eat(r, ','));
    return eat(r, close) || fail(r, close == ']' ? "expected ',' or ']'" : "expected ',' or '}'");
}

static bool value(reader* r, tv_json* out, int depth)
{
    ws(r);
    if (r->pos >= r->len)
        return fail(r, "expected a value");
    char c = r->s[r->pos];
    if (c == '{' || c == '[') {
        r->pos++;
        return container(r, out, depth, c == '{' ? '}' : ']');
    }
    if (c == '"') {
        out->type = TV_JSON_STRING;
        return string(r, &out->str);
    }
    static const char* const words[] = {"null", "true", "false"};
    for (int w = 0; w < 3; w++) {
        size_t n = strlen(words[w]);
        if (r->len - r->pos >= n && memcmp(&r->s[r->pos], words[w], n) == 0) {
            r->pos += n;
            out->type = w == 0 ? TV_JSON_NULL : TV_JSON_BOOL;
            out->num = w == 1;
            return true;
        }
    }
    if (c != '-' && (c < '0' || c > '9'))
        return fail(r, "expected a value");
    char num[64];
    size_t n = 0;
    while (r->pos + n < r->len && n + 1 < sizeof num && strchr("+-.eE0123456789", r->s[r->pos + n]) &&
           r->s[r->pos + n])
        n++;
    memcpy(num, &r->s[r->pos], n);
    num[n] = 0;
    char* end;
    out->type = TV_JSON_NUMBER;
    out->num = strtod(num, &end);
    if (end != num + n)
        return fail(r, "bad number");
    r->pos += n;
    return true;
}

bool tv_json_parse(const char* text, size_t len, const char* name, tv_json* out, char* err, size_t err_size)
{
    reader r = {.s = text, .len = len, .name = name, .err = err, .err_size = err_size};
    memset(out, 0, sizeof *out);
    bool ok = value(&r, out, 0);
    ws(&r);
    if (ok && r.pos < r.len)
        ok = fail(&r, "trailing bytes after the document");
    if (!ok)
        tv_json_free(out);
    return ok;
}

void tv_json_free(tv_json* j)
{
    for (int i = 0; i < j->count; i++) {
        tv_json_free(&j->items[i]);
        if (j->keys)
            free(j->keys[i]);
    }
    free(j->items);
    free(j->keys);
    free(j->str);
    memset(j, 0, sizeof *j);
}

const tv_json* tv_json_get(const tv_json* j, const char* key)
{
    if (!j || j->type != TV_JSON_OBJECT)
        return NULL;
    for (int i = 0; i < j->count; i++)
        if (j->keys[i] && strcmp(j->keys[i], key) == 0)
            return &j->items[i];
    return NULL;
}
