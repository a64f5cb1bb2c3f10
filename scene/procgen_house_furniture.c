/* procgen_house_furniture.c - builtin:house's furniture: tables, chairs,
 * shelves full of books, beds, wardrobes, a sofa, kitchen counters and bath
 * fittings, each a cluster of touching or interpenetrating boxes.
 *
 * Positions are fixed per room and keep the bundled walk's lanes clear
 * (procedural.h); the seed varies sizes, book rows and open doors only.
 */
#include "procgen_house.h"

#include <math.h>

/* Table top [x0,x1] x [z0,z1] at height top above floor y0; legs 1 cm into the top. */
static void _table(house* h, float x0, float z0, float x1, float z1, float y0, float top)
{
    house_part(h, x0, y0 + top - 0.04f, z0, x1, y0 + top, z1, h->wood);
    for (int i = 0; i < 4; i++) {
        float x = (i & 1) ? x1 - 0.08f : x0 + 0.03f, z = (i & 2) ? z1 - 0.08f : z0 + 0.03f;
        house_part(h, x, y0, z, x + 0.05f, y0 + top - 0.03f, z + 0.05f, h->wood);
    }
}

/* Chair centred at (x, z) whose sitter faces (fx, fz) (one of the axes). */
static void _chair(house* h, float x, float z, float fx, float fz, float y0)
{
    const float r = 0.21f;
    _table(h, x - r, z - r, x + r, z + r, y0, 0.45f);
    float bx = x - fx * (r - 0.015f), bz = z - fz * (r - 0.015f);
    float hx = fz != 0 ? r : 0.015f, hz = fx != 0 ? r : 0.015f;
    house_part(h, bx - hx, y0 + 0.45f, bz - hz, bx + hx, y0 + 0.9f, bz + hz, h->wood);
}

/* Shelf unit along `along` over [s0, s1], back at t_back against a wall,
 * front at t_front, `boards` boards up to height ht, each but the top one
 * carrying a seeded row of books packed side by side. */
static void _shelf(house* h, int along, float s0, float s1, float t_back, float t_front, float y0, float ht,
                   int boards)
{
    const float side = 0.02f, th = 0.02f;
    float dir = t_front > t_back ? 1.0f : -1.0f, depth = fabsf(t_front - t_back);
    house_span(h, along, s0, s0 + side, t_back, t_front, y0, y0 + ht, 0, h->wood);
    house_span(h, along, s1 - side, s1, t_back, t_front, y0, y0 + ht, 0, h->wood);
    house_span(h, along, s0 + side, s1 - side, t_back, t_back + dir * 0.006f, y0, y0 + ht, 0, h->wood);
    float pitch = (ht - th) / (float)(boards - 1);
    for (int i = 0; i < boards; i++) {
        float yb = y0 + i * pitch;
        house_span(h, along, s0 + side - 0.005f, s1 - side + 0.005f, t_back, t_front, yb, yb + th, 0, h->wood);
        if (i == boards - 1)
            break;
        float s = s0 + side, tallest = fminf(0.3f, pitch - th - 0.03f);
        while (true) {
            if (tv_rng_u32(&h->rng) % 7 == 0)
                s += scn_rng_range(&h->rng, 0.03f, 0.12f);
            float w = scn_rng_range(&h->rng, 0.02f, 0.05f);
            if (s + w > s1 - side)
                break;
            float bh = scn_rng_range(&h->rng, 0.6f, 1.0f) * tallest;
            float bd = scn_rng_range(&h->rng, 0.6f, 0.95f) * depth;
            float back = t_back + dir * 0.006f;
            house_span(h, along, s, s + w, back, back + dir * bd, yb + th, yb + th + bh, 0, h->book);
            s += w;
        }
    }
}

/* Bed over [x0,x1] x [z0,z1], headboard on the x0 side (head < 0) or the x1 side. */
static void _bed(house* h, float x0, float z0, float x1, float z1, float y0, int head)
{
    house_part(h, x0, y0 + 0.12f, z0, x1, y0 + 0.35f, z1, h->wood);
    _table(h, x0, z0, x1, z1, y0, 0.14f); /* a low platform: its legs */
    house_part(h, x0 + 0.03f, y0 + 0.35f, z0 + 0.03f, x1 - 0.03f, y0 + 0.55f, z1 - 0.03f, h->fabric);
    float hx = head < 0 ? x0 : x1 - 0.05f, px = head < 0 ? x0 + 0.08f : x1 - 0.48f;
    house_part(h, hx, y0, z0 - 0.02f, hx + 0.05f, y0 + 1.0f, z1 + 0.02f, h->wood);
    for (float z = z0 + 0.1f; z + 0.6f <= z1 - 0.05f; z += 0.7f)
        house_part(h, px, y0 + 0.55f, z, px + 0.4f, y0 + 0.68f, z + 0.6f, h->fabric);
}

/* Wardrobe along `along` over [s0, s1] against the wall at t_back: carcass,
 * doors 0.6 m wide touching its front and a handle through each. */
static void _wardrobe(house* h, int along, float s0, float s1, float t_back, float t_front, float y0)
{
    float dir = t_front > t_back ? 1.0f : -1.0f;
    house_span(h, along, s0, s1, t_back, t_front, y0, y0 + 2.1f, 0, h->wood);
    int doors = (int)((s1 - s0) / 0.6f + 0.5f);
    float w = (s1 - s0) / (float)doors;
    for (int i = 0; i < doors; i++) {
        float a = s0 + i * w + 0.003f, b = s0 + (i + 1) * w - 0.003f;
        house_span(h, along, a, b, t_front, t_front + dir * 0.02f, y0 + 0.05f, y0 + 2.05f, 0, h->door);
        float hs = (i & 1) ? a + 0.05f : b - 0.07f;
        house_span(h, along, hs, hs + 0.02f, t_front - dir * 0.01f, t_front + dir * 0.05f, y0 + 0.9f, y0 + 1.2f, 0,
                   h->metal);
    }
}

/* Kitchen counter along `along` over [s0, s1]: 0.6 m carcasses side by
 * side, door fronts and handles, a worktop overhanging 2 cm, wall cabinets. */
static void _counter(house* h, int along, float s0, float s1, float t_back, float y0)
{
    float td = t_back < 0 ? 1.0f : -1.0f, t_front = t_back + td * 0.6f; /* the wall is on the outer side */
    for (float s = s0; s + 0.3f < s1; s += 0.6f) {
        float e = fminf(s + 0.6f, s1);
        house_span(h, along, s, e, t_back, t_front, y0 + 0.1f, y0 + 0.87f, 0, h->wood);
        house_span(h, along, s + 0.003f, e - 0.003f, t_front, t_front + td * 0.02f, y0 + 0.12f, y0 + 0.85f, 0, h->door);
        house_span(h, along, s + 0.2f, e - 0.2f, t_front + td * 0.01f, t_front + td * 0.04f, y0 + 0.75f, y0 + 0.77f, 0,
                   h->metal);
        house_span(h, along, s, e, t_back, t_back + td * 0.35f, y0 + 1.45f, y0 + 2.15f, 0, h->wood);
        house_span(h, along, s + 0.003f, e - 0.003f, t_back + td * 0.35f, t_back + td * 0.37f, y0 + 1.47f, y0 + 2.13f,
                   0, h->door);
    }
    house_span(h, along, s0, s1, t_back, t_front + td * 0.02f, y0 + 0.87f, y0 + 0.91f, 0, h->tile);
}

static void _sofa(house* h, float x0, float z0, float x1, float z1, float y0)
{
    house_part(h, x0, y0, z0, x1, y0 + 0.42f, z1, h->fabric);
    house_part(h, x0, y0 + 0.42f, z0, x0 + 0.2f, y0 + 0.85f, z1, h->fabric);
    house_part(h, x0, y0 + 0.42f, z0, x1, y0 + 0.65f, z0 + 0.18f, h->fabric);
    house_part(h, x0, y0 + 0.42f, z1 - 0.18f, x1, y0 + 0.65f, z1, h->fabric);
    float w = (z1 - z0 - 0.36f) / 3.0f;
    for (int i = 0; i < 3; i++)
        house_part(h, x0 + 0.2f, y0 + 0.42f, z0 + 0.18f + i * w, x1, y0 + 0.55f, z0 + 0.18f + (i + 1) * w, h->fabric);
}

/* WC and basin against the wall x = wx, reaching into the room towards `side`. */
static void _wc(house* h, float wx, float z, float y0, float side)
{
    house_part(h, wx, y0, z - 0.2f, wx + side * 0.2f, y0 + 0.8f, z + 0.2f, h->tile);
    house_part(h, wx + side * 0.15f, y0, z - 0.18f, wx + side * 0.65f, y0 + 0.42f, z + 0.18f, h->tile);
    house_part(h, wx + side * 0.2f, y0 + 0.42f, z - 0.19f, wx + side * 0.66f, y0 + 0.44f, z + 0.19f, h->fabric);
}

static void _basin(house* h, float wx, float z, float y0, float side)
{
    house_part(h, wx, y0 + 0.8f, z - 0.3f, wx + side * 0.45f, y0 + 0.88f, z + 0.3f, h->tile);
    house_part(h, wx, y0, z - 0.06f, wx + side * 0.12f, y0 + 0.8f, z + 0.06f, h->tile);
    house_part(h, wx, y0 + 0.88f, z - 0.015f, wx + side * 0.15f, y0 + 1.05f, z + 0.015f, h->metal);
    house_part(h, wx, y0 + 1.2f, z - 0.3f, wx + side * 0.03f, y0 + 1.9f, z + 0.3f, h->metal); /* mirror */
}

static void _ground_floor(house* h)
{
    /* living room */
    _sofa(h, -5.65f, -3.4f, -4.8f, -1.0f, 0);
    _table(h, -4.7f, -2.6f, -4.3f, -1.6f, 0, 0.45f);
    _shelf(h, 0, -4.8f, -1.8f, -4.2f, -3.85f, 0, 2.0f, 6);
    _shelf(h, 2, -0.6f, 0.45f, -5.7f, -5.35f, 0, 1.2f, 4);
    _table(h, -2.0f, -1.0f, -1.6f, 0.3f, 0, 0.55f);
    /* kitchen */
    _counter(h, 0, -5.7f, -2.0f, 4.2f, 0);
    _counter(h, 2, 0.62f, 3.6f, -5.7f, 0);
    /* hall */
    _table(h, -1.44f, -1.2f, -1.1f, 0.4f, 0, 0.8f);
    /* dining room */
    _table(h, 3.0f, -2.3f, 4.6f, -1.2f, 0, 0.75f);
    for (int i = 0; i < 2; i++)
        _chair(h, 3.45f + i * 0.8f, -0.9f, 0, -1, 0);
    _chair(h, 4.9f, -1.75f, -1, 0, 0);
    _chair(h, 2.69f, -1.75f, 1, 0, 0);
    _shelf(h, 0, 4.0f, 5.6f, -4.2f, -3.85f, 0, 2.0f, 6);
    _wardrobe(h, 2, -2.4f, -0.6f, 5.7f, 5.2f, 0);
    /* utility room */
    _shelf(h, 0, 2.2f, 3.8f, 4.2f, 3.85f, 0, 1.8f, 5);
    house_part(h, 5.1f, 0, 3.5f, 5.7f, 0.85f, 4.15f, h->metal);
    _wc(h, 5.7f, 2.8f, 0, -1.0f);
    _basin(h, 5.7f, 1.9f, 0, -1.0f);
}

static void _upper_floor(house* h)
{
    const float y = 3.0f;
    /* west bedrooms */
    _bed(h, -5.7f, -2.6f, -3.7f, -1.0f, y, -1);
    _wardrobe(h, 0, -3.5f, -1.9f, -4.2f, -3.6f, y);
    _table(h, -2.65f, -0.2f, -1.6f, 0.45f, y, 0.75f);
    _chair(h, -2.1f, -0.45f, 0, 1, y);
    _shelf(h, 0, -5.6f, -4.4f, 0.5f, 0.15f, y, 1.6f, 5);
    _bed(h, -5.7f, 2.8f, -3.7f, 3.7f, y, -1);
    _wardrobe(h, 0, -3.4f, -2.0f, 4.2f, 3.6f, y);
    _shelf(h, 2, 0.8f, 2.4f, -5.7f, -5.35f, y, 2.0f, 6);
    /* east bedroom */
    _bed(h, 3.7f, -3.6f, 5.7f, -2.0f, y, 1);
    _table(h, 1.9f, -0.7f, 3.0f, -0.06f, y, 0.75f);
    _chair(h, 2.45f, -0.95f, 0, 1, y);
    _shelf(h, 2, -1.8f, -0.3f, 5.7f, 5.35f, y, 2.0f, 6);
    /* bathroom: tub with a rim round a sunk floor, WC, basin, cabinet */
    house_part(h, 3.9f, y, 3.4f, 5.7f, y + 0.55f, 3.48f, h->tile);
    house_part(h, 3.9f, y, 3.48f, 3.98f, y + 0.55f, 4.2f, h->tile);
    house_part(h, 3.98f, y, 3.48f, 5.7f, y + 0.1f, 4.2f, h->tile);
    _wc(h, 5.7f, 1.2f, y, -1.0f);
    _basin(h, 5.7f, 2.3f, y, -1.0f);
    _shelf(h, 0, 2.0f, 3.0f, 4.2f, 3.9f, y, 1.8f, 5);
}

void house_furnish(house* h)
{
    _ground_floor(h);
    _upper_floor(h);
}
