#define _DEFAULT_SOURCE /* mkdtemp, truncate */
/* glTF loading: a hand-written file exercising transforms, winding, index
 * types and normal generation, and every bad input the loader must reject. */
#include "image_io.h"
#include "scene.h"
#include "scene_test_dir.h"
#include "test.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[256];

/* Binary layout (offsets in bytes), one buffer view per block:
 *   0 quad positions (4 x vec3)   48 quad normals   96 quad uvs (float)
 * 128 triangle positions (3)     164 u16 indices (6) 176 u32 indices (9)
 * 212 u16 normalized uvs (4 x 2) 228 end */
#define BIN_SIZE 228
static uint8_t bin[BIN_SIZE];

static void make_bin(void)
{
    const float quad[12] = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
    const float normals[12] = { 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1 };
    const float uvs[8] = { 0, 0, 1, 0, 1, 1, 0, 1 };
    const float tri[9] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
    const uint16_t i16[6] = { 0, 1, 2, 0, 2, 3 };
    const uint32_t i32[9] = { 0, 1, 2, 0, 2, 3, 0, 0, 1 }; /* last one degenerate */
    const uint16_t uv16[8] = { 0, 0, 65535, 0, 65535, 65535, 0, 65535 };
    memcpy(bin + 0, quad, 48);
    memcpy(bin + 48, normals, 48);
    memcpy(bin + 96, uvs, 32);
    memcpy(bin + 128, tri, 36);
    memcpy(bin + 164, i16, 12);
    memcpy(bin + 176, i32, 36);
    memcpy(bin + 212, uv16, 16);
}

/* The JSON, with the POSITION count of accessor 0, the buffer entry and the
 * images array as knobs for the bad-input variants. */
static void make_json(char* out, size_t size, int quad_count, const char* buffer, const char* images)
{
    snprintf(out, size,
        "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
        "\"nodes\":["
        "{\"translation\":[10,0,0],\"children\":[1,2],\"mesh\":0},"
        "{\"rotation\":[0,0.70710678,0,0.70710678],\"scale\":[2,2,2],\"mesh\":1},"
        "{\"matrix\":[-1,0,0,0, 0,1,0,0, 0,0,1,0, 0,5,0,1],\"mesh\":2}],"
        "\"meshes\":["
        "{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2},\"indices\":4,\"material\":0}]},"
        "{\"primitives\":[{\"attributes\":{\"POSITION\":3}}]},"
        "{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":6},\"indices\":5,\"mode\":4},"
        "{\"attributes\":{\"POSITION\":3},\"mode\":1}]}],"
        "\"materials\":[{\"name\":\"mat0\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,0.5,0.25,1]%s},"
        "\"alphaMode\":\"MASK\",\"alphaCutoff\":0.3,\"doubleSided\":true}],"
        "%s"
        "\"buffers\":[%s],"
        "\"bufferViews\":["
        "{\"buffer\":0,\"byteOffset\":0,\"byteLength\":48},{\"buffer\":0,\"byteOffset\":48,\"byteLength\":48},"
        "{\"buffer\":0,\"byteOffset\":96,\"byteLength\":32},{\"buffer\":0,\"byteOffset\":128,\"byteLength\":36},"
        "{\"buffer\":0,\"byteOffset\":164,\"byteLength\":12},{\"buffer\":0,\"byteOffset\":176,\"byteLength\":36},"
        "{\"buffer\":0,\"byteOffset\":212,\"byteLength\":16}],"
        "\"accessors\":["
        "{\"bufferView\":0,\"componentType\":5126,\"count\":%d,\"type\":\"VEC3\"},"
        "{\"bufferView\":1,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\"},"
        "{\"bufferView\":2,\"componentType\":5126,\"count\":4,\"type\":\"VEC2\"},"
        "{\"bufferView\":3,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
        "{\"bufferView\":4,\"componentType\":5123,\"count\":6,\"type\":\"SCALAR\"},"
        "{\"bufferView\":5,\"componentType\":5125,\"count\":9,\"type\":\"SCALAR\"},"
        "{\"bufferView\":6,\"componentType\":5123,\"normalized\":true,\"count\":4,\"type\":\"VEC2\"}]}",
        images ? ",\"baseColorTexture\":{\"index\":0}" : "", images ? images : "", buffer, quad_count);
}

static void write_file(const char* path, const void* data, size_t size)
{
    FILE* f = fopen(path, "wb");
    TV_CHECK(f != NULL);
    if (!f)
        return;
    fwrite(data, 1, size, f);
    fclose(f);
}

/* Writes name.gltf + name.bin; returns the .gltf path in `path`. */
static void write_gltf(char* path, size_t size, const char* name, int quad_count, const char* images,
                       const uint8_t* data)
{
    char json[16384], buffer[256], bin_path[512];
    snprintf(buffer, sizeof buffer, "{\"uri\":\"%s.bin\",\"byteLength\":%d}", name, BIN_SIZE);
    make_json(json, sizeof json, quad_count, buffer, images);
    snprintf(path, size, "%s/%s.gltf", dir, name);
    snprintf(bin_path, sizeof bin_path, "%s/%s.bin", dir, name);
    write_file(path, json, strlen(json));
    write_file(bin_path, data, BIN_SIZE);
}

static void put_u32(uint8_t* p, uint32_t v)
{
    memcpy(p, &v, 4);
}

/* Writes name.glb (JSON chunk + BIN chunk); returns its size. */
static size_t write_glb(char* path, size_t size, const char* name)
{
    char json[16384], buffer[64];
    snprintf(buffer, sizeof buffer, "{\"byteLength\":%d}", BIN_SIZE);
    make_json(json, sizeof json, 4, buffer, NULL);
    size_t jlen = strlen(json), jpad = (jlen + 3) & ~(size_t)3, total = 12 + 8 + jpad + 8 + BIN_SIZE;
    uint8_t* glb = calloc(1, total);
    memcpy(glb, "glTF", 4);
    put_u32(glb + 4, 2);
    put_u32(glb + 8, (uint32_t)total);
    put_u32(glb + 12, (uint32_t)jpad);
    memcpy(glb + 16, "JSON", 4);
    memset(glb + 20, ' ', jpad);
    memcpy(glb + 20, json, jlen);
    put_u32(glb + 20 + jpad, BIN_SIZE);
    memcpy(glb + 24 + jpad, "BIN\0", 4);
    memcpy(glb + 28 + jpad, bin, BIN_SIZE);
    snprintf(path, size, "%s/%s.glb", dir, name);
    write_file(path, glb, total);
    free(glb);
    return total;
}

static const float* vtx(const scn_scene* s, uint32_t t, int c)
{
    return s->positions + 3 * (size_t)s->indices[3 * t + c];
}

static void face_normal(const scn_scene* s, uint32_t t, float n[3])
{
    const float *a = vtx(s, t, 0), *b = vtx(s, t, 1), *c = vtx(s, t, 2);
    float e1[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, e2[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3; k++)
        n[k] /= len;
}

static void check_scene(const scn_scene* s)
{
    /* 2 (mesh 0) + 1 (mesh 1; the LINES primitive is skipped) + 2 (mesh 2; one degenerate dropped) */
    TV_CHECK(s->triangle_count == 5);
    TV_CHECK(s->degenerate_dropped == 1);
    if (s->triangle_count != 5)
        return;
    float n[3];
    /* mesh 0: translated by +10 x, faces +z, given normals */
    TV_CHECK_NEAR(vtx(s, 0, 1)[0], 11.0, 1e-6);
    face_normal(s, 0, n);
    TV_CHECK_NEAR(n[2], 1.0, 1e-6);
    TV_CHECK_NEAR(s->normals[3 * s->indices[0] + 2], 1.0, 1e-6);
    /* mesh 1: R_y(90) S(2) then +10 x: (1,0,0) -> (10,0,-2); faces +x; normal generated */
    const float* p = vtx(s, 2, 1);
    TV_CHECK_NEAR(p[0], 10.0, 1e-5);
    TV_CHECK_NEAR(p[1], 0.0, 1e-5);
    TV_CHECK_NEAR(p[2], -2.0, 1e-5);
    TV_CHECK_NEAR(vtx(s, 2, 2)[1], 2.0, 1e-5);
    face_normal(s, 2, n);
    TV_CHECK_NEAR(n[0], 1.0, 1e-5);
    TV_CHECK_NEAR(s->normals[3 * s->indices[7] + 0], 1.0, 1e-5); /* corner 0 welds with mesh 0: smoothed */
    /* mesh 2: mirrored in x (det < 0) and lifted 5: winding flipped so it still faces +z */
    for (uint32_t t = 3; t < 5; t++) {
        face_normal(s, t, n);
        TV_CHECK_NEAR(n[2], 1.0, 1e-6);
        for (int c = 0; c < 3; c++) {
            TV_CHECK(vtx(s, t, c)[0] >= 9.0f && vtx(s, t, c)[0] <= 10.0f);
            TV_CHECK(vtx(s, t, c)[1] >= 5.0f && vtx(s, t, c)[1] <= 6.0f);
            TV_CHECK_NEAR(s->normals[3 * s->indices[3 * t + c] + 2], 1.0, 1e-6);
        }
    }
    /* normalized u16 uvs of mesh 2 decode to [0, 1] */
    uint32_t v = s->indices[3 * 3 + 0];
    TV_CHECK(s->uvs[2 * v] == 0.0f || s->uvs[2 * v] == 1.0f);
    bool saw_one = false;
    for (int c = 0; c < 3; c++)
        saw_one |= s->uvs[2 * s->indices[9 + c]] == 1.0f;
    TV_CHECK(saw_one);
    /* material: mesh 0's glTF material, the others the default */
    TV_CHECK(s->tri_material[0] != s->tri_material[2]);
    const scn_material* m = &s->materials[s->tri_material[0]];
    TV_CHECK(strcmp(m->name, "mat0") == 0);
    TV_CHECK_NEAR(m->base_color[1], 0.5, 1e-6);
    TV_CHECK(m->alpha_mode == SCN_ALPHA_MASK);
    TV_CHECK_NEAR(m->alpha_cutoff, 0.3, 1e-6);
    TV_CHECK(m->double_sided);
    TV_CHECK_NEAR(s->bounds_min[0], 9.0, 1e-5);
    TV_CHECK_NEAR(s->bounds_max[0], 11.0, 1e-5);
    TV_CHECK_NEAR(s->bounds_min[2], -2.0, 1e-5);
}

static void test_gltf_roundtrip(void)
{
    char path[512], err[512];
    write_gltf(path, sizeof path, "good", 4, NULL, bin);
    scn_scene s;
    TV_CHECK(scn_load(path, &s, err, sizeof err));
    check_scene(&s);
    TV_CHECK(strcmp(s.name, "good.gltf") == 0);
    scn_scene_free(&s);
}

static void test_glb_roundtrip(void)
{
    char path[512], err[512];
    write_glb(path, sizeof path, "good");
    scn_scene s;
    TV_CHECK(scn_load(path, &s, err, sizeof err));
    check_scene(&s);
    scn_scene_free(&s);
}

static void test_texture(void)
{
    uint8_t px[4 * 2 * 3] = { 255, 0, 0, 0, 255, 0, 0, 0, 255, 9, 9, 9, 20, 30, 40, 50, 60, 70 };
    char png[512], path[512], err[512];
    snprintf(png, sizeof png, "%s/tex.png", dir);
    TV_CHECK(scn_image_write_png(png, px, 4, 2, 3, err, sizeof err));
    write_gltf(path, sizeof path, "textured", 4, "\"textures\":[{\"source\":0}],\"images\":[{\"uri\":\"tex.png\"}],", bin);
    scn_scene s;
    TV_CHECK(scn_load(path, &s, err, sizeof err));
    TV_CHECK(s.texture_count == 1);
    if (s.texture_count == 1) {
        TV_CHECK(s.textures[0].width == 4 && s.textures[0].height == 2);
        TV_CHECK(s.textures[0].rgba8[4] == 0 && s.textures[0].rgba8[5] == 255 && s.textures[0].rgba8[7] == 255);
        TV_CHECK(s.textures[0].rgba8[4 * 5 + 1] == 60);
        TV_CHECK(s.materials[s.tri_material[0]].texture == 0);
    }
    scn_scene_free(&s);
}

static void base64(const uint8_t* in, size_t n, char* out)
{
    static const char abc[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (size_t i = 0; i < n; i += 3) {
        uint32_t v = (uint32_t)in[i] << 16 | (i + 1 < n ? (uint32_t)in[i + 1] << 8 : 0) | (i + 2 < n ? in[i + 2] : 0);
        *out++ = abc[v >> 18];
        *out++ = abc[(v >> 12) & 63];
        *out++ = i + 1 < n ? abc[(v >> 6) & 63] : '=';
        *out++ = i + 2 < n ? abc[v & 63] : '=';
    }
    *out = '\0';
}

static void test_embedded_texture(void)
{
    /* a data: URI image decodes through the same OpenImageIO path, from memory */
    uint8_t px[4 * 2 * 2] = { 1, 2, 3, 255, 4, 5, 6, 128, 7, 8, 9, 0, 10, 11, 12, 255 };
    char png[512], path[512], err[512];
    snprintf(png, sizeof png, "%s/embedded_src.png", dir);
    TV_CHECK(scn_image_write_png(png, px, 2, 2, 4, err, sizeof err));
    uint8_t file[2048];
    FILE* f = fopen(png, "rb");
    size_t n = f ? fread(file, 1, sizeof file, f) : 0;
    if (f)
        fclose(f);
    char b64[4096], images[4400];
    base64(file, n, b64);
    snprintf(images, sizeof images, "\"textures\":[{\"source\":0}],\"images\":[{\"uri\":\"data:image/png;base64,%s\"}],", b64);
    write_gltf(path, sizeof path, "embedded", 4, images, bin);
    scn_scene s;
    TV_CHECK(scn_load(path, &s, err, sizeof err));
    TV_CHECK(s.texture_count == 1);
    if (s.texture_count == 1)
        TV_CHECK(memcmp(s.textures[0].rgba8, px, sizeof px) == 0); /* alpha kept unassociated */
    scn_scene_free(&s);
}

/* Loading must fail, name the file and the problem (`expect`, NULL: any),
 * stay on one line and leave the scene empty. */
static void expect_failure(const char* path, const char* what, const char* expect)
{
    char err[512];
    scn_scene s;
    memset(&s, 0xAB, sizeof s);
    bool ok = scn_load(path, &s, err, sizeof err);
    TV_CHECK(!ok);
    TV_CHECK(strstr(err, path) != NULL);
    TV_CHECK(strchr(err, '\n') == NULL);
    TV_CHECK(!expect || strstr(err, expect));
    TV_CHECK(s.triangle_count == 0 && s.positions == NULL && s.materials == NULL);
    printf("     %s -> %s\n", what, err);
    if (ok)
        scn_scene_free(&s);
}

/* The test file with the first `from[i]` in its JSON replaced by `to[i]`. */
static void write_variant(char* path, size_t size, const char* name, const char* const from[2],
                          const char* const to[2], const char* images)
{
    char json[16384], edited[16384], buffer[256], bin_path[512];
    snprintf(buffer, sizeof buffer, "{\"uri\":\"%s.bin\",\"byteLength\":%d}", name, BIN_SIZE);
    make_json(edited, sizeof edited, 4, buffer, images);
    for (int i = 0; i < 2 && from[i]; i++) {
        memcpy(json, edited, sizeof json);
        char* at = strstr(json, from[i]);
        TV_CHECK(at != NULL);
        if (at)
            snprintf(edited, sizeof edited, "%.*s%s%s", (int)(at - json), json, to[i], at + strlen(from[i]));
    }
    snprintf(path, size, "%s/%s.gltf", dir, name);
    snprintf(bin_path, sizeof bin_path, "%s/%s.bin", dir, name);
    write_file(path, edited, strlen(edited));
    write_file(bin_path, bin, BIN_SIZE);
}

/* Offsets and counts near 2^64 must not wrap the bounds check (they read
 * outside the buffer or crashed), a negative offset must not read as 0, and
 * references to what the file lacks must fail rather than fall back. */
static void test_bad_references(void)
{
    static const char tri_accessor[] = "{\"bufferView\":3,";
    static const char tri_view[] = "{\"buffer\":0,\"byteOffset\":128,";
    static const struct {
        const char* name;
        const char* from[2];
        const char* to[2];
        const char *images, *expect;
    } cases[] = {
        { "acc_offset_wrap", { tri_accessor }, { "{\"bufferView\":3,\"byteOffset\":18446744073709551600," }, NULL,
          "accessor 3 (3 elements at offset 18446744073709551600" },
        { "view_offset_wrap", { tri_view }, { "{\"buffer\":0,\"byteOffset\":18446744073709551600," }, NULL,
          "reads past the end of buffer 0" },
        { "view_offset_negative", { tri_view }, { "{\"buffer\":0,\"byteOffset\":-128," }, NULL,
          "bufferViews[3].byteOffset is -128, not a non-negative integer" },
        { "count_huge", { "\"count\":3," }, { "\"count\":4611686018427387904," }, NULL,
          "(4611686018427387904 elements" },
        { "material_missing", { "\"material\":0" }, { "\"material\":7" }, NULL, "missing material 7 (the file has 1)" },
        { "texture_missing", { NULL }, { NULL }, "\"textures\":[],\"images\":[],", "references missing texture 0" },
        { "image_missing", { NULL }, { NULL }, "\"textures\":[{\"source\":3}],\"images\":[],", "references missing image 3" },
        { "scene_missing", { "\"scene\":0" }, { "\"scene\":4" }, NULL, "\"scene\" is 4 but the file has 1 scenes" },
        { "gltf1", { "\"version\":\"2.0\"" }, { "\"version\":\"1.0\"" }, NULL, "is glTF 1.0; trimvr reads glTF 2.0 only" },
        { "points_only", { "\"nodes\":[0]", "{\"POSITION\":3}}" }, { "\"nodes\":[1]", "{\"POSITION\":3},\"mode\":1}" },
          NULL, "has only point/line primitives (mode 1)" },
    };
    char path[512];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        write_variant(path, sizeof path, cases[i].name, cases[i].from, cases[i].to, cases[i].images);
        expect_failure(path, cases[i].name, cases[i].expect);
    }
}

static void test_bad_inputs(void)
{
    char path[512];
    snprintf(path, sizeof path, "%s/does_not_exist.gltf", dir);
    expect_failure(path, "missing file", NULL);
    size_t size = write_glb(path, sizeof path, "truncated");
    TV_CHECK(truncate(path, (off_t)(size / 2)) == 0);
    expect_failure(path, "truncated glb", NULL);
    snprintf(path, sizeof path, "%s/corrupt.gltf", dir);
    write_file(path, "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"mesh\"", 42);
    expect_failure(path, "corrupt json", NULL);
    write_gltf(path, sizeof path, "past_end", 40, NULL, bin);
    expect_failure(path, "accessor past buffer end", NULL);
    uint8_t bad[BIN_SIZE];
    memcpy(bad, bin, BIN_SIZE);
    uint32_t big = 99;
    memcpy(bad + 176 + 4, &big, 4);
    write_gltf(path, sizeof path, "index_range", 4, NULL, bad);
    expect_failure(path, "index out of range", NULL);
    memcpy(bad, bin, BIN_SIZE);
    float nan = NAN;
    memcpy(bad + 4, &nan, 4);
    write_gltf(path, sizeof path, "nan", 4, NULL, bad);
    expect_failure(path, "NaN position", NULL);
    write_gltf(path, sizeof path, "no_texture", 4, "\"textures\":[{\"source\":0}],\"images\":[{\"uri\":\"missing.png\"}],", bin);
    expect_failure(path, "missing texture", NULL);
    snprintf(path, sizeof path, "%s/scene.obj", dir);
    expect_failure(path, "unknown extension", NULL);
}

int main(void)
{
    if (!scene_test_dir_create(dir, sizeof dir, "tv_scene_gltf"))
        return 1;
    make_bin();
    TV_TEST_RUN(test_gltf_roundtrip);
    TV_TEST_RUN(test_glb_roundtrip);
    TV_TEST_RUN(test_texture);
    TV_TEST_RUN(test_embedded_texture);
    TV_TEST_RUN(test_bad_inputs);
    TV_TEST_RUN(test_bad_references);
    scene_test_dir_remove(dir);
    return tv_test_finish();
}
