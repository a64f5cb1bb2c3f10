/* q3vis_parse.c - the .pvs.json reader: base/json_read.h parses the document
 * (levels' files are at most a few MB), this file checks the keys it needs and
 * decodes the visdata with a strict base64 decoder. */
#include "q3vis.h"

#include "json_read.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_CLUSTERS (1u << 20)  /* far above any Quake 3 level (a few thousand) */

typedef struct _ctx {
    const char* name;
    char* err;
    size_t err_size;
} _ctx;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static bool _fail(const _ctx* c, const char* fmt, ...)
{
    char msg[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    snprintf(c->err, c->err_size, "%s: %s", c->name, msg);
    return false;
}

static int _b64_value(unsigned char c)
{
    if (c >= 'A' && c <= 'Z')
        return c - 'A';
    if (c >= 'a' && c <= 'z')
        return c - 'a' + 26;
    if (c >= '0' && c <= '9')
        return c - '0' + 52;
    if (c == '+')
        return 62;
    if (c == '/')
        return 63;
    return -1;
}

/* Strict standard base64 with '=' padding. */
static bool _base64(const _ctx* p, const char* s, size_t n, uint8_t** out, size_t* out_len)
{
    if (n % 4 != 0)
        return _fail(p, "visdata_b64: bad base64 (length %zu is not a multiple of 4)", n);
    size_t pad = (n >= 1 && s[n - 1] == '=') + (n >= 2 && s[n - 2] == '=');
    uint8_t* buf = malloc(n / 4 * 3 + 1);
    if (!buf)
        return _fail(p, "out of memory decoding visdata_b64");
    size_t o = 0;
    for (size_t i = 0; i < n; i += 4) {
        uint32_t v = 0;
        for (size_t k = 0; k < 4; k++) {
            int d = _b64_value((unsigned char)s[i + k]);
            bool padding = s[i + k] == '=' && i + k >= n - pad;
            if (d < 0 && !padding) {
                free(buf);
                return _fail(p, "visdata_b64: bad base64 (character %zu is not in the alphabet)", i + k);
            }
            v = v << 6 | (uint32_t)(d < 0 ? 0 : d);
        }
        buf[o++] = (uint8_t)(v >> 16);
        buf[o++] = (uint8_t)(v >> 8);
        buf[o++] = (uint8_t)v;
    }
    *out = buf;
    *out_len = o - pad;
    return true;
}

/* The member `key` of object j, failing with "missing key" when absent and
 * "appears twice" when repeated (the reader keeps both; which one counts
 * would be arbitrary). */
static const tv_json* _member(const _ctx* c, const tv_json* j, const char* key, const char* where)
{
    const tv_json* found = NULL;
    for (int i = 0; i < j->count; i++) {
        if (strcmp(j->keys[i], key) != 0)
            continue;
        if (found) {
            _fail(c, "%s%s appears twice", where, key);
            return NULL;
        }
        found = &j->items[i];
    }
    if (!found)
        _fail(c, "%smissing key %s", where, key);
    return found;
}

static bool _number(const _ctx* c, const tv_json* j, const char* what, double* out)
{
    if (j->type != TV_JSON_NUMBER || !isfinite(j->num))
        return _fail(c, "%s is not a finite number", what);
    *out = j->num;
    return true;
}

static bool _vec3(const _ctx* c, const tv_json* j, uint32_t leaf, const char* key, float v[3])
{
    if (j->type != TV_JSON_ARRAY || j->count != 3)
        return _fail(c, "leaf %u: %s is not a 3-vector", leaf, key);
    for (int k = 0; k < 3; k++) {
        double d = 0.0;
        if (!_number(c, &j->items[k], key, &d))
            return false;
        if (fabs(d) > 1e30)
            return _fail(c, "leaf %u: coordinate %g out of range", leaf, d);
        v[k] = (float)d;
    }
    return true;
}

static bool _leaf(const _ctx* c, const tv_json* j, uint32_t i, uint32_t n_clusters, pvs_q3vis_leaf* out)
{
    char where[32];
    snprintf(where, sizeof where, "leaf %u: ", i);
    if (j->type != TV_JSON_OBJECT)
        return _fail(c, "leaf %u is not an object", i);
    const tv_json* cl = _member(c, j, "cluster", where);
    const tv_json* mn = cl ? _member(c, j, "min", where) : NULL;
    const tv_json* mx = mn ? _member(c, j, "max", where) : NULL;
    double cluster = 0.0;
    if (!mx || !_number(c, cl, "cluster", &cluster) || !_vec3(c, mn, i, "min", out->min) ||
        !_vec3(c, mx, i, "max", out->max))
        return false;
    if (cluster != floor(cluster) || cluster < -1.0 || cluster >= (double)n_clusters)
        return _fail(c, "leaf %u: cluster %g outside [-1, %u)", i, cluster, n_clusters);
    out->cluster = (int32_t)cluster;
    for (int k = 0; k < 3; k++)
        if (!(out->min[k] <= out->max[k]))
            return _fail(c, "leaf %u: box min exceeds max on axis %d", i, k);
    return true;
}

static bool _document(const _ctx* c, const tv_json* doc, pvs_q3vis* vis)
{
    if (doc->type != TV_JSON_OBJECT)
        return _fail(c, "the document is not an object");
    const tv_json* n = _member(c, doc, "n_clusters", "");
    const tv_json* b = n ? _member(c, doc, "bytes_per_cluster", "") : NULL;
    const tv_json* data = b ? _member(c, doc, "visdata_b64", "") : NULL;
    const tv_json* leafs = data ? _member(c, doc, "leafs", "") : NULL;
    double nc = 0.0, bpc = 0.0;
    if (!leafs || !_number(c, n, "n_clusters", &nc) || !_number(c, b, "bytes_per_cluster", &bpc))
        return false;
    if (nc != floor(nc) || nc < 1 || nc > MAX_CLUSTERS)
        return _fail(c, "n_clusters %g is not an integer in [1, %u]", nc, MAX_CLUSTERS);
    if (bpc != floor(bpc) || bpc < ceil(nc / 8.0) || bpc > MAX_CLUSTERS)
        return _fail(c, "bytes_per_cluster %g cannot hold %g clusters", bpc, nc);
    vis->n_clusters = (uint32_t)nc;
    vis->bytes_per_cluster = (uint32_t)bpc;
    if (data->type != TV_JSON_STRING)
        return _fail(c, "visdata_b64 is not a string");
    size_t len = 0;
    if (!_base64(c, data->str, strlen(data->str), &vis->visdata, &len))
        return false;
    size_t want = (size_t)vis->n_clusters * vis->bytes_per_cluster;
    if (len != want)
        return _fail(c, "visdata has %zu bytes, expected n_clusters * bytes_per_cluster = %zu", len, want);
    if (leafs->type != TV_JSON_ARRAY)
        return _fail(c, "leafs is not an array");
    if (leafs->count == 0)
        return _fail(c, "leafs is empty");
    vis->leaves = malloc((size_t)leafs->count * sizeof *vis->leaves);
    if (!vis->leaves)
        return _fail(c, "out of memory reading %d leaves", leafs->count);
    for (; vis->leaf_count < (uint32_t)leafs->count; vis->leaf_count++)
        if (!_leaf(c, &leafs->items[vis->leaf_count], vis->leaf_count, vis->n_clusters,
                   &vis->leaves[vis->leaf_count]))
            return false;
    return true;
}

bool pvs_q3vis_parse(const char* text, size_t len, const char* name, pvs_q3vis* out, char* err, size_t err_size)
{
    memset(out, 0, sizeof *out);
    _ctx c = {.name = name ? name : "q3vis", .err = err, .err_size = err_size};
    tv_json doc;
    bool ok = tv_json_parse(text ? text : "", text ? len : 0, c.name, &doc, err, err_size);
    if (ok) {
        ok = _document(&c, &doc, out);
        tv_json_free(&doc);
    }
    if (!ok)
        pvs_q3vis_free(out);
    return ok;
}

bool pvs_q3vis_load(const char* path, pvs_q3vis* out, char* err, size_t err_size)
{
    memset(out, 0, sizeof *out);
    FILE* f = fopen(path, "rb");
    if (!f) {
        snprintf(err, err_size, "%s: cannot open", path);
        return false;
    }
    char* text = NULL;
    long size = -1;
    if (fseek(f, 0, SEEK_END) == 0)
        size = ftell(f);
    bool ok = size >= 0 && fseek(f, 0, SEEK_SET) == 0 && (text = malloc((size_t)size + 1)) != NULL &&
              fread(text, 1, (size_t)size, f) == (size_t)size;
    fclose(f);
    if (!ok)
        snprintf(err, err_size, "%s: cannot read", path);
    else
        ok = pvs_q3vis_parse(text, (size_t)size, path, out, err, err_size);
    free(text);
    return ok;
}

void pvs_q3vis_free(pvs_q3vis* vis)
{
    free(vis->visdata);
    free(vis->leaves);
    memset(vis, 0, sizeof *vis);
}
