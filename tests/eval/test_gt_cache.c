/* test_gt_cache.c - the ground-truth cache's file (eval/gt_cache.h): a
 * record with ids and pixel counts at every varint width comes back
 * exactly; an absent file is a plain miss; another key, a damaged byte, a
 * truncated file and ids beyond the scene are rejected with a reason; keys
 * differ when a viewcell or setting does. */
#define _DEFAULT_SOURCE /* mkdtemp */
#include "gt_cache.h"
#include "scene_test_dir.h"
#include "test.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char g_dir[256];

/* view 0: ids at every varint width (1-5 bytes of gap) and large counts;
 * view 1: empty; view 2: one id, 0 */
static const uint32_t k_ids[] = {0, 127, 128, 16383, 16384, 2097152, 268435456, 4294967294u};
static const uint32_t k_px[] = {1, 2, 921600, 127, 128, 16384, 7, 4000000000u};

static void make_record(pvs_gt_record* r)
{
    *r = (pvs_gt_record){.gt_ms = 1234.5, .full_render_ms = 6.25};
    uint32_t zero = 0, three = 3;
    TV_CHECK(pvs_gt_record_add_view(r, k_ids, k_px, 8));
    TV_CHECK(pvs_gt_record_add_view(r, NULL, NULL, 0));
    TV_CHECK(pvs_gt_record_add_view(r, &zero, &three, 1));
}

static void copy_bytes(const char* from, const char* to, long size) /* size < 0: all */
{
    FILE* in = fopen(from, "rb");
    FILE* out = fopen(to, "wb");
    TV_CHECK(in && out);
    int c;
    for (long n = 0; in && out && (size < 0 || n < size) && (c = fgetc(in)) != EOF; n++)
        fputc(c, out);
    if (in)
        fclose(in);
    if (out)
        fclose(out);
}

static void expect_rejected(const char* file, const char* key, uint32_t tris, const char* reason)
{
    pvs_gt_record r;
    char why[256];
    TV_CHECK(!pvs_gt_cache_load(file, key, tris, &r, why, sizeof why));
    TV_CHECK(strstr(why, reason) != NULL);
    TV_CHECK(r.views == 0 && r.ids == NULL);
    if (!strstr(why, reason))
        printf("  %s: '%s', expected '%s'\n", file, why, reason);
}

static void test_round_trip(void)
{
    pvs_gt_record w, r;
    make_record(&w);
    char file[512], err[256], why[256];
    snprintf(file, sizeof file, "%s/sub/gt.bin", g_dir);
    TV_CHECK(pvs_gt_cache_store(file, "key-a", &w, err, sizeof err));
    TV_CHECK(pvs_gt_cache_load(file, "key-a", UINT32_MAX, &r, why, sizeof why));
    TV_CHECK(r.views == 3 && r.entry_count == 9 && r.gt_ms == 1234.5 && r.full_render_ms == 6.25);
    TV_CHECK(r.view_first[0] == 0 && r.view_first[1] == 8 && r.view_first[2] == 8 && r.view_first[3] == 9);
    TV_CHECK(memcmp(r.ids, k_ids, sizeof k_ids) == 0 && memcmp(r.pixels, k_px, sizeof k_px) == 0);
    TV_CHECK(r.ids[8] == 0 && r.pixels[8] == 3);
    pvs_gt_record_free(&r);

    char missing[512];
    snprintf(missing, sizeof missing, "%s/none.bin", g_dir);
    TV_CHECK(!pvs_gt_cache_load(missing, "key-a", UINT32_MAX, &r, why, sizeof why) && why[0] == '\0');

    expect_rejected(file, "key-b", UINT32_MAX, "key differs");
    expect_rejected(file, "key-a", 1000, "malformed"); /* ids beyond the scene */
    char bad[512];
    snprintf(bad, sizeof bad, "%s/bad.bin", g_dir);
    copy_bytes(file, bad, 40);
    expect_rejected(bad, "key-a", UINT32_MAX, "checksum");
    copy_bytes(file, bad, -1);
    FILE* f = fopen(bad, "r+b");
    TV_CHECK(f && fseek(f, 30, SEEK_SET) == 0 && fputc(0x55, f) != EOF);
    if (f)
        fclose(f);
    expect_rejected(bad, "key-a", UINT32_MAX, "checksum");
    copy_bytes(file, bad, 10);
    expect_rejected(bad, "key-a", UINT32_MAX, "not a ground-truth cache file");
    pvs_gt_record_free(&w);
}

static void test_keys(void)
{
    pred_viewcell vc = {.v0 = {1, 2, 3}, .forward = {0, 0, -1}, .up = {0, 1, 0}, .delta = 0.1f, .z = 0.1f,
                        .fov_target_deg = 60, .fov_pvs_deg = 90, .frusta = 1};
    pvs_eval_desc d = {.samples = 200, .width = 1280, .height = 720, .eye_fov_h_deg = 60, .near_m = 0.05f,
                       .far_m = 500};
    char a[2048], b[2048], fa[600], fb[600];
    pvs_gt_cache_key("spec=x", &vc, &d, a, sizeof a);
    pvs_gt_cache_file("dir", a, fa, sizeof fa);
    vc.v0[0] = nextafterf(1.0f, 2.0f); /* one ulp away: another viewcell */
    pvs_gt_cache_key("spec=x", &vc, &d, b, sizeof b);
    pvs_gt_cache_file("dir", b, fb, sizeof fb);
    TV_CHECK(strcmp(a, b) != 0 && strcmp(fa, fb) != 0);
    vc.v0[0] = 1.0f;
    d.seed = 1;
    pvs_gt_cache_key("spec=x", &vc, &d, b, sizeof b);
    TV_CHECK(strcmp(a, b) != 0);
    d.seed = 0;
    pvs_gt_cache_key("spec=x", &vc, &d, b, sizeof b);
    TV_CHECK(strcmp(a, b) == 0 && strncmp(fa, "dir/gt-", 7) == 0);
}

int main(void)
{
    if (!scene_test_dir_create(g_dir, sizeof g_dir, "tv_gt_cache"))
        return 1;
    TV_TEST_RUN(test_round_trip);
    TV_TEST_RUN(test_keys);
    scene_test_dir_remove(g_dir);
    return tv_test_finish();
}
