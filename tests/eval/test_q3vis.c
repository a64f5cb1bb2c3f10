/* test_q3vis.c - the .pvs.json reader and cluster queries: a hand-written
 * file with known bits, malformed inputs (each error names the file and the
 * problem), and the real OpenArena levels' invariants when ../shared is
 * present. */
#define _DEFAULT_SOURCE /* mkdtemp */
#include "q3vis.h"
#include "scene_test_dir.h"
#include "test.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Three clusters, one byte per row. Row 0 = 0x03 (sees 0, 1), row 1 = 0x07
 * (sees 0, 1, 2), row 2 = 0x06 (sees 1, 2): base64 of bytes 03 07 06 is
 * "AwcG". Leaves: cluster 0 = [0,1]^3, cluster 1 = [1,2] x [0,1]^2,
 * cluster 2 = [2,3] x [0,1]^2, a solid leaf and the empty placeholder. */
static const char* k_small =
    "{\"scale\": 0.0254, \"coords\": \"test \\\"quoted\\\" \\/ text\", \"n_clusters\": 3,\n"
    " \"bytes_per_cluster\": 1, \"visdata_b64\": \"AwcG\", \"visible_clusters_per_cluster\": [2, 3, 2],\n"
    " \"nested\": {\"a\": [true, false, null, -1.5e3, {}]},\n"
    " \"leafs\": [{\"cluster\": 0, \"area\": 0, \"min\": [0, 0, 0], \"max\": [0, 0, 0]},\n"
    "  {\"cluster\": 0, \"area\": 0, \"min\": [0, 0, 0], \"max\": [1, 1, 1]},\n"
    "  {\"cluster\": 1, \"area\": 0, \"min\": [1, 0, 0], \"max\": [2, 1, 1]},\n"
    "  {\"cluster\": 2, \"area\": 0, \"min\": [2.0, 0.0, 0.0], \"max\": [3.0, 1.0, 1.0]},\n"
    "  {\"cluster\": -1, \"area\": -1, \"min\": [-5, -5, -5], \"max\": [-4, -4, -4]}]}\n";

static char g_dir[256];

static const char* write_file(const char* name, const char* text)
{
    static char path[512];
    snprintf(path, sizeof path, "%s/%s", g_dir, name);
    FILE* f = fopen(path, "wb");
    TV_CHECK(f != NULL);
    if (f) {
        fputs(text, f);
        fclose(f);
    }
    return path;
}

static void test_small_file(void)
{
    const char* path = write_file("small.pvs.json", k_small);
    pvs_q3vis vis;
    char err[256] = "";
    bool ok = pvs_q3vis_load(path, &vis, err, sizeof err);
    if (!ok)
        fprintf(stderr, "%s\n", err);
    TV_CHECK(ok);
    TV_CHECK(vis.n_clusters == 3 && vis.bytes_per_cluster == 1 && vis.leaf_count == 5);
    /* bit j of row i = cluster j visible from cluster i */
    static const int expect[3][3] = {{1, 1, 0}, {1, 1, 1}, {0, 1, 1}};
    for (uint32_t i = 0; i < 3; i++)
        for (uint32_t j = 0; j < 3; j++)
            TV_CHECK(pvs_q3vis_sees(&vis, i, j) == (expect[i][j] != 0));
    TV_CHECK(vis.leaves[3].cluster == 2 && vis.leaves[3].max[0] == 3.0f && vis.leaves[4].cluster == -1);

    uint8_t mask[3];
    TV_CHECK(pvs_q3vis_clusters_near(&vis, (float[3]){0.5f, 0.5f, 0.5f}, 0.0f, mask) == 1 && mask[0]);
    /* a ball reaching across the 0|1 boundary finds both */
    TV_CHECK(pvs_q3vis_clusters_near(&vis, (float[3]){0.9f, 0.5f, 0.5f}, 0.2f, mask) == 2 && mask[0] && mask[1]);
    /* inside the solid leaf, far from any cluster leaf: none (the placeholder at the origin is ignored) */
    TV_CHECK(pvs_q3vis_clusters_near(&vis, (float[3]){-4.5f, -4.5f, -4.5f}, 0.1f, mask) == 0);

    /* one triangle per cluster, one straddling clusters 1|2, one in solid space */
    float pos[] = {0.2f, 0, 0.2f, 0.8f, 0, 0.2f, 0.5f, 0.5f, 0.2f, /* cluster 0 */
                   1.2f, 0, 0.2f, 1.8f, 0, 0.2f, 1.5f, 0.5f, 0.2f, /* cluster 1 */
                   2.2f, 0, 0.2f, 2.8f, 0, 0.2f, 2.5f, 0.5f, 0.2f, /* cluster 2 */
                   1.8f, 0, 0.5f, 2.2f, 0, 0.5f, 2.0f, 0.5f, 0.5f, /* clusters 1 and 2 */
                   -4.8f, -4.8f, -4.8f, -4.2f, -4.8f, -4.8f, -4.5f, -4.2f, -4.8f};
    uint32_t idx[15];
    for (uint32_t i = 0; i < 15; i++)
        idx[i] = i;
    scn_scene scene = {.vertex_count = 15, .positions = pos, .triangle_count = 5, .indices = idx};
    pvs_q3vis_tri_map map;
    TV_CHECK(pvs_q3vis_map_triangles(&vis, &scene, &map, err, sizeof err));
    TV_CHECK(map.unclustered == 1);
    TV_CHECK(map.offsets[4] - map.offsets[3] == 2);
    uint32_t ids[5];
    uint8_t scratch[3];
    uint8_t from0[3] = {1, 0, 0}, from2[3] = {0, 0, 1}, from1[3] = {0, 1, 0};
    TV_CHECK(pvs_q3vis_triangles(&vis, &map, from0, scratch, ids) == 3);
    TV_CHECK(ids[0] == 0 && ids[1] == 1 && ids[2] == 3); /* 0 and 1 visible; the straddler via 1 */
    TV_CHECK(pvs_q3vis_triangles(&vis, &map, from2, scratch, ids) == 3);
    TV_CHECK(ids[0] == 1 && ids[1] == 2 && ids[2] == 3);
    TV_CHECK(pvs_q3vis_triangles(&vis, &map, from1, scratch, ids) == 4);
    pvs_q3vis_tri_map_free(&map);
    pvs_q3vis_free(&vis);
    TV_CHECK(vis.visdata == NULL && vis.leaf_count == 0);
}

/* Parses `text` as file `name`; expects failure with a message naming the
 * file and containing `needle`. */
static void expect_error(const char* name, const char* text, const char* needle)
{
    pvs_q3vis vis;
    char err[256] = "";
    bool ok = pvs_q3vis_parse(text, strlen(text), name, &vis, err, sizeof err);
    if (ok || strstr(err, name) != err || !strstr(err, needle))
        fprintf(stderr, "  %s: got \"%s\", wanted \"%s\"\n", name, ok ? "success" : err, needle);
    TV_CHECK(!ok && strstr(err, name) == err && strstr(err, needle));
    TV_CHECK(vis.visdata == NULL && vis.leaves == NULL);
}

static const char* k_leaf = "\"leafs\": [{\"cluster\": 0, \"min\": [0,0,0], \"max\": [1,1,1]}]";

static void test_errors(void)
{
    pvs_q3vis vis;
    char err[256] = "", path[300];
    snprintf(path, sizeof path, "%s/missing.pvs.json", g_dir);
    TV_CHECK(!pvs_q3vis_load(path, &vis, err, sizeof err) && strstr(err, path) == err && strstr(err, "cannot open"));

    char text[512];
    snprintf(text, sizeof text, "{\"n_clusters\": 2, \"bytes_per_cluster\": 1, \"visdata_b64\": \"A*==\", %s}", k_leaf);
    expect_error("alphabet.pvs.json", text, "bad base64");
    snprintf(text, sizeof text, "{\"n_clusters\": 2, \"bytes_per_cluster\": 1, \"visdata_b64\": \"AwcGA\", %s}", k_leaf);
    expect_error("length.pvs.json", text, "bad base64");
    /* 3 bytes for 2 clusters of 1 byte */
    snprintf(text, sizeof text, "{\"n_clusters\": 2, \"bytes_per_cluster\": 1, \"visdata_b64\": \"AwcG\", %s}", k_leaf);
    expect_error("size.pvs.json", text, "visdata has 3 bytes, expected n_clusters * bytes_per_cluster = 2");
    snprintf(text, sizeof text, "{\"n_clusters\": 9, \"bytes_per_cluster\": 1, \"visdata_b64\": \"AwcG\", %s}", k_leaf);
    expect_error("narrow.pvs.json", text, "bytes_per_cluster 1 cannot hold 9 clusters");
    expect_error("nokey.pvs.json", "{\"n_clusters\": 1, \"bytes_per_cluster\": 1, \"visdata_b64\": \"AQ==\"}",
                 "missing key leafs");
    expect_error("cluster.pvs.json",
                 "{\"n_clusters\": 1, \"bytes_per_cluster\": 1, \"visdata_b64\": \"AQ==\", \"leafs\": "
                 "[{\"cluster\": 1, \"min\": [0,0,0], \"max\": [1,1,1]}]}",
                 "cluster 1 outside [-1, 1)");
    expect_error("box.pvs.json",
                 "{\"n_clusters\": 1, \"bytes_per_cluster\": 1, \"visdata_b64\": \"AQ==\", \"leafs\": "
                 "[{\"cluster\": 0, \"min\": [0,2,0], \"max\": [1,1,1]}]}",
                 "min exceeds max");
    expect_error("truncated.pvs.json", "{\"n_clusters\": 1, \"bytes_per_cluster\"", "unexpected end of file");
    expect_error("syntax.pvs.json", "{\"n_clusters\" 1}", "byte 14: expected ':'");
    expect_error("trailing.pvs.json", "{} x", "trailing bytes after the document");
    expect_error("nokey0.pvs.json", "{}", "missing key n_clusters");
    expect_error("empty.pvs.json", "", "unexpected end of file");
    char deep[300];
    memset(deep, '[', 200);
    snprintf(deep + 200, sizeof deep - 200, "]");
    char nested[400];
    snprintf(nested, sizeof nested, "{\"x\": %s}", deep);
    expect_error("deep.pvs.json", nested, "nested too deeply");
}

/* Random truncations and byte edits of the small file: each parse either
 * succeeds or fails cleanly (one line naming the file, nothing left allocated;
 * the sanitizer build catches reads past the input). */
static void test_mutations(void)
{
    size_t len = strlen(k_small);
    char* buf = malloc(len);
    uint64_t state = 0x9e3779b97f4a7c15ull;
    uint32_t failed = 0, clean = 0;
    for (int i = 0; i < 4000; i++) {
        memcpy(buf, k_small, len);
        size_t n = len;
        for (int e = 0; e < 1 + i % 4; e++) {
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            uint32_t r = (uint32_t)(state >> 33);
            if (r % 5 == 0)
                n = r / 5 % (n + 1); /* truncate */
            else if (n > 0)
                buf[r / 5 % n] = (char)(r >> 24 ^ r); /* overwrite one byte */
        }
        pvs_q3vis vis;
        char err[256] = "";
        if (pvs_q3vis_parse(buf, n, "mut.json", &vis, err, sizeof err)) {
            TV_CHECK(vis.n_clusters > 0 && vis.visdata && vis.leaf_count > 0);
            pvs_q3vis_free(&vis);
        } else {
            failed++;
            clean += strncmp(err, "mut.json: ", 10) == 0 && !strchr(err, '\n') && !vis.visdata && !vis.leaves;
        }
    }
    TV_CHECK(failed > 1000 && clean == failed);
    free(buf);
}

static void test_real_levels(void)
{
    const char* shared = getenv("TRIMVR_SHARED");
    static const char* levels[] = {"oasago2", "oa_dm5", "czest2ctf", "ctf_inyard", "oacmpdm9", "pul1ctf"};
    for (size_t i = 0; i < sizeof levels / sizeof *levels; i++) {
        char path[1024], err[512] = "";
        snprintf(path, sizeof path, "%s/scenes/openarena/%s/%s.pvs.json", shared, levels[i], levels[i]);
        pvs_q3vis vis;
        bool ok = pvs_q3vis_load(path, &vis, err, sizeof err);
        if (!ok)
            fprintf(stderr, "%s\n", err);
        TV_CHECK(ok);
        if (!ok)
            continue;
        /* the parser enforces the size; the README's figure for oasago2 pins the count */
        TV_CHECK(vis.bytes_per_cluster >= (vis.n_clusters + 7) / 8);
        if (strcmp(levels[i], "oasago2") == 0)
            TV_CHECK(vis.n_clusters == 2280);
        uint32_t bad_leaf = 0, blind = 0, in_cluster = 0;
        for (uint32_t l = 0; l < vis.leaf_count; l++) {
            bad_leaf += vis.leaves[l].cluster < -1 || vis.leaves[l].cluster >= (int32_t)vis.n_clusters;
            in_cluster += vis.leaves[l].cluster >= 0;
        }
        for (uint32_t c = 0; c < vis.n_clusters; c++)
            blind += !pvs_q3vis_sees(&vis, c, c);
        TV_CHECK(bad_leaf == 0 && blind == 0 && in_cluster > 0);
        printf("  %s: %u clusters x %u bytes, %u leaves (%u in clusters)\n", levels[i], vis.n_clusters,
               vis.bytes_per_cluster, vis.leaf_count, in_cluster);
        pvs_q3vis_free(&vis);
    }
}

int main(void)
{
    if (!scene_test_dir_create(g_dir, sizeof g_dir, "tv_q3vis"))
        return 1;
    TV_TEST_RUN(test_small_file);
    TV_TEST_RUN(test_errors);
    TV_TEST_RUN(test_mutations);
    const char* shared = getenv("TRIMVR_SHARED");
    char probe[1024];
    snprintf(probe, sizeof probe, "%s/scenes/openarena/oasago2/oasago2.pvs.json", shared ? shared : "");
    FILE* f = shared ? fopen(probe, "rb") : NULL;
    if (f) {
        fclose(f);
        TV_TEST_RUN(test_real_levels);
    }
    scene_test_dir_remove(g_dir);
    int rc = tv_test_finish();
    if (rc == 0 && !f) {
        printf("skip: the OpenArena levels under $TRIMVR_SHARED/scenes/openarena are absent\n");
        return 77;
    }
    return rc;
}
