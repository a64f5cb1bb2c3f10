/* q3vis_parse.c - the .pvs.json reader: a small recursive-descent JSON parser
 * that understands exactly the keys it needs and skips (but still validates)
 * every other value, plus a strict base64 decoder. No DOM is built, so memory
 * use is bounded by the visdata and the leaf array. */
#include "q3vis.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_DEPTH 64             /* nesting limit of skipped values (fuzzed input) */
#define MAX_CLUSTERS (1u << 20)  /* far above any Quake 3 level (a few thousand) */

typedef struct _parser {
    const char* s;
    size_t len, pos;
    const char* name;
    char* err;
    size_t err_size;
    bool failed;
} _parser;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static bool _fail(_parser* p, const char* fmt, ...)
{
    if (p->failed)
        return false; /* keep the first, most specific message */
    p->failed = true;
    char msg[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    snprintf(p->err, p->err_size, "%s: %s", p->name, msg);
    return false;
}

static bool _syntax(_parser* p, const char* what)
{
    if (p->pos >= p->len)
        return _fail(p, "unexpected end of file, expected %s", what);
    return _fail(p, "byte %zu: expected %s", p->pos, what);
}

static void _ws(_parser* p)
{
    while (p->pos < p->len &&
           (p->s[p->pos] == ' ' || p->s[p->pos] == '\t' || p->s[p->pos] == '\n' || p->s[p->pos] == '\r'))
        p->pos++;
}

static bool _peek(_parser* p, char c)
{
    _ws(p);
    return p->pos < p->len && p->s[p->pos] == c;
}

static bool _expect(_parser* p, char c, const char* what)
{
    if (!_peek(p, c))
        return _syntax(p, what);
    p->pos++;
    return true;
}

/* A string's raw span (between the quotes, escapes left in place). */
static bool _string(_parser* p, const char** start, size_t* n)
{
    if (!_expect(p, '"', "a string"))
        return false;
    size_t b = p->pos;
    while (p->pos < p->len && p->s[p->pos] != '"') {
        unsigned char c = (unsigned char)p->s[p->pos];
        if (c < 0x20)
            return _fail(p, "byte %zu: control character in a string", p->pos);
        if (c == '\\') {
            p->pos++;
            if (p->pos >= p->len || !strchr("\"\\/bfnrtu", p->s[p->pos]))
                return _syntax(p, "an escape character");
        }
        p->pos++;
    }
    if (p->pos >= p->len)
        return _syntax(p, "a closing quote");
    *start = p->s + b;
    *n = p->pos - b;
    p->pos++;
    return true;
}

static bool _number(_parser* p, double* out)
{
    _ws(p);
    size_t b = p->pos;
    while (p->pos < p->len && strchr("+-0123456789.eE", p->s[p->pos]) && p->s[p->pos] != '\0')
        p->pos++;
    char buf[64];
    size_t n = p->pos - b;
    if (n == 0 || n >= sizeof buf) {
        p->pos = b;
        return _syntax(p, "a number");
    }
    memcpy(buf, p->s + b, n);
    buf[n] = '\0';
    char* end;
    *out = strtod(buf, &end);
    if (*end != '\0' || !isfinite(*out)) {
        p->pos = b;
        return _syntax(p, "a finite number");
    }
    return true;
}

static bool _literal(_parser* p, const char* word)
{
    size_t n = strlen(word);
    if (p->len - p->pos < n || memcmp(p->s + p->pos, word, n) != 0)
        return _syntax(p, "a value");
    p->pos += n;
    return true;
}

static bool _skip_value(_parser* p, int depth);

/* Calls member(p, key, key_len, user) for each key of an object, with the
 * cursor on the value; member must consume the value. */
typedef bool (*_member_fn)(_parser* p, const char* key, size_t key_len, void* user);

static bool _object(_parser* p, _member_fn member, void* user)
{
    if (!_expect(p, '{', "'{'"))
        return false;
    if (_peek(p, '}')) {
        p->pos++;
        return true;
    }
    for (;;) {
        const char* key;
        size_t n;
        if (!_string(p, &key, &n) || !_expect(p, ':', "':'") || !member(p, key, n, user))
            return false;
        if (_peek(p, ',')) {
            p->pos++;
            continue;
        }
        return _expect(p, '}', "',' or '}'");
    }
}

/* Calls element(p, index, user) for each array element, cursor on it. */
typedef bool (*_element_fn)(_parser* p, uint32_t index, void* user);

static bool _array(_parser* p, _element_fn element, void* user)
{
    if (!_expect(p, '[', "'['"))
        return false;
    if (_peek(p, ']')) {
        p->pos++;
        return true;
    }
    for (uint32_t i = 0;; i++) {
        if (i == UINT32_MAX)
            return _fail(p, "byte %zu: array too long", p->pos);
        if (!element(p, i, user))
            return false;
        if (_peek(p, ',')) {
            p->pos++;
            continue;
        }
        return _expect(p, ']', "',' or ']'");
    }
}

typedef struct _skip_ctx {
    int depth;
} _skip_ctx;

static bool _skip_member(_parser* p, const char* key, size_t n, void* user)
{
    (void)key, (void)n;
    return _skip_value(p, ((_skip_ctx*)user)->depth);
}

static bool _skip_element(_parser* p, uint32_t i, void* user)
{
    (void)i;
    return _skip_value(p, ((_skip_ctx*)user)->depth);
}

static bool _skip_value(_parser* p, int depth)
{
    if (depth > MAX_DEPTH)
        return _fail(p, "byte %zu: nesting deeper than %d", p->pos, MAX_DEPTH);
    _ws(p);
    if (p->pos >= p->len)
        return _syntax(p, "a value");
    _skip_ctx sub = {depth + 1};
    const char* s;
    size_t n;
    double d;
    switch (p->s[p->pos]) {
    case '{': return _object(p, _skip_member, &sub);
    case '[': return _array(p, _skip_element, &sub);
    case '"': return _string(p, &s, &n);
    case 't': return _literal(p, "true");
    case 'f': return _literal(p, "false");
    case 'n': return _literal(p, "null");
    default: return _number(p, &d);
    }
}

static bool _key_is(const char* key, size_t n, const char* want)
{
    return strlen(want) == n && memcmp(key, want, n) == 0;
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
static bool _base64(_parser* p, const char* s, size_t n, uint8_t** out, size_t* out_len)
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

typedef struct _doc {
    pvs_q3vis* vis;
    double n_clusters, bytes_per_cluster;
    bool has_n, has_bytes, has_leafs;
    uint8_t* visdata;
    size_t visdata_len;
    uint32_t leaf_cap;
    /* the leaf being read */
    pvs_q3vis_leaf leaf;
    bool has_cluster, has_min, has_max;
} _doc;

static bool _vec3(_parser* p, float v[3])
{
    if (!_expect(p, '[', "'[' of a 3-vector"))
        return false;
    for (int k = 0; k < 3; k++) {
        double d;
        if (k > 0 && !_expect(p, ',', "',' in a 3-vector"))
            return false;
        if (!_number(p, &d))
            return false;
        if (fabs(d) > 1e30)
            return _fail(p, "byte %zu: coordinate %g out of range", p->pos, d);
        v[k] = (float)d;
    }
    return _expect(p, ']', "']' closing a 3-vector");
}

static bool _leaf_member(_parser* p, const char* key, size_t n, void* user)
{
    _doc* d = user;
    if (_key_is(key, n, "cluster")) {
        double c;
        if (!_number(p, &c))
            return false;
        if (c != floor(c) || c < -1.0 || c > 2147483647.0)
            return _fail(p, "byte %zu: leaf cluster %g is not an integer >= -1", p->pos, c);
        d->leaf.cluster = (int32_t)c;
        d->has_cluster = true;
        return true;
    }
    if (_key_is(key, n, "min")) {
        d->has_min = true;
        return _vec3(p, d->leaf.min);
    }
    if (_key_is(key, n, "max")) {
        d->has_max = true;
        return _vec3(p, d->leaf.max);
    }
    _skip_ctx sub = {2};
    return _skip_member(p, key, n, &sub);
}

static bool _leaf(_parser* p, uint32_t i, void* user)
{
    _doc* d = user;
    d->has_cluster = d->has_min = d->has_max = false;
    if (!_object(p, _leaf_member, d))
        return false;
    if (!d->has_cluster || !d->has_min || !d->has_max)
        return _fail(p, "leaf %u lacks %s", i, !d->has_cluster ? "cluster" : !d->has_min ? "min" : "max");
    for (int k = 0; k < 3; k++)
        if (!(d->leaf.min[k] <= d->leaf.max[k]))
            return _fail(p, "leaf %u: box min exceeds max on axis %d", i, k);
    pvs_q3vis* vis = d->vis;
    if (vis->leaf_count == d->leaf_cap) {
        uint32_t cap = d->leaf_cap ? 2 * d->leaf_cap : 256;
        pvs_q3vis_leaf* grown = cap > d->leaf_cap ? realloc(vis->leaves, cap * sizeof *grown) : NULL;
        if (!grown)
            return _fail(p, "out of memory reading leaf %u", i);
        vis->leaves = grown;
        d->leaf_cap = cap;
    }
    vis->leaves[vis->leaf_count++] = d->leaf;
    return true;
}

static bool _top_member(_parser* p, const char* key, size_t n, void* user)
{
    _doc* d = user;
    if (_key_is(key, n, "n_clusters")) {
        d->has_n = true;
        return _number(p, &d->n_clusters);
    }
    if (_key_is(key, n, "bytes_per_cluster")) {
        d->has_bytes = true;
        return _number(p, &d->bytes_per_cluster);
    }
    if (_key_is(key, n, "visdata_b64")) {
        const char* s;
        size_t len;
        if (d->visdata)
            return _fail(p, "visdata_b64 appears twice");
        return _string(p, &s, &len) && _base64(p, s, len, &d->visdata, &d->visdata_len);
    }
    if (_key_is(key, n, "leafs")) {
        if (d->has_leafs)
            return _fail(p, "leafs appears twice");
        d->has_leafs = true;
        return _array(p, _leaf, d);
    }
    _skip_ctx sub = {1};
    return _skip_member(p, key, n, &sub);
}

/* Cross-field checks once the whole document is read. */
static bool _validate(_parser* p, _doc* d)
{
    if (!d->has_n || !d->has_bytes || !d->visdata || !d->has_leafs)
        return _fail(p, "missing key %s",
                     !d->has_n ? "n_clusters" : !d->has_bytes ? "bytes_per_cluster" : !d->visdata ? "visdata_b64"
                                                                                                 : "leafs");
    double nc = d->n_clusters, bpc = d->bytes_per_cluster;
    if (nc != floor(nc) || nc < 1 || nc > MAX_CLUSTERS)
        return _fail(p, "n_clusters %g is not an integer in [1, %u]", nc, MAX_CLUSTERS);
    if (bpc != floor(bpc) || bpc < ceil(nc / 8.0) || bpc > MAX_CLUSTERS)
        return _fail(p, "bytes_per_cluster %g cannot hold %g clusters", bpc, nc);
    pvs_q3vis* vis = d->vis;
    vis->n_clusters = (uint32_t)nc;
    vis->bytes_per_cluster = (uint32_t)bpc;
    size_t want = (size_t)vis->n_clusters * vis->bytes_per_cluster;
    if (d->visdata_len != want)
        return _fail(p, "visdata has %zu bytes, expected n_clusters * bytes_per_cluster = %zu", d->visdata_len,
                     want);
    if (vis->leaf_count == 0)
        return _fail(p, "leafs is empty");
    for (uint32_t i = 0; i < vis->leaf_count; i++)
        if (vis->leaves[i].cluster >= (int32_t)vis->n_clusters)
            return _fail(p, "leaf %u: cluster %d outside [-1, %u)", i, vis->leaves[i].cluster, vis->n_clusters);
    vis->visdata = d->visdata;
    d->visdata = NULL;
    return true;
}

bool pvs_q3vis_parse(const char* text, size_t len, const char* name, pvs_q3vis* out, char* err, size_t err_size)
{
    memset(out, 0, sizeof *out);
    _parser p = {.s = text, .len = text ? len : 0, .name = name ? name : "q3vis", .err = err,
                 .err_size = err_size};
    _doc d = {.vis = out};
    bool ok = _object(&p, _top_member, &d) && _validate(&p, &d);
    if (ok) {
        _ws(&p);
        if (p.pos != p.len)
            ok = _fail(&p, "byte %zu: trailing characters after the top-level object", p.pos);
    }
    free(d.visdata);
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
