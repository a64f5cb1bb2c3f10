/* procgen_house.c - builtin:house, a detailed two-storey house.
 *
 * Built the way CAD/BIM exports are: every part is its own closed box, and
 * parts touch, share coplanar faces or pass into each other (frames into
 * reveals, slabs into walls, legs into table tops, books side by side). The
 * layout is the contract in procedural.h; the walls, slabs and windows come
 * from here, the furniture from procgen_house_furniture.c.
 */
#include "procgen_house.h"

#include <math.h>

#define CELL 0.5f     /* walls and slabs: cells so the PVS octree has triangles to sort */
#define STOREY 3.0f   /* floor-to-floor height */
#define SLAB 0.25f    /* upper floor slab thickness (underside at 2.75 m) */
#define OUT_X 6.0f    /* outer half extents */
#define OUT_Z 4.5f
#define EXT 0.3f      /* exterior wall thickness */
#define INT_HALF 0.06f /* interior walls: 0.12 m */
#define DOOR_W 1.0f /* 0.96 m clear: the walkable rule's 0.5 m grid finds a column through it */
#define DOOR_H 2.1f
#define YARD_Y -0.15f

/* Stairs: 16 risers up the hall's east side towards -z, open side at x = STAIR_X0. */
#define STAIR_X0 0.4f
#define STAIR_Z0 2.2f
#define STAIR_GOING 0.26f
#define STAIR_RISERS 16
#define TREAD 0.06f /* tread thickness: over the walkable rule's 5 cm floor merge, so treads are floors */
#define HOLE_Z1 1.4f /* slab opening over the stairs: z in [STAIR_Z0 - 15 goings, HOLE_Z1] */

void house_span(house* h, int along, float s0, float s1, float t0, float t1, float y0, float y1, float cell,
                uint32_t m)
{
    float a0 = fminf(s0, s1), a1 = fmaxf(s0, s1), c0 = fminf(t0, t1), c1 = fmaxf(t0, t1);
    float lo[3] = { along == 0 ? a0 : c0, y0, along == 0 ? c0 : a0 };
    float hi[3] = { along == 0 ? a1 : c1, y1, along == 0 ? c1 : a1 };
    scn_gen_box(h->b, lo, hi, SCN_FACE_ALL, cell, m);
}

void house_part(house* h, float x0, float y0, float z0, float x1, float y1, float z1, uint32_t m)
{
    house_span(h, 0, x0, x1, z0, z1, y0, y1, 0.0f, m);
}

/* An opening in a wall: centre and width along it, sill and head heights. */
typedef struct opening {
    float c, w, sill, head;
} opening;

/* A wall from s0 to s1 along `along`, across [t0, t1], up [y0, y1], with
 * openings (sorted by centre): piers between them, a piece below each
 * opening above y0 and a lintel piece above each. */
static void _wall(house* h, int along, float s0, float s1, float t0, float t1, float y0, float y1,
                  const opening* op, int n)
{
    float s = s0;
    for (int i = 0; i < n; i++) {
        float lo = op[i].c - op[i].w / 2, hi = op[i].c + op[i].w / 2;
        house_span(h, along, s, lo, t0, t1, y0, y1, CELL, h->wall);
        if (op[i].sill > y0)
            house_span(h, along, lo, hi, t0, t1, y0, op[i].sill, CELL, h->wall);
        house_span(h, along, lo, hi, t0, t1, op[i].head, y1, CELL, h->wall);
        s = hi;
    }
    house_span(h, along, s, s1, t0, t1, y0, y1, CELL, h->wall);
}

/* Window in the opening o of a wall across [t0, t1] whose outside is the t1
 * side when out > 0: frame, mullion, transom, glazing beads on the inside of
 * each of the four panes, outer sill and inner window board. No glass. */
static void _window(house* h, int along, opening o, float t0, float t1, float out)
{
    const float f = 0.07f, fd = 0.035f, md = 0.025f, bead = 0.02f;
    float lo = o.c - o.w / 2, hi = o.c + o.w / 2, tm = (t0 + t1) / 2;
    float outer = out > 0 ? t1 : t0, inner = out > 0 ? t0 : t1;
    house_span(h, along, lo, lo + f, tm - fd, tm + fd, o.sill, o.head, 0, h->frame);
    house_span(h, along, hi - f, hi, tm - fd, tm + fd, o.sill, o.head, 0, h->frame);
    house_span(h, along, lo, hi, tm - fd, tm + fd, o.sill, o.sill + f, 0, h->frame);
    house_span(h, along, lo, hi, tm - fd, tm + fd, o.head - f, o.head, 0, h->frame);
    float yt = o.sill + 0.68f * (o.head - o.sill);
    house_span(h, along, o.c - md, o.c + md, tm - md, tm + md, o.sill + f - 0.01f, o.head - f + 0.01f, 0, h->frame);
    house_span(h, along, lo + f - 0.01f, hi - f + 0.01f, tm - md, tm + md, yt - md, yt + md, 0, h->frame);
    float cols[2][2] = { { lo + f, o.c - md }, { o.c + md, hi - f } };
    float rows[2][2] = { { o.sill + f, yt - md }, { yt + md, o.head - f } };
    float b0 = tm - out * md, b1 = b0 - out * 0.015f; /* beads against the mullion's inner face */
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            float a0 = cols[i][0], a1 = cols[i][1], r0 = rows[j][0], r1 = rows[j][1];
            house_span(h, along, a0, a0 + bead, b0, b1, r0, r1, 0, h->frame);
            house_span(h, along, a1 - bead, a1, b0, b1, r0, r1, 0, h->frame);
            house_span(h, along, a0, a1, b0, b1, r0, r0 + bead, 0, h->frame);
            house_span(h, along, a0, a1, b0, b1, r1 - bead, r1, 0, h->frame);
        }
    house_span(h, along, lo - 0.04f, hi + 0.04f, tm, outer + out * 0.05f, o.sill - 0.04f, o.sill, 0, h->frame);
    house_span(h, along, lo - 0.05f, hi + 0.05f, tm - out * fd, inner - out * 0.03f, o.sill, o.sill + 0.025f, 0,
               h->wood);
}

/* Door in the opening o (floor at y0) of a wall across [t0, t1]: linings,
 * architraves on both faces, a leaf hinged at the low end and a handle.
 * swing 0: closed in the wall's middle; +1 / -1: open at 90 degrees on the
 * t1 / t0 side, against the lining. */
static void _door(house* h, int along, opening o, float y0, float t0, float t1, int swing)
{
    float lo = o.c - o.w / 2, hi = o.c + o.w / 2, tm = (t0 + t1) / 2, head = o.head;
    house_span(h, along, lo, lo + 0.02f, t0, t1, y0, head, 0, h->door);
    house_span(h, along, hi - 0.02f, hi, t0, t1, y0, head, 0, h->door);
    house_span(h, along, lo, hi, t0, t1, head - 0.02f, head, 0, h->door);
    for (int side = 0; side < 2; side++) {
        float a = side ? t1 : t0, b = side ? t1 + 0.015f : t0 - 0.015f;
        house_span(h, along, lo - 0.07f, lo, a, b, y0, head + 0.07f, 0, h->frame);
        house_span(h, along, hi, hi + 0.07f, a, b, y0, head + 0.07f, 0, h->frame);
        house_span(h, along, lo - 0.07f, hi + 0.07f, a, b, head, head + 0.07f, 0, h->frame);
    }
    float leaf = o.w - 0.04f, yh = y0 + 1.0f;
    if (swing == 0) {
        house_span(h, along, lo + 0.02f, hi - 0.02f, tm - 0.02f, tm + 0.02f, y0 + 0.01f, head - 0.03f, 0, h->door);
        house_span(h, along, hi - 0.12f, hi - 0.08f, tm - 0.08f, tm + 0.08f, yh, yh + 0.03f, 0, h->metal);
    } else {
        float face = swing > 0 ? t1 : t0, end = face + swing * leaf;
        house_span(h, along, lo + 0.02f, lo + 0.06f, face, end, y0 + 0.01f, head - 0.03f, 0, h->door);
        house_span(h, along, lo - 0.02f, lo + 0.10f, end - swing * 0.12f, end - swing * 0.08f, yh, yh + 0.03f, 0,
                   h->metal);
    }
}

/* Exterior walls of storey k (y in [k*STOREY, (k+1)*STOREY]) with their windows
 * and, on the ground floor, the front door. Windows: 0.9-2.1 m above the floor. */
static void _facades(house* h, int k)
{
    float y0 = k * STOREY, y1 = y0 + STOREY, sill = y0 + 0.9f, head = y0 + 2.1f;
    opening south[5] = { { -4.4f, 1.2f, sill, head }, { -2.7f, 1.2f, sill, head }, { 0.0f, 0.8f, sill, head },
                         { 2.7f, 1.2f, sill, head }, { 4.4f, 1.2f, sill, head } };
    opening north[5] = { { -4.4f, 1.2f, sill, head }, { -2.7f, 1.2f, sill, head }, { -0.75f, 1.0f, sill, head },
                         { 2.7f, 1.2f, sill, head }, { 4.4f, 1.2f, sill, head } };
    opening west[2] = { { -2.2f, 1.2f, sill, head }, { 2.4f, 1.2f, sill, head } };
    opening east[2] = { { -2.2f, 1.2f, sill, head }, { 2.2f, 1.2f, sill, head } };
    if (k == 0)
        north[2] = (opening){ -0.75f, 1.2f, y0, y0 + 2.2f }; /* front door */
    _wall(h, 0, -OUT_X, OUT_X, -OUT_Z, -OUT_Z + EXT, y0, y1, south, 5);
    _wall(h, 0, -OUT_X, OUT_X, OUT_Z - EXT, OUT_Z, y0, y1, north, 5);
    _wall(h, 2, -OUT_Z + EXT, OUT_Z - EXT, -OUT_X, -OUT_X + EXT, y0, y1, west, 2);
    _wall(h, 2, -OUT_Z + EXT, OUT_Z - EXT, OUT_X - EXT, OUT_X, y0, y1, east, 2);
    for (int i = 0; i < 5; i++) {
        _window(h, 0, south[i], -OUT_Z, -OUT_Z + EXT, -1.0f);
        if (k == 0 && i == 2)
            _door(h, 0, north[i], y0, OUT_Z - EXT, OUT_Z, -1);
        else
            _window(h, 0, north[i], OUT_Z - EXT, OUT_Z, 1.0f);
    }
    for (int i = 0; i < 2; i++) {
        _window(h, 2, west[i], -OUT_X, -OUT_X + EXT, -1.0f);
        _window(h, 2, east[i], OUT_X - EXT, OUT_X, 1.0f);
    }
}

/* Interior walls of storey k: the hall's walls x = +-1.5 and one cross wall
 * on each side. Door centres sit on the walkable rule's grid (x, z = 0.25
 * mod 0.5 m, from the yard's corner), each listed with its swing (open doors swing into the
 * room, away from the hall). Doors on the bundled walk are always open; the
 * others are closed at random. */
static void _partitions(house* h, int k)
{
    float y0 = k * STOREY, y1 = (k + 1) * STOREY - (k == 0 ? SLAB : 0.0f) + 0.05f; /* 5 cm into the slab above */
    float head = y0 + DOOR_H, wi = 5.7f;
    opening hall_w[2] = { { -2.25f, DOOR_W, y0, head }, { 2.25f, DOOR_W, y0, head } };
    opening hall_e[2] = { { -3.25f, DOOR_W, y0, head }, { 3.25f, DOOR_W, y0, head } };
    opening cross_w[1] = { { -3.25f, DOOR_W, y0, head } }, cross_e[1] = { { 3.75f, DOOR_W, y0, head } };
    _wall(h, 2, -4.2f, 4.2f, -1.5f - INT_HALF, -1.5f + INT_HALF, y0, y1, hall_w, 2);
    _wall(h, 2, -4.2f, 4.2f, 1.5f - INT_HALF, 1.5f + INT_HALF, y0, y1, hall_e, 2);
    _wall(h, 0, -wi, -1.5f - INT_HALF, 0.56f - INT_HALF, 0.56f + INT_HALF, y0, y1, cross_w, 1);
    _wall(h, 0, 1.5f + INT_HALF, wi, -INT_HALF, INT_HALF, y0, y1, cross_e, 1);
    bool walked = k == 0;
    for (int i = 0; i < 2; i++) {
        bool open_w = walked || (tv_rng_u32(&h->rng) & 1), open_e = (walked && i == 0) || (tv_rng_u32(&h->rng) & 1);
        _door(h, 2, hall_w[i], y0, -1.5f - INT_HALF, -1.5f + INT_HALF, open_w ? -1 : 0);
        _door(h, 2, hall_e[i], y0, 1.5f - INT_HALF, 1.5f + INT_HALF, open_e ? 1 : 0);
    }
    _door(h, 0, cross_w[0], y0, 0.56f - INT_HALF, 0.56f + INT_HALF, walked || (tv_rng_u32(&h->rng) & 1) ? 1 : 0);
    _door(h, 0, cross_e[0], y0, -INT_HALF, INT_HALF, (tv_rng_u32(&h->rng) & 1) ? 1 : 0);
}

/* Stairs: 6 cm treads with a 3 cm nosing, risers, stringers stepped along both
 * sides, a baluster per tread and a stepped handrail; then the railing
 * round the slab opening on the upper floor. */
static void _stairs(house* h)
{
    const float rise = STOREY / STAIR_RISERS, x1 = 1.5f - INT_HALF;
    for (int k = 1; k <= STAIR_RISERS; k++) {
        float zk = STAIR_Z0 - (k - 1) * STAIR_GOING, zn = zk - STAIR_GOING, top = k * rise;
        house_part(h, STAIR_X0, (k - 1) * rise, zk - 0.02f, x1, top - (k < STAIR_RISERS ? TREAD : 0.0f), zk,
                   h->stair);
        if (k == STAIR_RISERS)
            break;
        house_part(h, STAIR_X0, top - TREAD, zn, x1, top, zk + 0.03f, h->stair);
        float sy0 = fmaxf(0.0f, (k - 1) * rise - 0.15f);
        house_part(h, STAIR_X0 - 0.06f, sy0, zn, STAIR_X0, top + 0.05f, zk, h->stair);
        house_part(h, x1 - 0.04f, sy0, zn, x1, top + 0.05f, zk, h->stair);
        float zc = zk - STAIR_GOING / 2;
        house_part(h, STAIR_X0 - 0.045f, top, zc - 0.015f, STAIR_X0 - 0.015f, top + 0.9f, zc + 0.015f, h->wood);
        house_part(h, STAIR_X0 - 0.055f, top + 0.9f, zn, STAIR_X0 - 0.005f, top + 0.95f, zk, h->wood);
    }
    float zs = STAIR_Z0 - (STAIR_RISERS - 1) * STAIR_GOING, y = STOREY;
    for (float z = zs + 0.06f; z < HOLE_Z1; z += 0.12f)
        house_part(h, STAIR_X0 - 0.045f, y, z - 0.015f, STAIR_X0 - 0.015f, y + 0.9f, z + 0.015f, h->wood);
    for (float x = STAIR_X0 + 0.06f; x < x1; x += 0.12f)
        house_part(h, x - 0.015f, y, HOLE_Z1 + 0.015f, x + 0.015f, y + 0.9f, HOLE_Z1 + 0.045f, h->wood);
    house_part(h, STAIR_X0 - 0.055f, y + 0.9f, zs, STAIR_X0 - 0.005f, y + 0.95f, HOLE_Z1 + 0.055f, h->wood);
    house_part(h, STAIR_X0 - 0.055f, y + 0.9f, HOLE_Z1 + 0.005f, x1, y + 0.95f, HOLE_Z1 + 0.055f, h->wood);
}

/* Ground slab, the upper slab in four pieces round the stair opening, an
 * overhanging roof slab and the yard around the house. */
static void _slabs(house* h)
{
    float lo[3] = { -OUT_X, YARD_Y, -OUT_Z }, hi[3] = { OUT_X, 0.0f, OUT_Z };
    scn_gen_box(h->b, lo, hi, SCN_FACE_ALL, CELL, h->slab);
    float y0 = STOREY - SLAB, y1 = STOREY, wi = OUT_X - EXT, di = OUT_Z - EXT;
    float x1 = 1.5f - INT_HALF, zs = STAIR_Z0 - (STAIR_RISERS - 1) * STAIR_GOING;
    house_span(h, 0, -wi, STAIR_X0, -di, di, y0, y1, CELL, h->slab);
    house_span(h, 0, x1, wi, -di, di, y0, y1, CELL, h->slab);
    house_span(h, 0, STAIR_X0, x1, -di, zs, y0, y1, CELL, h->slab);
    house_span(h, 0, STAIR_X0, x1, HOLE_Z1, di, y0, y1, CELL, h->slab);
    house_span(h, 0, -OUT_X - 0.3f, OUT_X + 0.3f, -OUT_Z - 0.3f, OUT_Z + 0.3f, 2 * STOREY, 2 * STOREY + 0.25f, CELL,
               h->slab);
    float o[3] = { -12.0f, YARD_Y, -10.0f }, u[3] = { 0, 0, 20.0f }, v[3] = { 24.0f, 0, 0 }; /* z x x = +y */
    scn_gen_quad(h->b, o, u, v, 20, 24, h->tile);
}

void scn_gen_house(scn_builder* b, uint64_t seed)
{
    house h = { .b = b };
    tv_rng_seed(&h.rng, seed, 0x40E5);
    scn_gen_add_textures(b);
    float tint = scn_rng_range(&h.rng, 0.85f, 1.0f);
    h.wall = scn_gen_material(b, "wall", SCN_GEN_TEX_FACADE, tint, 0.95f, 0.9f, false);
    h.slab = scn_gen_material(b, "slab", SCN_GEN_TEX_CONCRETE, 0.9f, 0.9f, 0.88f, false);
    h.frame = scn_gen_material(b, "frame", -1, 0.95f, 0.95f, 0.95f, false);
    h.door = scn_gen_material(b, "door", SCN_GEN_TEX_WOOD, 0.9f, 0.8f, 0.7f, false);
    h.stair = scn_gen_material(b, "stair", SCN_GEN_TEX_WOOD, 0.75f, 0.6f, 0.45f, false);
    h.wood = scn_gen_material(b, "furniture", SCN_GEN_TEX_WOOD, 0.8f, tint, 0.7f, false);
    h.fabric = scn_gen_material(b, "fabric", SCN_GEN_TEX_TILES, 0.5f, 0.6f, 0.8f, false);
    h.metal = scn_gen_material(b, "metal", -1, 0.6f, 0.6f, 0.65f, false);
    h.book = scn_gen_material(b, "book", -1, 0.7f, 0.3f, 0.25f, false);
    h.tile = scn_gen_material(b, "tile", SCN_GEN_TEX_TILES, 0.8f, 0.8f, 0.75f, false);
    _slabs(&h);
    for (int k = 0; k < 2; k++) {
        _facades(&h, k);
        _partitions(&h, k);
    }
    _stairs(&h);
    house_furnish(&h);
}
