/* test_pvs_gpu_cases.c - the GPU trim-region PVS on constructed occluder
 * configurations, each with the triangles it must hide and keep:
 * interpenetrating occluders, thin walls, umbrae inside umbrae, occluders
 * across layers, back faces past edges, culled backs, cracks, slivers, a
 * candidate behind a back, a slot under a lifted wall, openings at the view
 * edge and through a gap, and coincident twins (pvs_gpu_fixture.h). */
#include "pvs_gpu_checks.h"
#include "pvs_shared.h"

#include <cglm/cglm.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Two boxes crossing each other (a plus sign seen from above): the union
 * occludes, although neither's silhouette is an edge of the union. */
static void test_interpenetrating_occluders(void)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    add_box(&f.scene, -3.0f, -2.0f, -6.2f, 3.0f, 2.0f, -6.0f, m);
    add_box(&f.scene, -0.2f, -2.5f, -7.5f, 0.2f, 2.5f, -4.5f, m);
    uint32_t hidden = add_box(&f.scene, -0.5f, -0.5f, -12.0f, 0.5f, 0.5f, -11.0f, m);
    check_configuration(&f, "interpenetrating occluders", 0.05f, FN_SIMPLE, &hidden, 1, NULL, 0);
}

/* A 1 cm thick wall: its front and back faces are one pixel-width apart in
 * depth, so the occlusion interval between them is very short. */
static void test_thin_walls(void)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    add_box(&f.scene, -3.0f, -2.0f, -6.01f, 3.0f, 2.0f, -6.0f, m);
    uint32_t hidden = add_box(&f.scene, -0.5f, -0.5f, -12.0f, 0.5f, 0.5f, -11.0f, m);
    uint32_t beside = add_box(&f.scene, 6.5f, -0.5f, -12.0f, 7.5f, 0.5f, -11.0f, m); /* past the wall's edge */
    check_configuration(&f, "thin (1 cm) wall", 0.05f, FN_SIMPLE, &hidden, 1, &beside, 1);
}

/* Consecutive occluders (the paper's figure 5): a box in the first wall's
 * umbra, and one in the umbra of both. */
static void test_umbra_inside_umbra(void)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    add_box(&f.scene, -2.0f, -1.5f, -4.2f, 2.0f, 1.5f, -4.0f, m);
    add_box(&f.scene, -5.0f, -3.0f, -8.2f, 5.0f, 3.0f, -8.0f, m);
    uint32_t hidden[2] = {add_box(&f.scene, -0.4f, -0.4f, -6.5f, 0.4f, 0.4f, -5.7f, m),
                          add_box(&f.scene, -1.0f, -1.0f, -12.0f, 1.0f, 1.0f, -11.0f, m)};
    check_configuration(&f, "umbra inside an umbra", 0.1f, FN_SIMPLE, hidden, 2, NULL, 0);
}

/* A wall right behind a smaller one, inside the umbra of its edges: at the
 * pixels where the small wall's trim region meets its edge, the large wall
 * is hidden but uneroded, so it still hides the box behind both from the
 * whole viewcell. Until 2026-11-24 a face inside a hidden range was skipped
 * and the box, seen past the end of the umbra, was output. */
static void test_uneroded_wall_in_an_umbra(void)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    add_box(&f.scene, -1.0f, -1.0f, -5.02f, 1.0f, 1.0f, -5.0f, m);
    add_box(&f.scene, -5.0f, -5.0f, -5.6f, 5.0f, 5.0f, -5.5f, m);
    uint32_t hidden = add_box(&f.scene, 4.0f, -2.0f, -31.0f, 8.0f, 2.0f, -30.0f, m);
    check_configuration(&f, "an uneroded wall inside an umbra", 0.1f, FN_SIMPLE, &hidden, 1, NULL, 0);
}

/* The same with leaves of at most 4 triangles: every occluder spans several
 * layers, so a pixel often becomes trimmed in a later layer than the one
 * holding its occluder's front face (the prior faces of resolve.h). */
static void test_occluders_across_layers(void)
{
    /* The strict order (74 layers), then merged into at most 14 layers
     * (docs/trim-regions.md, "Merging layers"): the same answer. */
    const uint32_t max_layers[2] = {UINT32_MAX, PVS_LAYERS_DEFAULT_MAX};
    for (int i = 0; i < 2; i++) {
        fixture f = {.octree_cap = 4, .max_layers = max_layers[i]};
        uint32_t m = constructed_scene(&f);
        add_box(&f.scene, -2.0f, -1.5f, -4.2f, 2.0f, 1.5f, -4.0f, m);
        add_box(&f.scene, -5.0f, -3.0f, -8.2f, 5.0f, 3.0f, -8.0f, m);
        uint32_t hidden[2] = {add_box(&f.scene, -0.4f, -0.4f, -6.5f, 0.4f, 0.4f, -5.7f, m),
                              add_box(&f.scene, -1.0f, -1.0f, -12.0f, 1.0f, 1.0f, -11.0f, m)};
        uint32_t beside = add_box(&f.scene, 6.5f, -0.5f, -12.0f, 7.5f, 0.5f, -11.0f, m);
        check_configuration(&f, i == 0 ? "umbra inside an umbra, 4 triangles per leaf"
                                       : "umbra inside an umbra, 4 triangles per leaf, layers merged",
                            0.1f, FN_SIMPLE, hidden, 2, &beside, 1);
    }
}

/* A double-sided quad seen from behind past a box's edge: its back is
 * drawn, so it is visible there. */
static void test_back_face_past_an_edge(void)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    add_box(&f.scene, -3.0f, -2.0f, -4.2f, 0.5f, 2.0f, -4.0f, m);
    uint32_t quad = f.scene.triangle_count;
    const float away[4][3] = {{0.9f, -0.5f, -8.0f}, {0.75f, -0.5f, -8.0f}, {0.75f, 0.5f, -8.0f}, {0.9f, 0.5f, -8.0f}};
    fx_quad(&f.scene, away, double_sided(&f));
    check_configuration(&f, "back face past an occluder's edge", 0.3f, FN_SIMPLE, NULL, 0, &quad, 1);
}

/* A 4 x 3 m wall 4 m away facing away from the whole viewcell, and a box 4 m
 * behind it. Double-sided, the wall hides the box and is in the PVS; single-
 * sided (glTF's default), the renderer culls it from every eye: the box is
 * seen through it and the wall is not in the PVS (its backs only close
 * intervals, TV_ID_CULLED). Until culled backs existed a single-sided wall
 * seen from behind sealed every pixel it covered. */
static void test_culled_back_hides_nothing(void)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    uint32_t wall = fx_quad_z(&f.scene, 2.0f, -1.5f, -2.0f, 1.5f, -4.0f, double_sided(&f));
    uint32_t box = add_box(&f.scene, -0.5f, -0.5f, -8.5f, 0.5f, 0.5f, -7.5f, m);
    check_configuration(&f, "a double-sided wall seen from behind hides a box", 0.1f, FN_SIMPLE, &box, 1, &wall, 1);

    printf("  a single-sided wall seen from behind hides nothing\n");
    f = (fixture){0};
    m = constructed_scene(&f);
    wall = fx_quad_z(&f.scene, 2.0f, -1.5f, -2.0f, 1.5f, -4.0f, m);
    box = add_box(&f.scene, -0.5f, -0.5f, -8.5f, 0.5f, 0.5f, -7.5f, m);
    pvs_result r;
    pvs_viewcell vc;
    compute_at_origin(&f, 0.1f, &vc, &r);
    TV_CHECK(count_in_range(&r, wall, 2) == 0);
    TV_CHECK(count_in_range(&r, box, 12) > 0);
    check_fn(&f, &r, &vc, FN_SIMPLE);
    fixture_close(&f);
}

/* A 10 cm slab whose right side v* sees almost edge-on, and an open quad
 * 10 m away just behind its edge from v*, seen past it from eyes 10 cm
 * aside. The silhouette lies between the side face and the back face, and
 * the side's plane meets the rays of the trimmed pixels far in front of the
 * slab, so a trim at the midpoint of the two planes' depths (or at the
 * nearer) lies in front of the slab and validates nothing: the slab's front
 * face became the terminator and the quad was lost (14 pixels of a cone
 * sample). The trim drawn in the back face's plane fixes it. */
static void test_open_quad_past_a_slab_edge(void)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    add_box(&f.scene, -3.0f, -2.0f, -5.1f, -0.05f, 2.0f, -5.0f, m);
    uint32_t quad = fx_quad_z(&f.scene, -0.35f, -0.5f, -0.12f, 0.5f, -10.0f, m);
    check_configuration(&f, "open quad past a slab's edge", 0.1f, FN_SIMPLE, NULL, 0, &quad, 1);
}

/* The same slab, and a floor below everything from 6 to 60 m ahead,
 * single-sided and facing down (seen from behind, so a lone back face
 * terminates). It is drawn in the layer of its nearest octree leaf, right
 * after the slab's, and seals the trimmed pixels behind the slab's edge
 * long before the layer of the quad 10 m away, which lies in front of it
 * there. Until sealed pixels kept their terminator's depth (and output a
 * later layer's faces in front of it) the quad was lost: 9 FN pixels at a
 * cone sample. */
static void test_late_face_before_terminator(void)
{
    fixture f = {.octree_cap = 4, .max_layers = UINT32_MAX}; /* the strict order */
    uint32_t m = constructed_scene(&f);
    add_box(&f.scene, -3.0f, -2.0f, -5.1f, -0.05f, 2.0f, -5.0f, m);
    const float floor[4][3] = {{-5.0f, -1.0f, -6.0f}, {-5.0f, -1.0f, -60.0f}, {5.0f, -1.0f, -60.0f}, {5.0f, -1.0f, -6.0f}};
    fx_quad(&f.scene, floor, m);
    uint32_t quad = fx_quad_z(&f.scene, -0.35f, -0.9f, -0.12f, -0.3f, -10.0f, m);
    check_configuration(&f, "a later layer's face in front of a terminator", 0.1f, FN_SIMPLE, NULL, 0, &quad, 1);
}

/* The slab again, and 10 m away, just past its edge, a 1.5 cm wide strip
 * seen from behind (facing away from the whole viewcell, single-sided): half
 * a PVS pixel wide, so no pixel centre lands on it; v* sees it only behind
 * the slab, eyes to the right of v* past the slab's edge. Four triangles per
 * octree leaf put the strip in a later layer than the slab, whose interval
 * leaves only its hidden range in that layer's sequence. Until the backs of
 * triangles narrower than a pixel became candidate backs the strip was in
 * no sequence and was lost. */
static void test_sliver_seen_from_behind(void)
{
    fixture f = {.octree_cap = 4, .max_layers = UINT32_MAX}; /* the strict order */
    uint32_t m = constructed_scene(&f);
    add_box(&f.scene, -3.0f, -2.0f, -5.1f, -0.05f, 2.0f, -5.0f, m);
    const float x0 = -0.16f, x1 = -0.145f, y0 = -0.5f, y1 = 0.5f, z = -10.0f;
    const float strip[4][3] = {{x1, y0, z}, {x0, y0, z}, {x0, y1, z}, {x1, y1, z}}; /* faces -z */
    uint32_t back = fx_quad(&f.scene, strip, double_sided(&f));
    check_configuration(&f, "a sliver seen from behind past a slab's edge", 0.1f, FN_SIMPLE, NULL, 0, &back, 1);
}

/* A 3 m thick box 3 m away, its right edge just right of v*, a far wall,
 * and behind the box a see-through pane (no silhouettes of its own) tilted
 * away from v*, 0.35 m of depth per pixel up the image: its lower edge runs
 * from off-screen 5.9 m away to 6.1 m, 0.3 m left of the box's edge, inside
 * the box's trim region at Δ = 0.3 m, where the umbra ends beyond 8 m. The
 * whole pane is hidden from the viewcell (every line from it to an eye
 * crosses the box's back). At a pixel its lower edge crosses off the
 * centre, the square's nearest corner lies below the edge, off the pane,
 * where its plane is nearer than the box's back (6 m): a candidate entered
 * at max(nearest corner, centre - half the slope) fell inside the box's
 * validated interval and was output; at the nearest depth of the pane's
 * part inside the pixel it lies behind the back, in the umbra. */
static void test_candidate_behind_a_validated_back(void)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    uint32_t glass = fx_material(&f.scene, 0.7f, 0.8f, 0.9f, SCN_ALPHA_BLEND, false, -1);
    add_box(&f.scene, -40.0f, -2.0f, -6.0f, 0.05f, 2.0f, -3.0f, m);
    const float tilted[4][3] = {{-30.0f, -0.3f, -5.9f}, {-0.3f, -0.3f, -6.1f}, {-1.3f, -0.156f, -8.5f},
                                {-30.0f, -0.156f, -8.5f}}; /* faces v* */
    fx_quad_z(&f.scene, -60.0f, -40.0f, 60.0f, 40.0f, -50.0f, m); /* the umbra's depth bound */
    uint32_t pane = fx_quad(&f.scene, tilted, glass); /* last: ids pane.. are its two */
    check_configuration(&f, "a candidate behind a validated interval's back", 0.3f, FN_SIMPLE, &pane, 1, NULL, 0);
}

/* A 0.2 m thick wall 5 m away standing on a floor 1.2 m below v* that runs
 * on under it (no bottom face: the feet of its four faces are border
 * edges). On an opaque floor the feet rest (scn_join_rest_edges): the front
 * face's foot, where wall and floor both face v*, is no silhouette, the
 * other three (their faces turned away) still are; on an alpha-masked floor,
 * which may have holes, all four are. Nothing is lost either way. */
static void test_wall_standing_on_a_floor(void)
{
    uint32_t silhouettes[2] = {0, 0};
    for (int masked = 0; masked < 2; masked++) {
        fixture f = {0};
        uint32_t m = constructed_scene(&f);
        uint32_t floor_material = masked ? fx_material(&f.scene, 0.5f, 0.5f, 0.5f, SCN_ALPHA_MASK, false, -1) : m;
        const float floor[4][3] = {{-8.0f, -1.2f, -1.0f}, {8.0f, -1.2f, -1.0f}, {8.0f, -1.2f, -30.0f},
                                   {-8.0f, -1.2f, -30.0f}}; /* faces up */
        fx_quad(&f.scene, floor, floor_material);
        add_standing_box(&f.scene, -4.0f, -1.2f, -5.2f, 4.0f, 1.5f, -5.0f, m);
        uint32_t box = add_box(&f.scene, -0.5f, -1.2f, -12.0f, 0.5f, -0.2f, -11.0f, m);
        printf("  a wall standing on a%s floor\n", masked ? "n alpha-masked" : "n opaque");
        pvs_result r;
        pvs_viewcell vc;
        compute_at_origin(&f, 0.1f, &vc, &r);
        silhouettes[masked] = r.stats.silhouettes;
        TV_CHECK(count_in_range(&r, box, 12) == 0);
        check_fn(&f, &r, &vc, FN_SIMPLE);
        fixture_close(&f);
    }
    TV_CHECK(silhouettes[0] + 1 == silhouettes[1]);
}

/* A 27 cm slab filling the view 1.15 m away, and glued on its far face a
 * box whose near face lies in that face's plane (an upper storey's wall on
 * a floor slab, builtin:house). That face's edges are silhouettes from v*
 * by the manifold rule (it faces v*, the box's sides do not), and their
 * trims validated the slab's interval, so a box 6 m behind both, past their
 * umbrae, was output. They are glued (scn_join_glued_edges): no silhouette. */
static void test_box_glued_on_a_slab(void)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    add_box(&f.scene, -30.0f, -30.0f, -1.42f, 30.0f, 30.0f, -1.15f, m);
    add_box(&f.scene, -0.3f, -0.5f, -3.0f, 0.3f, 0.5f, -1.42f, m);
    uint32_t hidden = add_box(&f.scene, -2.0f, -2.0f, -8.0f, 2.0f, 2.0f, -7.5f, m);
    check_configuration(&f, "a box glued on a slab", 0.1f, FN_SIMPLE, &hidden, 1, NULL, 0);
}

/* A pillar whose front face is two quads with a 1.9 cm vertical slit
 * between them, 2.5 m away: 0.65 PVS pixels wide and placed between two
 * PVS pixel centres, so v* sees nothing through it, while eyes of the
 * viewcell (whose pixels are finer) see through it. The slit's two edges
 * are crack edges (scn_mark_cracks). Double-sided, the eyes see the inside
 * of the back face, a back face from everywhere in the viewcell: the
 * intervals the crack regions validate output their back faces too. Single-
 * sided, that back is culled and the eyes see what lies behind the pillar:
 * such an interval hides only its inside, and a box behind the slit is in
 * the PVS. */
static void crack_in_a_pillar(bool two_sided)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    if (two_sided)
        m = double_sided(&f);
    const float x0 = -0.7f, x1 = 0.9f, y0 = -1.0f, y1 = 1.0f, z0 = -3.5f, z1 = -2.5f, a = 0.4819f, b = 0.5007f;
    const float q[7][4][3] = {
        {{x0, y0, z1}, {a, y0, z1}, {a, y1, z1}, {x0, y1, z1}}, /* +z, left of the slit */
        {{b, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {b, y1, z1}}, /* +z, right of it */
        {{x1, y0, z1}, {x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}},
        {{x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0}},
        {{x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0}, {x0, y1, z0}},
        {{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}},
        {{x1, y0, z0}, {x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}}, /* -z, last: the known answer */
    };
    uint32_t back = 0;
    for (int i = 0; i < 7; i++)
        back = fx_quad(&f.scene, q[i], m);
    if (two_sided) {
        check_configuration(&f, "a crack in a double-sided pillar", 0.1f, FN_SIMPLE, NULL, 0, &back, 1);
        return;
    }
    uint32_t behind = add_box(&f.scene, 0.9f, -0.3f, -6.5f, 1.5f, 0.3f, -6.0f, m); /* seen through the slit only */
    check_configuration(&f, "a box behind a crack in a single-sided pillar", 0.1f, FN_SIMPLE, NULL, 0, &behind, 1);
}

static void test_crack_in_a_pillar(void)
{
    crack_in_a_pillar(true);
    crack_in_a_pillar(false);
}

/* A 0.2 m thick wall lifted 10 cm off a floor that ends 10 cm behind it,
 * and a 5 cm high quad standing at the floor's far edge, seen through the
 * slot by the eyes below v* (v0's own view included) and by no pixel centre
 * of v*. The wall has no bottom face, so at the pixels just above its foot
 * the ray enters its front and leaves through the open bottom: the run of
 * the wall's front and the quad never closes, and P3 carries it with the
 * foot's trim. Until 2026-12-02 P4 output only the run's first front (the
 * wall) and lost the quad (154 FN pixels at v0, 104 at the worst cone
 * sample at 30 cm); a trim carried with the run validates it. */
static void test_quad_seen_under_a_lifted_wall(void)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    const float floor[4][3] = {{-8.0f, -1.2f, -1.0f}, {8.0f, -1.2f, -1.0f}, {8.0f, -1.2f, -5.3f},
                               {-8.0f, -1.2f, -5.3f}}; /* faces up */
    fx_quad(&f.scene, floor, m);
    add_standing_box(&f.scene, -4.0f, -1.1f, -5.2f, 4.0f, 1.5f, -5.0f, m);
    uint32_t quad = fx_quad_z(&f.scene, -1.0f, -1.2f, 1.0f, -1.15f, -5.3f, m); /* faces v* */
    check_configuration(&f, "a quad seen under a lifted wall", 0.3f, FN_SIMPLE, NULL, 0, &quad, 1);
}

/* A 0.2 m square hole near the edge of the 60-degree target view (which
 * ends at x = 1.73 at this depth): the box seen through it must be kept,
 * one behind the solid part culled. The hole's 5 cm side walls are seen
 * from the cone's rear apex at about 0.03 degrees, a sliver thinner than
 * any pixel: an eye render's pixel centres may land on it where the PVS
 * raster's (0.5 degrees apart) do not (measured: 9 pixels in one cone
 * sample, none from v0 or the apex), hence FN_SLIVER. */
static void test_small_opening_at_view_edge(void)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    /* a 5 cm slab around the hole, as four boxes */
    const float z0 = -3.05f, z1 = -3.0f, hx0 = 1.4f, hx1 = 1.6f, hy0 = -0.1f, hy1 = 0.1f;
    add_box(&f.scene, -6.0f, -4.0f, z0, hx0, 4.0f, z1, m); /* left of the hole */
    add_box(&f.scene, hx1, -4.0f, z0, 6.0f, 4.0f, z1, m);  /* right of it */
    add_box(&f.scene, hx0, hy1, z0, hx1, 4.0f, z1, m);     /* above */
    add_box(&f.scene, hx0, -4.0f, z0, hx1, hy0, z1, m);    /* below */
    uint32_t through = add_box(&f.scene, 2.7f, -0.3f, -6.3f, 3.3f, 0.3f, -5.7f, m);
    uint32_t hidden = add_box(&f.scene, -3.3f, -0.3f, -6.3f, -2.7f, 0.3f, -5.7f, m);
    check_configuration(&f, "small opening at the edge of the view", 0.05f, FN_SLIVER, &hidden, 1, &through, 1);
}

/* Two walls 2 m away with a 10 cm vertical gap, and a box 4.2 m away beside
 * the gap, hidden from v0 and v* but seen through the gap from the viewcell's
 * left rim. Nothing else lies behind the gap, so the bound of the scene's
 * depth behind the gap's edges is the box's own (docs/trim-width.md): were
 * the box missing from the bound, the widths would shrink to a pixel and
 * the box would be culled. A box deep behind the right wall stays hidden. */
static void test_box_seen_through_a_gap(void)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    add_box(&f.scene, -4.0f, -3.0f, -2.1f, -0.05f, 3.0f, -2.0f, m);
    add_box(&f.scene, 0.05f, -3.0f, -2.1f, 4.0f, 3.0f, -2.0f, m);
    uint32_t through = add_box(&f.scene, 0.25f, -0.3f, -4.5f, 0.55f, 0.3f, -4.2f, m);
    uint32_t hidden = add_box(&f.scene, 3.0f, -0.5f, -12.0f, 4.0f, 0.5f, -11.0f, m);
    check_configuration(&f, "a box seen only through a gap", 0.3f, FN_SIMPLE, &hidden, 1, &through, 1);
}

/* A room whose ceiling is two coincident double-sided quads of opposite
 * winding (a zero-thickness surface as some exporters write it), large enough
 * to pass behind v*: such triangles cross the near plane and are drawn
 * undilated. Both twins tie in depth at every pixel; the depth test keeps
 * one, but an eye's raster may show either (found on oa:oacmpdm9: the twin
 * the PVS lost covered a third of some sample views), so both must be in. */
static void test_coincident_twins_across_near_plane(void)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    const float e = 40.0f, yc = 2.0f;
    const float ceiling[4][3] = {{-e, yc, -e}, {e, yc, -e}, {e, yc, e}, {-e, yc, e}}; /* faces down */
    const float twin[4][3] = {{-e, yc, -e}, {-e, yc, e}, {e, yc, e}, {e, yc, -e}};    /* same diagonal, faces up */
    uint32_t first = fx_quad(&f.scene, ceiling, double_sided(&f));
    fx_quad(&f.scene, twin, f.scene.material_count - 1);
    const float floor_q[4][3] = {{-e, -1.5f, -e}, {-e, -1.5f, e}, {e, -1.5f, e}, {e, -1.5f, -e}};
    fx_quad(&f.scene, floor_q, m);
    scn_scene_update_bounds(&f.scene);
    fixture_open(&f, 0);
    pvs_result r;
    pvs_viewcell vc = viewcell(0.0f, 0.0f, 0.0f, 0.05f);
    TV_CHECK(compute(&f, &vc, &r));
    TV_CHECK(count_in_range(&r, first, 4) == 4);
    TV_CHECK(apex_fn(&f, &r, &vc) == 0);
    fixture_close(&f);
}

/* At Δ 10 cm from the origin: none of the n triangles from `first` on (all
 * behind a wall) is in the PVS, and no false-negative pixel. Closes f. */
static void check_hidden_behind_wall(fixture* f, uint32_t first, uint32_t n)
{
    pvs_result r;
    pvs_viewcell vc;
    compute_at_origin(f, 0.1f, &vc, &r);
    printf("  quads behind the wall in the PVS: %u of %u\n", count_in_range(&r, first, n), n);
    TV_CHECK(count_in_range(&r, first, n) == 0);
    check_fn(f, &r, &vc, FN_SIMPLE);
    fixture_close(f);
}

/* A single-sided wall exported as two coincident quads of opposite winding
 * (BSP levels), the culled twin rounded 0.01 mm nearer than the front, and
 * 24 open quads facing v* stacked 5-8 m behind the wall near its left edge,
 * hidden from the whole viewcell, at pixels the edge's trim region reaches.
 * The culled twin sorted first was a lone back the walk skips, so the front
 * had no back: a run carried through every later layer, whose carry
 * overflowed on the quads behind, and the overflow policy output them all
 * (TV_PVS_CULLED_NUDGE puts a culled back behind a coincident front). */
static void test_culled_twin_of_a_wall(void)
{
    fixture f = {.octree_cap = 4, .max_layers = UINT32_MAX}; /* the strict order */
    uint32_t m = constructed_scene(&f);
    const float z = -4.0f, twin_z = z + 1e-5f;
    fx_quad_z(&f.scene, -2.0f, -1.5f, 2.0f, 1.5f, z, m);      /* faces v* */
    fx_quad_z(&f.scene, 2.0f, -1.5f, -2.0f, 1.5f, twin_z, m); /* its culled twin */
    uint32_t first = f.scene.triangle_count;
    for (int i = 0; i < 24; i++) {
        float d = 5.0f + 3.0f * (float)i / 23.0f; /* depth behind v0 */
        fx_quad_z(&f.scene, -0.46f * d, -0.2f, -0.44f * d, 0.2f, -d, m);
    }
    check_hidden_behind_wall(&f, first, 48);
}

/* The same wall with its twin's corners exactly on its own (OpenArena's
 * fog sheet, docs/journal/2026-12-03-czfp.md), so the four triangles share
 * the quad's diagonal, and small open quads far behind it along the
 * diagonal's shadow. As a non-manifold edge the diagonal was a silhouette,
 * its trim region eroded the wall along it, and the quads behind that
 * region's umbra were output; paired into two flat sheets
 * (scn_pair_sheets) it is none, and the wall hides them all. */
static void test_twinned_wall_diagonal(void)
{
    fixture f = {0};
    uint32_t m = constructed_scene(&f);
    const float wall[4][3] = {{-2.0f, -1.5f, -4.0f}, {2.0f, -1.5f, -4.0f}, {2.0f, 1.5f, -4.0f}, {-2.0f, 1.5f, -4.0f}};
    const float twin[4][3] = {{-2.0f, -1.5f, -4.0f}, {-2.0f, 1.5f, -4.0f}, {2.0f, 1.5f, -4.0f}, {2.0f, -1.5f, -4.0f}};
    fx_quad(&f.scene, wall, m); /* faces v* */
    fx_quad(&f.scene, twin, m);
    uint32_t first = f.scene.triangle_count;
    const float depths[7] = {6.0f, 10.0f, 15.0f, 20.0f, 30.0f, 45.0f, 60.0f};
    for (int i = 0; i < 7; i++) {
        for (int j = -1; j <= 1; j++) {
            float s = depths[i] / 4.0f, x = 1.2f * (float)j * s, y = 0.9f * (float)j * s, h = 0.1f * s;
            fx_quad_z(&f.scene, x - h, y - h, x + h, y + h, -depths[i], m);
        }
    }
    check_hidden_behind_wall(&f, first, 42);
}

/* ---- a finely tessellated surface: every triangle of it is visible ---- */

/* Ids of r carrying every bit of `reason`; whether each id carries some rule. */
static uint32_t with_reason(const pvs_result* r, uint32_t reason, bool* all_explained)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < r->count; i++) {
        n += (r->reasons[i] & reason) == reason;
        *all_explained = *all_explained && r->reasons[i] != 0 && r->reasons[i] < (1u << TV_REASON_COUNT);
    }
    return n;
}

/* Explain mode (pvs_desc.explain) gives the same PVS with the rules behind
 * each id: the builtin:unit wall facing v* is in its visibility buffer (P4)
 * and nothing there overflows; in the city ids name the overflow policy
 * exactly when pixels overflowed, and far more of them with k = 1 (almost
 * every pixel overflows) than with k = 32 (a few dozen do). The identity is
 * checked where nothing overflows: the overflow policy's outputs vary run to
 * run on lavapipe (docs/journal/2026-12-02-bench-at-scale.md). */
static void test_explain_names_the_rules(void)
{
    pvs_viewcell vc = viewcell(0.0f, 1.5f, 0.0f, 0.1f);
    pvs_result r;
    fixture plain = {0};
    load(&plain, "builtin:unit", 0);
    TV_CHECK(compute(&plain, &vc, &r) && r.reasons == NULL);
    uint32_t n = r.count, ids[64];
    TV_CHECK(n <= 64);
    memcpy(ids, r.ids, sizeof(uint32_t) * (n <= 64 ? n : 64));
    fixture_close(&plain);

    fixture f = {.explain = true};
    load(&f, "builtin:unit", 0);
    uint32_t w0, wn;
    TV_CHECK(scn_unit_object("wall", &w0, &wn));
    bool explained = true;
    TV_CHECK(compute(&f, &vc, &r) && r.reasons != NULL);
    TV_CHECK(r.count == n && n <= 64 && memcmp(r.ids, ids, sizeof(uint32_t) * n) == 0);
    uint32_t wall_vis = 0;
    for (uint32_t i = 0; r.reasons && i < r.count; i++)
        wall_vis += r.ids[i] >= w0 && r.ids[i] < w0 + wn && (r.reasons[i] & TV_REASON_VIS);
    TV_CHECK(wall_vis >= 2 && with_reason(&r, TV_REASON_OVERFLOW, &explained) == 0 && explained);
    fixture_close(&f);

    vc = viewcell(0.0f, 1.7f, 30.0f, 0.1f);
    const uint32_t ks[2] = {1, 32};
    uint32_t overflowed[2] = {0, 0};
    for (int i = 0; i < 2; i++) {
        f = (fixture){.explain = true};
        load(&f, "builtin:city?tris=20000", ks[i]);
        TV_CHECK(compute(&f, &vc, &r) && r.reasons != NULL);
        overflowed[i] = r.reasons ? with_reason(&r, TV_REASON_OVERFLOW, &explained) : 0;
        printf("  k = %u: %u of %u ids output by the overflow policy, %llu overflowing pixels\n", ks[i],
               overflowed[i], r.count, (unsigned long long)r.stats.overflow_pixels);
        TV_CHECK(explained && (overflowed[i] > 0) == (r.stats.overflow_pixels > 0));
        fixture_close(&f);
    }
    TV_CHECK(overflowed[0] > 4 * overflowed[1]);
}

int main(void)
{
    g_rnd = fx_context();
    TV_TEST_RUN(test_interpenetrating_occluders);
    TV_TEST_RUN(test_thin_walls);
    TV_TEST_RUN(test_umbra_inside_umbra);
    TV_TEST_RUN(test_uneroded_wall_in_an_umbra);
    TV_TEST_RUN(test_occluders_across_layers);
    TV_TEST_RUN(test_back_face_past_an_edge);
    TV_TEST_RUN(test_culled_back_hides_nothing);
    TV_TEST_RUN(test_open_quad_past_a_slab_edge);
    TV_TEST_RUN(test_late_face_before_terminator);
    TV_TEST_RUN(test_sliver_seen_from_behind);
    TV_TEST_RUN(test_candidate_behind_a_validated_back);
    TV_TEST_RUN(test_crack_in_a_pillar);
    TV_TEST_RUN(test_wall_standing_on_a_floor);
    TV_TEST_RUN(test_box_glued_on_a_slab);
    TV_TEST_RUN(test_quad_seen_under_a_lifted_wall);
    TV_TEST_RUN(test_small_opening_at_view_edge);
    TV_TEST_RUN(test_box_seen_through_a_gap);
    TV_TEST_RUN(test_coincident_twins_across_near_plane);
    TV_TEST_RUN(test_culled_twin_of_a_wall);
    TV_TEST_RUN(test_twinned_wall_diagonal);
    TV_TEST_RUN(test_explain_names_the_rules);
    TV_CHECK(rnd_validation_message_count(g_rnd) == 0);
    rnd_destroy(g_rnd);
    return tv_test_finish();
}
