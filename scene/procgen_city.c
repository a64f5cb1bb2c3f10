/* procgen_city.c - builtin:city, streets and buildings with heavy occlusion.
 *
 * Layout contract (procedural.h): block pitch 40 m, streets centred on
 * x = i*40 and z = j*40, free of geometry above the ground up to 6 m within
 * 4 m of each centreline. Lots start 6 m from a centreline; only thin street
 * furniture (lamp posts, awnings, fences) comes closer, and never nearer than
 * 4.05 m. The triangle budget is met by choosing the facade window-cell size:
 * a count-only pass per candidate size, bisected on a log scale for the
 * largest cell that still reaches the budget. The layout is drawn from the
 * seed alone (no random draw per window), so it is independent of the budget
 * except for the extent, which grows with it.
 */
#include "procgen.h"
#include "procedural.h"

#include "log.h"

#include <math.h>

#define P SCN_CITY_BLOCK_PITCH

typedef struct city {
    scn_builder* b;
    tv_rng rng;
    float cell; /* facade window cell width, metres */
    uint32_t asphalt, pavement, walls[3], glass, roof, metal, awning, foliage;
} city;

static void _v3(float out[3], float x, float y, float z)
{
    out[0] = x, out[1] = y, out[2] = z;
}

/* out = a + s*u + t*v + w*n */
static void _at(float out[3], const float a[3], const float u[3], float s, const float v[3], float t,
                const float n[3], float w)
{
    for (int k = 0; k < 3; k++)
        out[k] = a[k] + s * u[k] + t * v[k] + w * n[k];
}

static void _scaled(float out[3], const float d[3], float s)
{
    _v3(out, d[0] * s, d[1] * s, d[2] * s);
}

/* One window cell at c0 (lower corner on the facade plane): a frame of four
 * quads and a recess of depth d (sill, head, two jambs, glass). */
#define WINDOW_CELL_QUADS 9
static void _window_cell(city* c, const float c0[3], const float along[3], const float n[3], float cw, float ch,
                         uint32_t wall)
{
    static const float up[3] = { 0, 1, 0 };
    float mx = 0.2f * cw, mb = 0.25f * ch, mt = 0.15f * ch, ww = cw - 2 * mx, wh = ch - mb - mt;
    float d = fminf(0.3f, 0.15f * cw);
    float o[3], u[3], v[3];
    _scaled(u, along, cw), _scaled(v, up, mb);
    scn_gen_quad(c->b, c0, u, v, 1, 1, wall);
    _at(o, c0, up, ch - mt, up, 0, n, 0), _scaled(v, up, mt);
    scn_gen_quad(c->b, o, u, v, 1, 1, wall);
    _scaled(u, along, mx), _scaled(v, up, wh);
    _at(o, c0, up, mb, up, 0, n, 0);
    scn_gen_quad(c->b, o, u, v, 1, 1, wall);
    _at(o, c0, along, cw - mx, up, mb, n, 0);
    scn_gen_quad(c->b, o, u, v, 1, 1, wall);
    float hole[3], dn[3], wa[3], hu[3];
    _at(hole, c0, along, mx, up, mb, n, -d); /* inner lower corner of the recess */
    _scaled(dn, n, d), _scaled(wa, along, ww), _scaled(hu, up, wh);
    scn_gen_quad(c->b, hole, wa, hu, 1, 1, c->glass);
    scn_gen_quad(c->b, hole, dn, wa, 1, 1, wall); /* sill, faces up */
    _at(o, hole, up, wh, up, 0, n, 0);
    scn_gen_quad(c->b, o, wa, dn, 1, 1, wall); /* head, faces down */
    scn_gen_quad(c->b, hole, hu, dn, 1, 1, wall); /* jamb, faces +along */
    _at(o, hole, along, ww, up, 0, n, 0);
    scn_gen_quad(c->b, o, dn, hu, 1, 1, wall); /* jamb, faces -along */
}

/* A facade from `origin` along the unit vector `along` (its outward normal is
 * along x up), width x height metres, tiled with window cells. */
static void _facade(city* c, const float origin[3], const float along[3], float width, float height, uint32_t wall)
{
    static const float up[3] = { 0, 1, 0 };
    float n[3] = { along[1] * up[2] - along[2] * up[1], along[2] * up[0] - along[0] * up[2],
                   along[0] * up[1] - along[1] * up[0] };
    float cell_h = 1.25f * c->cell;
    uint32_t cols = (uint32_t)(width / c->cell), rows = (uint32_t)(height / cell_h);
    if (cols == 0 || rows == 0) { /* budget too small for windows: a plain wall */
        float u[3], v[3];
        _scaled(u, along, width), _scaled(v, up, height);
        scn_gen_quad(c->b, origin, u, v, scn_gen_cells(width, 8.0f), scn_gen_cells(height, 8.0f), wall);
        return;
    }
    if (c->b->count_only) {
        c->b->vertex_total += 4ull * WINDOW_CELL_QUADS * cols * rows;
        c->b->triangle_total += 2ull * WINDOW_CELL_QUADS * cols * rows;
        return;
    }
    float cw = width / cols, ch = height / rows;
    for (uint32_t j = 0; j < rows; j++)
        for (uint32_t i = 0; i < cols; i++) {
            float c0[3];
            _at(c0, origin, along, i * cw, up, j * ch, n, 0);
            _window_cell(c, c0, along, n, cw, ch, wall);
        }
}

/* A building block [x0,x1] x [y0,y1] x [z0,z1]: four facades, a roof, a cornice. */
static void _building(city* c, float x0, float x1, float y0, float y1, float z0, float z1, uint32_t wall)
{
    float o[3], along[3];
    float h = y1 - y0;
    _v3(o, x0, y0, z1), _v3(along, 1, 0, 0);
    _facade(c, o, along, x1 - x0, h, wall); /* +z */
    _v3(o, x1, y0, z0), _v3(along, -1, 0, 0);
    _facade(c, o, along, x1 - x0, h, wall); /* -z */
    _v3(o, x1, y0, z1), _v3(along, 0, 0, -1);
    _facade(c, o, along, z1 - z0, h, wall); /* +x */
    _v3(o, x0, y0, z0), _v3(along, 0, 0, 1);
    _facade(c, o, along, z1 - z0, h, wall); /* -x */
    float lo[3] = { x0 - 0.3f, y1 - 0.5f, z0 - 0.3f }, hi[3] = { x1 + 0.3f, y1, z1 + 0.3f };
    scn_gen_box(c->b, lo, hi, SCN_FACE_ALL, 8.0f, c->roof); /* cornice slab doubles as the roof */
}

static void _rooftop_units(city* c, float x0, float x1, float y, float z0, float z1)
{
    uint32_t units = tv_rng_u32(&c->rng) % 3;
    for (uint32_t k = 0; k < units; k++) {
        float sx = scn_rng_range(&c->rng, 1.5f, 4.0f), sz = scn_rng_range(&c->rng, 1.5f, 4.0f);
        float cx = scn_rng_range(&c->rng, x0 + sx, x1 - sx), cz = scn_rng_range(&c->rng, z0 + sz, z1 - sz);
        float lo[3] = { cx - sx / 2, y, cz - sz / 2 }, hi[3] = { cx + sx / 2, y + scn_rng_range(&c->rng, 1.0f, 3.0f), cz + sz / 2 };
        scn_gen_box(c->b, lo, hi, SCN_FACE_NO_BOTTOM, 0.0f, c->metal);
    }
}

static uint32_t _wall(city* c)
{
    return c->walls[tv_rng_u32(&c->rng) % 3];
}

/* Awning over the ground floor of the lot side facing -z, 4.6 m from the street centre. */
static void _awning(city* c, float x0, float x1, float street_z, float dir)
{
    float z_facade = street_z + dir * 6.0f, z_edge = street_z + dir * 4.6f;
    float lo[3] = { x0, 2.8f, fminf(z_facade, z_edge) }, hi[3] = { x1, 3.0f, fmaxf(z_facade, z_edge) };
    scn_gen_box(c->b, lo, hi, SCN_FACE_ALL, 0.0f, c->awning);
}

static void _park(city* c, float bx, float bz)
{
    /* a fence 5.5 m from the street centres and a few trees */
    float lo_f = 5.5f, hi_f = P - 5.5f;
    for (int side = 0; side < 4; side++) {
        for (float t = lo_f; t <= hi_f + 1e-3f; t += 2.5f) {
            float px = side < 2 ? bx + t : bx + (side == 2 ? lo_f : hi_f);
            float pz = side < 2 ? bz + (side == 0 ? lo_f : hi_f) : bz + t;
            float lo[3] = { px - 0.05f, 0, pz - 0.05f }, hi[3] = { px + 0.05f, 1.2f, pz + 0.05f };
            scn_gen_box(c->b, lo, hi, SCN_FACE_NO_BOTTOM, 0.0f, c->metal);
        }
        float lo[3], hi[3];
        if (side < 2) {
            float z = bz + (side == 0 ? lo_f : hi_f);
            _v3(lo, bx + lo_f, 1.0f, z - 0.03f), _v3(hi, bx + hi_f, 1.1f, z + 0.03f);
        } else {
            float x = bx + (side == 2 ? lo_f : hi_f);
            _v3(lo, x - 0.03f, 1.0f, bz + lo_f), _v3(hi, x + 0.03f, 1.1f, bz + hi_f);
        }
        scn_gen_box(c->b, lo, hi, SCN_FACE_ALL, 4.0f, c->metal);
    }
    uint32_t trees = 3 + tv_rng_u32(&c->rng) % 5;
    for (uint32_t k = 0; k < trees; k++) {
        float tx = bx + scn_rng_range(&c->rng, 10.0f, 30.0f), tz = bz + scn_rng_range(&c->rng, 10.0f, 30.0f);
        float h = scn_rng_range(&c->rng, 4.0f, 9.0f), r = scn_rng_range(&c->rng, 1.5f, 3.0f);
        float lo[3] = { tx - 0.2f, 0, tz - 0.2f }, hi[3] = { tx + 0.2f, h * 0.5f, tz + 0.2f };
        scn_gen_box(c->b, lo, hi, SCN_FACE_NO_BOTTOM, 0.0f, c->awning);
        float clo[3] = { tx - r, h * 0.5f, tz - r }, chi[3] = { tx + r, h, tz + r };
        scn_gen_box(c->b, clo, chi, SCN_FACE_ALL, 1.0f, c->foliage);
    }
}

static void _lamp_posts(city* c, float bx, float bz)
{
    /* two posts on each side of the block, 4.5 m from the street centre,
     * arms reaching to 4.05 m: inside the sidewalk band, outside the street. */
    for (int side = 0; side < 4; side++)
        for (int k = 0; k < 2; k++) {
            float t = k ? 28.0f : 12.0f, d = side & 1 ? P - 4.5f : 4.5f, arm = side & 1 ? 0.4f : -0.4f;
            float px = side < 2 ? bx + t : bx + d, pz = side < 2 ? bz + d : bz + t;
            float lo[3] = { px - 0.08f, 0, pz - 0.08f }, hi[3] = { px + 0.08f, 5.5f, pz + 0.08f };
            scn_gen_box(c->b, lo, hi, SCN_FACE_NO_BOTTOM, 0.0f, c->metal);
            float alo[3] = { px - 0.05f, 5.3f, pz - 0.05f }, ahi[3] = { px + 0.05f, 5.4f, pz + 0.05f };
            float* reach = arm > 0 ? ahi : alo;
            reach[side < 2 ? 2 : 0] += arm;
            scn_gen_box(c->b, alo, ahi, SCN_FACE_ALL, 0.0f, c->metal);
        }
}

static void _block(city* c, int bi, int bj)
{
    float bx = bi * P, bz = bj * P; /* the lot spans [bx+6, bx+34] */
    float r = scn_rng_range(&c->rng, 0.0f, 1.0f);
    _lamp_posts(c, bx, bz);
    if (r < 0.1f) {
        _park(c, bx, bz);
        return;
    }
    if (r < 0.4f) { /* stepped tiers */
        float y = 0.0f;
        uint32_t tiers = 2 + tv_rng_u32(&c->rng) % 2;
        uint32_t wall = _wall(c);
        for (uint32_t t = 0; t < tiers; t++) {
            float inset = 6.0f + 3.0f * t, h = scn_rng_range(&c->rng, 6.0f, 18.0f);
            _building(c, bx + inset, bx + P - inset, y, y + h, bz + inset, bz + P - inset, wall);
            y += h;
        }
        _rooftop_units(c, bx + 6 + 3 * tiers, bx + P - 6 - 3 * tiers, y, bz + 6 + 3 * tiers, bz + P - 6 - 3 * tiers);
    } else if (r < 0.75f) { /* four buildings around alleys */
        for (int q = 0; q < 4; q++) {
            float x0 = bx + (q & 1 ? 21.0f : 6.0f), z0 = bz + (q & 2 ? 21.0f : 6.0f);
            float h = scn_rng_range(&c->rng, 6.0f, 30.0f);
            _building(c, x0, x0 + 13.0f, 0.0f, h, z0, z0 + 13.0f, _wall(c));
            _rooftop_units(c, x0, x0 + 13.0f, h, z0, z0 + 13.0f);
        }
    } else { /* tower on a podium */
        float podium = scn_rng_range(&c->rng, 5.0f, 8.0f), h = scn_rng_range(&c->rng, 45.0f, 110.0f);
        _building(c, bx + 6, bx + P - 6, 0.0f, podium, bz + 6, bz + P - 6, _wall(c));
        _building(c, bx + 12, bx + P - 12, podium, podium + h, bz + 12, bz + P - 12, _wall(c));
        _rooftop_units(c, bx + 12, bx + P - 12, podium + h, bz + 12, bz + P - 12);
    }
    if (scn_rng_range(&c->rng, 0.0f, 1.0f) < 0.5f)
        _awning(c, bx + 9.0f, bx + 24.0f, bz, 1.0f);
}

static void _ground(city* c, int n)
{
    /* 5 m cells: asphalt within 5 m of a centreline, pavement elsewhere */
    float extent = n * P + 10.0f;
    int cells = (int)(2 * extent / 5.0f);
    for (int j = 0; j < cells; j++)
        for (int i = 0; i < cells; i++) {
            float x = -extent + 5.0f * i, z = -extent + 5.0f * j;
            float fx = fmodf(x + 1000 * P, P), fz = fmodf(z + 1000 * P, P);
            bool street = fx < 5.0f || fx >= P - 5.0f || fz < 5.0f || fz >= P - 5.0f;
            float o[3] = { x, 0, z }, u[3] = { 0, 0, 5.0f }, v[3] = { 5.0f, 0, 0 }; /* z x x = +y */
            scn_gen_quad(c->b, o, u, v, 1, 1, street ? c->asphalt : c->pavement);
        }
}

static void _city_emit(scn_builder* b, uint64_t seed, int n, float cell)
{
    city c = { .b = b, .cell = cell };
    tv_rng_seed(&c.rng, seed, 0xC17);
    scn_gen_add_textures(b);
    c.asphalt = scn_gen_material(b, "asphalt", SCN_GEN_TEX_CONCRETE, 0.35f, 0.35f, 0.38f, false);
    c.pavement = scn_gen_material(b, "pavement", SCN_GEN_TEX_TILES, 0.8f, 0.78f, 0.72f, false);
    c.walls[0] = scn_gen_material(b, "brick", SCN_GEN_TEX_BRICKS, 1.0f, 1.0f, 1.0f, false);
    c.walls[1] = scn_gen_material(b, "facade", SCN_GEN_TEX_FACADE, 0.95f, 0.9f, 0.8f, false);
    c.walls[2] = scn_gen_material(b, "concrete", SCN_GEN_TEX_CONCRETE, 0.9f, 0.9f, 0.95f, false);
    c.glass = scn_gen_material(b, "glass", SCN_GEN_TEX_FACADE, 0.45f, 0.6f, 0.8f, false);
    c.roof = scn_gen_material(b, "roof", SCN_GEN_TEX_CONCRETE, 0.55f, 0.5f, 0.5f, false);
    c.metal = scn_gen_material(b, "metal", SCN_GEN_TEX_CONCRETE, 0.3f, 0.32f, 0.3f, false);
    c.awning = scn_gen_material(b, "awning", SCN_GEN_TEX_WOOD, 0.9f, 0.5f, 0.4f, false);
    c.foliage = scn_gen_material(b, "foliage", SCN_GEN_TEX_CONCRETE, 0.3f, 0.6f, 0.25f, false);
    _ground(&c, n);
    for (int bj = -n; bj < n; bj++)
        for (int bi = -n; bi < n; bi++)
            _block(&c, bi, bj);
}

static uint64_t _city_count(uint64_t seed, int n, float cell)
{
    scn_scene scratch;
    scn_builder counter;
    scn_builder_init(&counter, &scratch, true);
    _city_emit(&counter, seed, n, cell);
    uint64_t tris = counter.triangle_total;
    scn_builder_abort(&counter);
    return tris;
}

void scn_gen_city(scn_builder* b, uint64_t seed, uint32_t tris, uint32_t movers)
{
    int n = tris <= 300000 ? 2 : tris <= 1200000 ? 3 : 4; /* blocks per half-extent */
    float lo = logf(0.25f), hi = logf(40.0f);
    for (int it = 0; it < 30; it++) { /* more triangles for smaller cells */
        float mid = 0.5f * (lo + hi);
        if (_city_count(seed, n, expf(mid)) > tris)
            lo = mid;
        else
            hi = mid;
    }
    float cell = expf(lo); /* the largest cell still giving at least `tris` */
    tv_log(TV_LOG_DEBUG, "builtin:city: %d blocks per side, window cell %.3f m for %u triangles", 2 * n, cell, tris);
    _city_emit(b, seed, n, cell);
    scn_gen_city_movers(b, seed, n, movers);
}
