#define _POSIX_C_SOURCE 200809L
#include "gt_cache.h"

#include "fs.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define MAGIC "trimvr-gt-cache\n"
#define MAGIC_LEN 16

/* FNV-1a's prime on 8-byte words: fast enough for the textures of Sponza,
 * and a file's key is compared in full anyway. */
static uint64_t hash_bytes(uint64_t h, const void* data, size_t n)
{
    const uint8_t* p = data;
    for (; n >= 8; n -= 8, p += 8) {
        uint64_t w;
        memcpy(&w, p, 8);
        h = (h ^ w) * 0x100000001b3ull;
        h ^= h >> 29;
    }
    for (; n > 0; n--, p++)
        h = (h ^ *p) * 0x100000001b3ull;
    return h;
}

void pvs_gt_scene_id(const scn_scene* scene, const char* spec, const char* device, char* out, size_t size)
{
    uint64_t h = 0xcbf29ce484222325ull;
    h = hash_bytes(h, scene->positions, (size_t)scene->vertex_count * 3 * sizeof(float));
    h = hash_bytes(h, scene->uvs, (size_t)scene->vertex_count * 2 * sizeof(float));
    h = hash_bytes(h, scene->indices, (size_t)scene->triangle_count * 3 * sizeof(uint32_t));
    h = hash_bytes(h, scene->tri_material, (size_t)scene->triangle_count * sizeof(uint32_t));
    for (uint32_t m = 0; m < scene->material_count; m++) {
        const scn_material* mat = &scene->materials[m];
        int32_t rule[4] = {mat->texture, (int32_t)mat->alpha_mode, mat->double_sided, 0};
        memcpy(&rule[3], &mat->alpha_cutoff, sizeof(float));
        h = hash_bytes(h, rule, sizeof rule);
    }
    for (uint32_t t = 0; t < scene->texture_count; t++) {
        const scn_texture* tex = &scene->textures[t];
        h = hash_bytes(h, &tex->width, sizeof tex->width);
        h = hash_bytes(h, &tex->height, sizeof tex->height);
        h = hash_bytes(h, tex->rgba8, (size_t)tex->width * tex->height * 4);
    }
    snprintf(out, size, "spec=%s;scene=%016llx;tris=%u;dynamic=%u;device=%s", spec, (unsigned long long)h,
             scene->triangle_count, scene->dynamic_triangle_count, device);
}

void pvs_gt_cache_key(const char* scene_id, const pred_viewcell* vc, const pvs_eval_desc* d, char* key, size_t size)
{
    /* %a: floats exactly, so a key never matches a different viewcell */
    snprintf(key, size,
             "version=%d;%s;v0=%a,%a,%a;forward=%a,%a,%a;up=%a,%a,%a;delta=%a;z=%a;fov-target=%a;fov-pvs=%a;"
             "frusta=%d;samples=%u;res=%ux%u;eye-fov=%a;near=%a;far=%a;seed=%u",
             PVS_GT_CACHE_VERSION, scene_id, vc->v0[0], vc->v0[1], vc->v0[2], vc->forward[0], vc->forward[1],
             vc->forward[2], vc->up[0], vc->up[1], vc->up[2], vc->delta, vc->z, vc->fov_target_deg,
             vc->fov_pvs_deg, vc->frusta, d->samples, d->width, d->height, d->eye_fov_h_deg, d->near_m, d->far_m,
             d->seed);
}

void pvs_gt_cache_file(const char* dir, const char* key, char* file, size_t size)
{
    snprintf(file, size, "%s/gt-%016llx.bin", dir,
             (unsigned long long)hash_bytes(0xcbf29ce484222325ull, key, strlen(key)));
}

bool pvs_gt_record_add_view(pvs_gt_record* r, const uint32_t* ids, const uint32_t* pixels, uint32_t count)
{
    if (r->entry_count + (uint64_t)count > r->entry_cap) {
        uint64_t cap = r->entry_cap ? r->entry_cap : 4096;
        while (cap < r->entry_count + (uint64_t)count)
            cap *= 2;
        if (cap > UINT32_MAX)
            return false;
        uint32_t* i = realloc(r->ids, cap * sizeof *i);
        if (i)
            r->ids = i;
        uint32_t* p = realloc(r->pixels, cap * sizeof *p);
        if (p)
            r->pixels = p;
        if (!i || !p)
            return false;
        r->entry_cap = (uint32_t)cap;
    }
    uint32_t* first = realloc(r->view_first, (r->views + 2) * sizeof *first);
    if (!first)
        return false;
    r->view_first = first;
    first[r->views] = r->entry_count;
    if (count) { /* an empty view may pass NULL */
        memcpy(r->ids + r->entry_count, ids, count * sizeof *ids);
        memcpy(r->pixels + r->entry_count, pixels, count * sizeof *pixels);
    }
    r->entry_count += count;
    first[++r->views] = r->entry_count;
    return true;
}

void pvs_gt_record_free(pvs_gt_record* r)
{
    free(r->view_first);
    free(r->ids);
    free(r->pixels);
    *r = (pvs_gt_record){0};
}

/* The body after the header: per view its entry count, then each entry's id
 * as the gap from the previous one and its pixels, all LEB128 varints (ids
 * ascend, so gaps are small). */
typedef struct buf {
    uint8_t* p;
    size_t n, cap;
} buf;

static bool put(buf* b, const void* data, size_t n)
{
    if (b->n + n > b->cap) {
        size_t cap = b->cap ? b->cap : 1 << 16;
        while (cap < b->n + n)
            cap *= 2;
        uint8_t* p = realloc(b->p, cap);
        if (!p)
            return false;
        b->p = p;
        b->cap = cap;
    }
    memcpy(b->p + b->n, data, n);
    b->n += n;
    return true;
}

static bool put_varint(buf* b, uint32_t v)
{
    uint8_t out[5];
    size_t n = 0;
    do {
        out[n++] = (uint8_t)((v & 0x7f) | (v >= 0x80 ? 0x80 : 0));
        v >>= 7;
    } while (v);
    return put(b, out, n);
}

static bool get_varint(const uint8_t** p, const uint8_t* end, uint32_t* v)
{
    uint64_t x = 0;
    for (int shift = 0; shift < 35 && *p < end; shift += 7) {
        uint8_t c = *(*p)++;
        x |= (uint64_t)(c & 0x7f) << shift;
        if (!(c & 0x80)) {
            *v = (uint32_t)x;
            return x <= UINT32_MAX;
        }
    }
    return false;
}

bool pvs_gt_cache_store(const char* file, const char* key, const pvs_gt_record* r, char* err, size_t err_size)
{
    buf b = {0};
    uint32_t key_len = (uint32_t)strlen(key);
    bool ok = put(&b, MAGIC, MAGIC_LEN) && put(&b, &key_len, 4) && put(&b, key, key_len) && put(&b, &r->views, 4) &&
              put(&b, &r->gt_ms, 8) && put(&b, &r->full_render_ms, 8);
    for (uint32_t v = 0; ok && v < r->views; v++) {
        ok = put_varint(&b, r->view_first[v + 1] - r->view_first[v]);
        for (uint32_t e = r->view_first[v], prev = 0; ok && e < r->view_first[v + 1]; prev = r->ids[e++])
            ok = put_varint(&b, r->ids[e] - prev) && put_varint(&b, r->pixels[e]);
    }
    uint64_t sum = hash_bytes(0xcbf29ce484222325ull, b.p, b.n);
    ok = ok && put(&b, &sum, 8);
    char dir[4096], tmp[4200];
    snprintf(dir, sizeof dir, "%s", file);
    char* slash = strrchr(dir, '/');
    if (slash)
        *slash = '\0';
    snprintf(tmp, sizeof tmp, "%s.tmp-%ld", file, (long)getpid());
    FILE* f = NULL;
    if (!ok)
        snprintf(err, err_size, "out of memory");
    else if ((slash && !tv_mkdirs(dir)) || !(f = fopen(tmp, "wb"))) {
        snprintf(err, err_size, "cannot create %s: %s", slash ? tmp : file, strerror(errno));
        ok = false;
    } else {
        ok = fwrite(b.p, 1, b.n, f) == b.n;
        ok = (fclose(f) == 0) && ok;
        if (!ok || rename(tmp, file) != 0) {
            snprintf(err, err_size, "cannot write %s: %s", file, strerror(errno));
            remove(tmp);
            ok = false;
        }
    }
    free(b.p);
    return ok;
}

static bool reject(char* why, size_t size, const char* reason)
{
    snprintf(why, size, "%s", reason);
    return false;
}

static bool parse(const uint8_t* p, size_t n, const char* key, uint32_t scene_tris, pvs_gt_record* out, char* why,
                  size_t why_size)
{
    uint32_t key_len, views;
    if (n < MAGIC_LEN + 4 + 8 || memcmp(p, MAGIC, MAGIC_LEN) != 0)
        return reject(why, why_size, "not a ground-truth cache file");
    const uint8_t* end = p + n - 8;
    uint64_t sum;
    memcpy(&sum, end, 8);
    if (sum != hash_bytes(0xcbf29ce484222325ull, p, n - 8))
        return reject(why, why_size, "checksum mismatch (damaged or truncated)");
    p += MAGIC_LEN;
    memcpy(&key_len, p, 4);
    p += 4;
    if ((size_t)(end - p) < (size_t)key_len + 20 || key_len != strlen(key) || memcmp(p, key, key_len) != 0)
        return reject(why, why_size, "written for another scene, viewcell or setting (key differs)");
    p += key_len;
    memcpy(&views, p, 4);
    memcpy(&out->gt_ms, p + 4, 8);
    memcpy(&out->full_render_ms, p + 12, 8);
    p += 20;
    for (uint32_t v = 0; v < views; v++) {
        uint32_t count, id = 0, gap = 0, px = 0;
        if (!get_varint(&p, end, &count) || count > scene_tris)
            return reject(why, why_size, "malformed view list");
        uint32_t* ids = malloc((count ? count : 1) * sizeof *ids);
        uint32_t* pixels = malloc((count ? count : 1) * sizeof *pixels);
        bool ok = ids && pixels;
        for (uint32_t e = 0; ok && e < count; e++) {
            ok = get_varint(&p, end, &gap) && get_varint(&p, end, &px) && (e == 0 || gap > 0) &&
                 (uint64_t)id + gap < scene_tris;
            id += gap;
            ids[e] = id;
            pixels[e] = px;
        }
        ok = ok && pvs_gt_record_add_view(out, ids, pixels, count);
        free(ids);
        free(pixels);
        if (!ok)
            return reject(why, why_size, "malformed view list or out of memory");
    }
    if (p != end)
        return reject(why, why_size, "trailing bytes");
    return true;
}

bool pvs_gt_cache_load(const char* file, const char* key, uint32_t scene_tris, pvs_gt_record* out, char* why,
                       size_t why_size)
{
    *out = (pvs_gt_record){0};
    why[0] = '\0';
    FILE* f = fopen(file, "rb");
    if (!f)
        return errno == ENOENT ? false : reject(why, why_size, strerror(errno));
    uint8_t* data = NULL;
    long n = -1;
    if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0 &&
        (data = malloc(n ? (size_t)n : 1)) && fread(data, 1, (size_t)n, f) != (size_t)n)
        n = -1;
    fclose(f);
    bool ok = n >= 0 && data ? parse(data, (size_t)n, key, scene_tris, out, why, why_size)
                             : reject(why, why_size, "cannot read it");
    free(data);
    if (!ok)
        pvs_gt_record_free(out);
    return ok;
}
