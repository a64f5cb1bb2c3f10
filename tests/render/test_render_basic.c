/* Mesh pass on hand-built scenes: known colours, ids and depths, alpha
 * masking, double-sided lighting. Runs with validation on; any validation
 * warning or error fails the test. */
#include "mesh_shared.h"
#include "image_compare.h"
#include "log.h"
#include "render_fixture.h"
#include "test.h"
#include "render_vk.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 64
#define H 64

static rnd_context* ctx;

typedef struct frame {
    uint8_t rgba[W * H * 4];
    uint32_t ids[W * H];
    float depth[W * H];
} frame;

/* Draws tri_ids[0..count) (every triangle when NULL) and reads it all back. */
static frame* render_subset(const scn_scene* s, const rnd_camera* cam, const uint32_t* tri_ids, uint32_t count)
{
    char err[256];
    frame* f = calloc(1, sizeof *f);
    rnd_gpu_scene* g = rnd_scene_create(ctx, s, err, sizeof err);
    rnd_target* t = rnd_target_create(ctx, W, H, err, sizeof err);
    TV_CHECK(g && t);
    rnd_draw_stats stats;
    TV_CHECK(rnd_draw(ctx, t, g, cam, tri_ids, count, &stats));
    TV_CHECK(stats.triangles == (tri_ids ? count : s->triangle_count) && stats.cpu_ms > 0);
    TV_CHECK(rnd_target_read_color(ctx, t, f->rgba) && rnd_target_read_ids(ctx, t, f->ids) &&
             rnd_target_read_depth(ctx, t, f->depth));
    rnd_target_destroy(ctx, t);
    rnd_scene_destroy(ctx, g);
    return f;
}

static frame* render(const scn_scene* s, const rnd_camera* cam) { return render_subset(s, cam, NULL, 0); }

static const uint8_t* px(const frame* f, int x, int y) { return f->rgba + 4 * (y * W + x); }

/* Expected linear shade of a base colour channel lit with normal n. */
static float shade(float base, const float n[3], int channel)
{
    const float sun_dir[3] = {TV_SUN_DIR}, sun[3] = {TV_SUN_COLOR}, sky[3] = {TV_SKY_COLOR},
                ground[3] = {TV_GROUND_COLOR};
    float t = n[1] * 0.5f + 0.5f;
    float ndl = fmaxf(n[0] * sun_dir[0] + n[1] * sun_dir[1] + n[2] * sun_dir[2], 0.0f);
    return base * (ground[channel] + (sky[channel] - ground[channel]) * t + sun[channel] * ndl);
}

static void device_with_validation(void)
{
    TV_CHECK(rnd_device_name(ctx)[0] != '\0');
    char err[256];
    /* bad input fails with a message, not a crash */
    TV_CHECK(rnd_target_create(ctx, 0, 16, err, sizeof err) == NULL && err[0]);
    scn_scene empty = {0};
    TV_CHECK(rnd_scene_create(ctx, &empty, err, sizeof err) == NULL && err[0]);
}

/* Sink that swallows the deliberately provoked validation error below. */
static void quiet_sink(tv_log_level level, const char* message, void* user) { ++*(int*)user; }

static void validation_messages_are_counted(void)
{
    /* a second context: the provoked error must not count against ctx */
    rnd_context* other = fx_context();
    int logged = 0;
    tv_log_set_sink(quiet_sink, &logged);
    VkBufferCreateInfo info = {.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO, .size = 16, .usage = 0};
    VkBuffer buffer = VK_NULL_HANDLE;
    vkCreateBuffer(other->device, &info, NULL, &buffer); /* usage 0 is invalid */
    if (buffer)
        vkDestroyBuffer(other->device, buffer, NULL);
    tv_log_set_sink(NULL, NULL);
    TV_CHECK(rnd_validation_message_count(other) >= 1 && logged >= 1);
    rnd_destroy(other);
}

static void device_choice(void)
{
    char err[256];
    rnd_context* c = rnd_create(&(rnd_desc){.device = "no-such-device-name", .validation = -1}, err, sizeof err);
    TV_CHECK(c == NULL && strstr(err, "no-such-device-name"));
    c = rnd_create(&(rnd_desc){.device = "0", .validation = -1}, err, sizeof err);
    TV_CHECK(c != NULL);
    rnd_destroy(c);
}

static void red_quad_colour_id_depth(void)
{
    scn_scene s;
    fx_scene_init(&s, 1, 1);
    uint32_t red = fx_material(&s, 1, 0, 0, SCN_ALPHA_OPAQUE, false, -1);
    fx_quad_z(&s, -1, -1, 1, 1, -5, red);
    rnd_camera cam = fx_camera();
    frame* f = render(&s, &cam);

    const float n[3] = {0, 0, 1};
    const uint8_t* c = px(f, W / 2, H / 2);
    TV_CHECK(abs(c[0] - fx_srgb8(shade(1, n, 0))) <= 1 && c[1] == 0 && c[2] == 0 && c[3] == 255);
    /* below-right of the centre is triangle 0 (c0 c1 c2), above-left triangle 1 */
    TV_CHECK(f->ids[(H / 2 + 4) * W + W / 2 + 4] == 0);
    TV_CHECK(f->ids[(H / 2 - 4) * W + W / 2 - 4] == 1);
    /* depth of a plane at distance 5: far (d - near) / ((far - near) d) */
    TV_CHECK_NEAR(f->depth[(H / 2) * W + W / 2], 100.0 * 4.9 / (99.9 * 5.0), 1e-6);

    /* the background: clear colour, no triangle, far depth */
    const uint8_t* bg = px(f, 0, 0);
    TV_CHECK(abs(bg[0] - fx_srgb8(0.05f)) <= 1 && abs(bg[1] - fx_srgb8(0.1f)) <= 1 &&
             abs(bg[2] - fx_srgb8(0.2f)) <= 1 && bg[3] == 0);
    TV_CHECK(f->ids[0] == TV_NO_TRIANGLE && f->depth[0] == 1.0f);

    /* coverage: the quad spans 2 / (2 * 5 tan 30deg) of the height */
    size_t covered = 0;
    for (int i = 0; i < W * H; i++)
        covered += f->ids[i] != TV_NO_TRIANGLE;
    double side = W * 1.0 / (5.0 * tan(30.0 * acos(-1.0) / 180.0));
    TV_CHECK_NEAR((double)covered, side * side, 2 * 2 * side);
    free(f);
    scn_scene_free(&s);
}

static void alpha_mask_discards(void)
{
    /* a 4x1 texture: opaque white left half, transparent right half */
    uint8_t texels[16] = {255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0, 255, 255, 255, 0};
    scn_scene s;
    fx_scene_init(&s, 3, 3);
    s.textures = calloc(1, sizeof *s.textures);
    s.textures[0] = (scn_texture){4, 1, malloc(sizeof texels)};
    memcpy(s.textures[0].rgba8, texels, sizeof texels);
    s.texture_count = 1;
    uint32_t green_mask = fx_material(&s, 0, 1, 0, SCN_ALPHA_MASK, false, 0);
    uint32_t green_opaque = fx_material(&s, 0, 1, 0, SCN_ALPHA_OPAQUE, false, 0);
    uint32_t red = fx_material(&s, 1, 0, 0, SCN_ALPHA_OPAQUE, false, -1);
    fx_quad_z(&s, -3, -3, 3, 3, -8, red);         /* triangles 0, 1 */
    fx_quad_z(&s, -1, 0, 1, 1, -4, green_mask);   /* triangles 2, 3: upper half of the view */
    fx_quad_z(&s, -1, -1, 1, 0, -4, green_opaque); /* triangles 4, 5: lower half */
    rnd_camera cam = fx_camera();
    frame* f = render(&s, &cam);
    /* upper half: the left (opaque texels) is the green quad, the right shows the red one */
    int yu = H / 2 - 6, yl = H / 2 + 6, xl = W / 2 - 8, xr = W / 2 + 8;
    TV_CHECK(f->ids[yu * W + xl] == 2 || f->ids[yu * W + xl] == 3);
    TV_CHECK(px(f, xl, yu)[1] > 100 && px(f, xl, yu)[0] == 0);
    TV_CHECK(f->ids[yu * W + xr] <= 1);
    TV_CHECK(px(f, xr, yu)[0] > 100 && px(f, xr, yu)[1] == 0);
    /* lower half: an opaque material ignores the texture's alpha */
    TV_CHECK(f->ids[yl * W + xl] >= 4 && f->ids[yl * W + xl] <= 5);
    TV_CHECK(f->ids[yl * W + xr] >= 4 && f->ids[yl * W + xr] <= 5);
    TV_CHECK(px(f, xr, yl)[1] > 100);
    free(f);
    scn_scene_free(&s);
}

static void double_sided_back_faces(void)
{
    /* quads facing away from the camera (normal -Z): the double-sided one is
     * lit as if facing the camera, the single-sided one is culled (glTF
     * doubleSided false), showing the red quad behind it */
    scn_scene s;
    fx_scene_init(&s, 3, 3);
    uint32_t two = fx_material(&s, 1, 1, 1, SCN_ALPHA_OPAQUE, true, -1);
    uint32_t one = fx_material(&s, 1, 1, 1, SCN_ALPHA_OPAQUE, false, -1);
    const float left[4][3] = {{-1, -1, -5}, {-1, 1, -5}, {-0.1f, 1, -5}, {-0.1f, -1, -5}};
    const float right[4][3] = {{0.1f, -1, -5}, {0.1f, 1, -5}, {1, 1, -5}, {1, -1, -5}};
    uint32_t red = fx_material(&s, 1, 0, 0, SCN_ALPHA_OPAQUE, false, -1);
    fx_quad(&s, left, two);
    fx_quad(&s, right, one);
    fx_quad_z(&s, -1, -1, 1, 1, -8, red);
    TV_CHECK(s.normals[2] < 0);
    rnd_camera cam = fx_camera();
    frame* f = render(&s, &cam);
    const float front[3] = {0, 0, 1};
    TV_CHECK(abs(px(f, W / 2 - 6, H / 2)[0] - fx_srgb8(shade(1, front, 0))) <= 1);
    TV_CHECK(f->ids[(H / 2) * W + W / 2 - 6] <= 1);
    TV_CHECK(f->ids[(H / 2) * W + W / 2 + 6] >= 4);
    TV_CHECK(abs(px(f, W / 2 + 6, H / 2)[0] - fx_srgb8(shade(1, front, 0))) <= 1 && px(f, W / 2 + 6, H / 2)[1] == 0);
    free(f);
    scn_scene_free(&s);
}

static bool near8(const uint8_t* c, const float linear[3], int tolerance)
{
    for (int i = 0; i < 3; i++)
        if (abs(c[i] - fx_srgb8(linear[i])) > tolerance)
            return false;
    return true;
}

/* A red opaque quad (a box's front face) at z -6, a 50 % green BLEND pane at
 * -5 and a 50 % blue one at -4, the near pane added first so that id order
 * is not back-to-front order. Blending is linear (sRGB attachment); stored
 * 8-bit sRGB between layers costs a code or two. */
static void blend_panes_over_box(void)
{
    scn_scene s;
    fx_scene_init(&s, 3, 3);
    uint32_t red = fx_material(&s, 1, 0, 0, SCN_ALPHA_OPAQUE, false, -1);
    uint32_t blue = fx_material(&s, 0, 0, 1, SCN_ALPHA_BLEND, false, -1);
    uint32_t green = fx_material(&s, 0, 1, 0, SCN_ALPHA_BLEND, false, -1);
    s.materials[blue].base_color[3] = s.materials[green].base_color[3] = 0.5f;
    uint32_t box = fx_quad_z(&s, -3, -3, 3, 3, -6, red);
    uint32_t near_pane = fx_quad_z(&s, -0.8f, -0.8f, 0.8f, 0.8f, -4, blue);
    uint32_t far_pane = fx_quad_z(&s, -1.6f, -1.6f, 1.6f, 1.6f, -5, green);
    rnd_camera cam = fx_camera();
    const float n[3] = {0, 0, 1};
    const float r = shade(1, n, 0), g = shade(1, n, 1), b = shade(1, n, 2);
    const int centre = (H / 2) * W + W / 2, green_only = (H / 2) * W + W / 2 + 14, box_only = (H / 2) * W + W / 2 + 22;

    frame* f = render(&s, &cam);
    /* back to front: blue over (green over red); front to back would give green over (blue over red) */
    const float mix3[3] = {0.25f * r, 0.25f * g, 0.5f * b}, mix2[3] = {0.5f * r, 0.5f * g, 0};
    TV_CHECK(near8(px(f, W / 2, H / 2), mix3, 3) && px(f, W / 2, H / 2)[3] == 255);
    TV_CHECK(near8(px(f, W / 2 + 14, H / 2), mix2, 3));
    TV_CHECK(near8(px(f, W / 2 + 22, H / 2), (const float[3]){r, 0, 0}, 1));
    /* ids and depth: the nearest surface, BLEND included (the FN metric's choice) */
    TV_CHECK(f->ids[centre] == near_pane || f->ids[centre] == near_pane + 1);
    TV_CHECK(f->ids[green_only] == far_pane || f->ids[green_only] == far_pane + 1);
    TV_CHECK(f->ids[box_only] == box || f->ids[box_only] == box + 1);
    TV_CHECK_NEAR(f->depth[centre], 100.0 * 3.9 / (99.9 * 4.0), 1e-6);
    free(f);

    /* a subset, unsorted: the box behind the near pane is still blended in */
    const uint32_t pane_and_box[4] = {near_pane + 1, box, near_pane, box + 1};
    f = render_subset(&s, &cam, pane_and_box, 4);
    TV_CHECK(near8(px(f, W / 2, H / 2), (const float[3]){0.5f * r, 0, 0.5f * b}, 3));
    TV_CHECK(f->ids[centre] == near_pane || f->ids[centre] == near_pane + 1);
    free(f);
    /* only the panes (the ground truth's see-through peel): ids and depth of the nearest one */
    const uint32_t panes[4] = {far_pane, far_pane + 1, near_pane, near_pane + 1};
    f = render_subset(&s, &cam, panes, 4);
    TV_CHECK(f->ids[centre] == near_pane || f->ids[centre] == near_pane + 1);
    TV_CHECK(f->ids[green_only] == far_pane || f->ids[green_only] == far_pane + 1);
    TV_CHECK(f->ids[box_only] == TV_NO_TRIANGLE && f->depth[box_only] == 1.0f);
    TV_CHECK_NEAR(f->depth[green_only], 100.0 * 4.9 / (99.9 * 5.0), 1e-6);
    free(f);

    /* the near pane opaque: pure blue, the box hidden */
    s.materials[blue].alpha_mode = SCN_ALPHA_OPAQUE;
    f = render(&s, &cam);
    TV_CHECK(near8(px(f, W / 2, H / 2), (const float[3]){0, 0, b}, 1));
    TV_CHECK(f->ids[centre] == near_pane || f->ids[centre] == near_pane + 1);
    free(f);
    scn_scene_free(&s);
}

int main(void)
{
    ctx = fx_context();
    TV_TEST_RUN(device_with_validation);
    TV_TEST_RUN(validation_messages_are_counted);
    TV_TEST_RUN(device_choice);
    TV_TEST_RUN(red_quad_colour_id_depth);
    TV_TEST_RUN(alpha_mask_discards);
    TV_TEST_RUN(double_sided_back_faces);
    TV_TEST_RUN(blend_panes_over_box);
    TV_CHECK(rnd_validation_message_count(ctx) == 0);
    rnd_destroy(ctx);
    return tv_test_finish();
}
