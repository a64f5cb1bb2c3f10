/* Trim width against brute-force sampling of the double-cone viewcell, the
 * width narrowed by the depth bound behind the edge (a wall before a back
 * wall), and the umbra quad's geometry. */
#include <math.h>

#include "depth_bound.h"
#include "pvs_test_scenes.h"
#include "test.h"
#include "trim_width.h"
#include "umbra.h"

#define TWO_PI 6.283185307179586

/* Largest inward image displacement (normalised units, seen from v* at the
 * origin looking along +depth) of the far-plane point seen just past
 * silhouette point (sigma * d, d) from viewpoints sampled over the double cone. */
static double sampled_max(const pvs_trim_params* p, double d, const double sigma[2], const double n[2],
                          uint32_t* rng)
{
    double z = p->delta / p->tan_half_fov, best = -1e30;
    for (int ia = 0; ia <= 400; ia++) {
        double a = 2.0 * z * ia / 400.0;
        double r = (a <= z ? a : 2.0 * z - a) * p->tan_half_fov;
        for (int k = 0; k < 96; k++) {
            double phi = TWO_PI * k / 96.0, scale = k % 4 == 3 ? pvs_test_rand(rng) : 1.0;
            double b[2] = {scale * r * cos(phi), scale * r * sin(phi)}, disp = 0.0;
            for (int c = 0; c < 2; c++) {
                double s = sigma[c] * d;
                double pl = b[c] + (s - b[c]) * (p->far_dist - a) / (d - a);
                disp -= n[c] * (pl / p->far_dist - sigma[c]);
            }
            best = disp > best ? disp : best;
        }
    }
    return best;
}

static void test_trim_width_matches_sampling(void)
{
    uint32_t rng = 4242;
    int checked = 0;
    for (int i = 0; i < 60; i++) {
        pvs_trim_params p = {.delta = 0.02f + 0.3f * pvs_test_rand(&rng),
                             .tan_half_fov = 0.3f + 1.2f * pvs_test_rand(&rng),
                             .far_dist = 20.0f + 80.0f * pvs_test_rand(&rng), .focal_px = 1.0f};
        double z = p.delta / p.tan_half_fov;
        double d = 2.0 * z + 0.05 + (p.far_dist - 2.0 * z) * pvs_test_rand(&rng) * pvs_test_rand(&rng);
        double sigma[2] = {p.tan_half_fov * (2.0 * pvs_test_rand(&rng) - 1.0),
                           p.tan_half_fov * (2.0 * pvs_test_rand(&rng) - 1.0)};
        double ang = TWO_PI * pvs_test_rand(&rng), n[2] = {cos(ang), sin(ang)};
        double w = pvs_trim_width_px(&p, (float)d, (float)(sigma[0] * n[0] + sigma[1] * n[1]));
        double m = sampled_max(&p, d, sigma, n, &rng);
        TV_CHECK(m <= w * (1.0 + 1e-4) + 1e-7); /* conservative */
        if (w > 1e-5) {
            TV_CHECK(m >= 0.995 * w); /* and tight */
            checked++;
        }
    }
    TV_CHECK(checked > 30);
}

static void test_trim_width_known_values(void)
{
    /* A very wide frustum puts v* at v0: the classic Δ (1/d - 1/F). */
    pvs_trim_params p = {.delta = 0.1f, .tan_half_fov = 1000.0f, .far_dist = 10.0f, .focal_px = 500.0f};
    TV_CHECK_NEAR(pvs_trim_width_px(&p, 2.0f, 0.0f), 500.0 * 0.1 * (0.5 - 0.1), 1e-3);
    /* 90 degrees, on the axis: z = Δ, maximum at the base disk. */
    pvs_trim_params q = {.delta = 0.1f, .tan_half_fov = 1.0f, .far_dist = 10.0f, .focal_px = 1.0f};
    TV_CHECK_NEAR(pvs_trim_width_px(&q, 2.0f, 0.0f), 0.1 / 1.9 * 8.0 / 10.0, 1e-6);
    TV_CHECK(pvs_trim_width_px(&q, 10.0f, 0.0f) == 0.0f); /* at the far plane */
    TV_CHECK(pvs_trim_width_px(&q, 12.0f, 0.3f) == 0.0f);
    TV_CHECK(isinf(pvs_trim_width_px(&q, 0.2f, 0.0f))); /* within the viewcell's depth */
    /* Wider toward the image border when the edge faces inwards (apex behind v0). */
    TV_CHECK(pvs_trim_width_px(&q, 2.0f, -0.8f) > pvs_trim_width_px(&q, 2.0f, 0.8f));
}

static void project(const pvs_view* v, const float p[3], float img[2])
{
    pvs_view_frame f = pvs_view_frame_make(v);
    TV_CHECK(pvs_view_project(v, &f, p, img) > 0.0f);
}

static void test_umbra_quad(void)
{
    pvs_view v = {.apex = {0, 0, 0}, .forward = {0, 0, -1}, .up = {0, 1, 0}, .fov_y_deg = 90.0f,
                  .near_dist = 0.1f, .far_dist = 50.0f};
    float e0[3] = {-1, 1, -5}, e1[3] = {1, 1.5f, -6}, inside[3] = {0, 0, -5};
    pvs_umbra_quad q;
    const float w[2] = {0.01f, 0.02f};
    TV_CHECK(pvs_umbra_quad_make(&v, e0, e1, inside, w, w, &q));
    for (int a = 0; a < 3; a++) {
        TV_CHECK(q.corner[0][a] == e0[a] && q.corner[1][a] == e1[a]);
    }
    float i0[2], i1[2], c2[2], c3[2], ii[2];
    project(&v, e0, i0);
    project(&v, e1, i1);
    project(&v, inside, ii);
    project(&v, q.corner[2], c2);
    project(&v, q.corner[3], c3);
    TV_CHECK_NEAR(-q.corner[2][2], 50.0, 1e-3); /* far-plane depth along forward */
    TV_CHECK_NEAR(-q.corner[3][2], 50.0, 1e-3);
    /* The far corners project onto the extruded vertices: displaced by the
     * width, perpendicular to the edge, towards the occluder. */
    float t[2] = {i1[0] - i0[0], i1[1] - i0[1]}, len = sqrtf(t[0] * t[0] + t[1] * t[1]);
    float d3[2] = {c3[0] - i0[0], c3[1] - i0[1]}, d2[2] = {c2[0] - i1[0], c2[1] - i1[1]};
    TV_CHECK_NEAR(sqrtf(d3[0] * d3[0] + d3[1] * d3[1]), 0.01, 1e-5);
    TV_CHECK_NEAR(sqrtf(d2[0] * d2[0] + d2[1] * d2[1]), 0.02, 1e-5);
    TV_CHECK_NEAR((d3[0] * t[0] + d3[1] * t[1]) / len, 0.0, 1e-5);
    TV_CHECK_NEAR((d2[0] * t[0] + d2[1] * t[1]) / len, 0.0, 1e-5);
    float side = (ii[0] - i0[0]) * d3[0] + (ii[1] - i0[1]) * d3[1];
    TV_CHECK(side > 0.0f);
    TV_CHECK_NEAR(c3[0], q.extruded[0][0], 1e-5);
    TV_CHECK_NEAR(c2[1], q.extruded[1][1], 1e-5);
    /* Degenerate inputs are refused. */
    float behind[3] = {0, 0, 1}, f0[3] = {-1, 1, -5}, f1[3] = {1, 1, -5}, on_line[3] = {0.5f, 1, -5};
    TV_CHECK(!pvs_umbra_quad_make(&v, e0, behind, inside, w, w, &q));
    TV_CHECK(!pvs_umbra_quad_make(&v, e0, e0, inside, w, w, &q));
    TV_CHECK(!pvs_umbra_quad_make(&v, f0, f1, on_line, w, w, &q));
}

/* Adds the quad a, b, c, d (two triangles) to the bound. */
static void add_quad(pvs_depth_bound* b, float x0, float y0, float x1, float y1, float z)
{
    const float t[2][3][3] = {{{x0, y0, z}, {x1, y0, z}, {x1, y1, z}}, {{x0, y0, z}, {x1, y1, z}, {x0, y1, z}}};
    pvs_depth_bound_add(b, t[0], 3);
    pvs_depth_bound_add(b, t[1], 3);
}

/* A wall at depth d whose right edge (x = ex) is a silhouette, before a back
 * wall at depth D: every back-wall point that an eye sampled on the double
 * cone sees just past the edge lands, seen from v*, within the width
 * narrowed by the bound (pvs_umbra_far_depth), which is within rounding of
 * the exact maximum and far narrower than the far-plane width. The umbra's
 * far corners lie on the far-plane umbra's lines, on the extruded rays. */
static void test_width_narrowed_by_a_back_wall(void)
{
    const float delta = 0.2f, d = 2.0f, ex = 0.3f;
    pvs_view v = {.apex = {0, 0, 0}, .forward = {0, 0, -1}, .up = {0, 1, 0}, .fov_y_deg = 90.0f,
                  .aspect = 1.0f, .near_dist = 0.05f, .far_dist = 100.0f};
    pvs_depth_bound b;
    TV_CHECK(pvs_depth_bound_init(&b, 400, 400));
    const float backs[3] = {3.0f, 6.0f, 20.0f};
    for (int k = 0; k < 3; k++) {
        const float D = backs[k];
        pvs_depth_bound_begin(&b, &v);
        add_quad(&b, -5.0f, -3.0f, ex, 3.0f, -d);                  /* the wall, its edge at x = ex */
        add_quad(&b, -3.0f * D, -3.0f * D, 3.0f * D, 3.0f * D, -D); /* the back wall */
        pvs_depth_bound_finish(&b);
        const float e0[3] = {ex, -0.5f, -d}, e1[3] = {ex, 0.5f, -d}, inside[3] = {ex - 1.0f, 0.0f, -d};
        float bound = pvs_umbra_far_depth(&b, delta, 1.0f, e0, e1);
        TV_CHECK(bound >= D && bound <= D * 1.0002f);
        pvs_trim_params p = {.delta = delta, .tan_half_fov = 1.0f, .far_dist = bound, .focal_px = 1.0f};
        pvs_trim_params pf = p;
        pf.far_dist = v.far_dist;
        const float sigma = ex / d; /* the edge's outward normal is +x */
        float w = pvs_trim_width_px(&p, d, sigma), wf = pvs_trim_width_px(&pf, d, sigma);
        /* (D - d) / D against (F - d) / F */
        TV_CHECK(w < wf * (D - d) / D * v.far_dist / (v.far_dist - d) * 1.001f && w < wf);
        /* eyes on the double cone (z = Δ: base disk at depth Δ, far apex at 2Δ) */
        double worst = -1.0;
        uint32_t rng = 7u + (uint32_t)k;
        for (int i = 0; i < 20000; i++) {
            double a = 2.0 * delta * pvs_test_rand(&rng), r = (a <= delta ? a : 2.0 * delta - a);
            double phi = 6.283185307179586 * pvs_test_rand(&rng), rr = r * sqrt(pvs_test_rand(&rng));
            if (i % 3 == 0)
                rr = r; /* the cone's surface */
            double eye[3] = {rr * cos(phi), rr * sin(phi), -a};
            double sy = -0.5 + pvs_test_rand(&rng), s[3] = {ex, sy, -d};
            double t = (D - a) / (d - a), q[3]; /* the back-wall point seen past s */
            for (int c = 0; c < 3; c++)
                q[c] = eye[c] + t * (s[c] - eye[c]);
            double inward = sigma - q[0] / D; /* from s's image towards the occluder (-x) */
            worst = inward > worst ? inward : worst;
        }
        printf("  back wall at %g m: bound %.4f, width %.5f (far plane: %.5f), worst sampled %.5f\n", D, bound, w,
               wf, worst);
        TV_CHECK(worst <= w * (1.0 + 1e-5) && worst >= 0.97 * w);
        /* The umbra is the far-plane one cut to the narrowed footprint: its
         * far corner lies on the far-plane quad's line from e0, on the
         * narrowed ray, in front of the far plane. */
        const float wn[2] = {w, w}, wfar[2] = {wf, wf};
        pvs_umbra_quad q, qf;
        TV_CHECK(pvs_umbra_quad_make(&v, e0, e1, inside, wn, wfar, &q));
        TV_CHECK(pvs_umbra_quad_make(&v, e0, e1, inside, wfar, wfar, &qf));
        float depth = -q.corner[3][2];
        TV_CHECK(depth > d && depth < 0.99f * v.far_dist);
        TV_CHECK_NEAR(q.corner[3][0] / depth, q.extruded[0][0], 1e-5);
        float t = (depth - d) / (v.far_dist - d);
        for (int a = 0; a < 3; a++)
            TV_CHECK_NEAR(q.corner[3][a], e0[a] + t * (qf.corner[3][a] - e0[a]), 1e-3 * depth);
    }
    /* Nothing behind the wall: the bound is the wall's own depth and the
     * width vanishes; the umbra's far corners stay near the edge's depth. */
    pvs_depth_bound_begin(&b, &v);
    add_quad(&b, -5.0f, -3.0f, ex, 3.0f, -d);
    pvs_depth_bound_finish(&b);
    const float e0[3] = {ex, -0.5f, -d}, e1[3] = {ex, 0.5f, -d}, inside[3] = {ex - 1.0f, 0.0f, -d};
    float bound = pvs_umbra_far_depth(&b, delta, 1.0f, e0, e1);
    TV_CHECK(bound >= d && bound <= d * 1.0002f);
    pvs_trim_params p = {.delta = delta, .tan_half_fov = 1.0f, .far_dist = bound, .focal_px = 400.0f};
    TV_CHECK(pvs_trim_width_px(&p, d, ex / d) < 0.01f);
    pvs_trim_params pf = p;
    pf.far_dist = v.far_dist;
    const float wn[2] = {1.0f / 400.0f, 1.0f / 400.0f}; /* the one pixel P1 adds */
    const float wfar[2] = {wn[0] + pvs_trim_width_px(&pf, d, ex / d) / 400.0f, wn[1] + pvs_trim_width_px(&pf, d, ex / d) / 400.0f};
    pvs_umbra_quad q;
    TV_CHECK(pvs_umbra_quad_make(&v, e0, e1, inside, wn, wfar, &q));
    TV_CHECK(-q.corner[2][2] > d && -q.corner[2][2] < 1.1f * d);
    /* An edge within 2z of v* has no finite reach: the far plane. */
    const float n0[3] = {ex, -0.5f, -0.3f}, n1[3] = {ex, 0.5f, -0.3f};
    TV_CHECK(pvs_umbra_far_depth(&b, delta, 1.0f, n0, n1) == v.far_dist);
    pvs_depth_bound_free(&b);
}

int main(void)
{
    TV_TEST_RUN(test_trim_width_matches_sampling);
    TV_TEST_RUN(test_trim_width_known_values);
    TV_TEST_RUN(test_width_narrowed_by_a_back_wall);
    TV_TEST_RUN(test_umbra_quad);
    return tv_test_finish();
}
