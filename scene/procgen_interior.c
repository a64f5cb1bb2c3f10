/* procgen_interior.c - builtin:interior, rooms off a corridor.
 *
 * Coordinates are the layout contract in procedural.h. Surfaces are split
 * into cells of at most 1 m so the PVS octree has triangles to sort.
 */
#include "procgen.h"

#define CELL 1.0f
#define H 3.0f
#define WALL 0.2f
#define DOOR_HALF 0.6f
#define DOOR_H 2.2f

static const float room_x[4] = { -18.0f, -6.0f, 6.0f, 18.0f };

typedef struct interior {
    scn_builder* b;
    tv_rng rng;
    uint32_t floor, wall, ceiling, column, furniture, partition;
} interior;

static void _box(interior* in, float x0, float y0, float z0, float x1, float y1, float z1, unsigned faces, uint32_t m)
{
    float lo[3] = { x0, y0, z0 }, hi[3] = { x1, y1, z1 };
    scn_gen_box(in->b, lo, hi, faces, CELL, m);
}

/* Floor (facing up) and ceiling (facing down) over [x0,x1] x [z0,z1]. */
static void _floor_ceiling(interior* in, float x0, float x1, float z0, float z1)
{
    float dx = x1 - x0, dz = z1 - z0;
    float o[3] = { x0, 0, z0 }, u[3] = { 0, 0, dz }, v[3] = { dx, 0, 0 }; /* z x x = +y */
    scn_gen_quad(in->b, o, u, v, scn_gen_cells(dz, CELL), scn_gen_cells(dx, CELL), in->floor);
    o[1] = H;
    scn_gen_quad(in->b, o, v, u, scn_gen_cells(dx, CELL), scn_gen_cells(dz, CELL), in->ceiling);
}

/* The corridor wall on side s (+1: z in [1.5, 1.7]), with four doorways. */
static void _corridor_wall(interior* in, float s)
{
    float z0 = s > 0 ? 1.5f : -1.5f - WALL, z1 = z0 + WALL;
    unsigned sides = SCN_FACE_ALL & ~(SCN_FACE_NEG_Y | SCN_FACE_POS_Y); /* floor and ceiling close them */
    float x = -24.0f;
    for (int r = 0; r < 4; r++) {
        _box(in, x, 0, z0, room_x[r] - DOOR_HALF, H, z1, sides, in->wall);
        _box(in, room_x[r] - DOOR_HALF, DOOR_H, z0, room_x[r] + DOOR_HALF, H, z1, SCN_FACE_ALL & ~SCN_FACE_POS_Y,
             in->wall); /* lintel */
        x = room_x[r] + DOOR_HALF;
    }
    _box(in, x, 0, z0, 24.0f, H, z1, sides, in->wall);
}

static void _room(interior* in, float cx, float s)
{
    unsigned sides = SCN_FACE_ALL & ~(SCN_FACE_NEG_Y | SCN_FACE_POS_Y);
    float zn = s * 1.7f, zf = s * 10.5f; /* near (corridor) and far interior faces */
    float z0 = s > 0 ? zn : zf, z1 = s > 0 ? zf : zn;
    _floor_ceiling(in, cx - 4.0f, cx + 4.0f, z0, z1);
    float t0 = s > 0 ? 1.5f : -1.7f; /* doorway threshold through the corridor wall */
    float to[3] = { cx - DOOR_HALF, 0, t0 }, tu[3] = { 0, 0, WALL }, tv[3] = { 2 * DOOR_HALF, 0, 0 };
    scn_gen_quad(in->b, to, tu, tv, 1, 2, in->floor);
    float far0 = s > 0 ? 10.5f : -10.5f - WALL;
    _box(in, cx - 4.0f - WALL, 0, far0, cx + 4.0f + WALL, H, far0 + WALL, sides, in->wall);
    _box(in, cx - 4.0f - WALL, 0, z0, cx - 4.0f, H, z1, sides, in->wall);
    _box(in, cx + 4.0f, 0, z0, cx + 4.0f + WALL, H, z1, sides, in->wall);
    /* columns, off the doorway-to-centre line */
    float c1 = s * 4.5f, c2 = s * 8.5f;
    _box(in, cx + 2.0f, 0, c1 - 0.2f, cx + 2.4f, H, c1 + 0.2f, sides, in->column);
    _box(in, cx - 2.7f, 0, c2 - 0.2f, cx - 2.3f, H, c2 + 0.2f, sides, in->column);
    /* zero-thickness partition facing the room centre (+x) */
    float pz0 = s > 0 ? 7.0f : -10.0f;
    float o[3] = { cx - 3.2f, 0, pz0 }, u[3] = { 0, 0, 3.0f }, v[3] = { 0, 2.0f, 0 }; /* z x y = -x */
    scn_gen_quad(in->b, o, v, u, 2, 3, in->partition);
    uint32_t pieces = 1 + tv_rng_u32(&in->rng) % 3;
    for (uint32_t k = 0; k < pieces; k++) {
        float side = (tv_rng_u32(&in->rng) & 1) ? 1.0f : -1.0f;
        float w = scn_rng_range(&in->rng, 0.6f, 1.4f), d = scn_rng_range(&in->rng, 0.5f, 1.2f);
        float h = scn_rng_range(&in->rng, 0.5f, 1.9f);
        float x_near = cx + side * scn_rng_range(&in->rng, 1.0f, 3.8f - w);
        float zc = s * scn_rng_range(&in->rng, 2.5f, 9.5f);
        float xa = side > 0 ? x_near : x_near - w, za = zc - d / 2;
        _box(in, xa, 0, za, xa + w, h, za + d, SCN_FACE_NO_BOTTOM, in->furniture);
    }
}

void scn_gen_interior(scn_builder* b, uint64_t seed, uint32_t movers)
{
    interior in = { .b = b };
    tv_rng_seed(&in.rng, seed, 0x1A7);
    scn_gen_add_textures(b);
    float tint = scn_rng_range(&in.rng, 0.85f, 1.0f);
    in.floor = scn_gen_material(b, "floor", SCN_GEN_TEX_WOOD, 1.0f, 1.0f, 1.0f, false);
    in.wall = scn_gen_material(b, "wall", SCN_GEN_TEX_BRICKS, tint, 0.95f, 0.9f, false);
    in.ceiling = scn_gen_material(b, "ceiling", SCN_GEN_TEX_TILES, 0.95f, 0.95f, 0.95f, false);
    in.column = scn_gen_material(b, "column", SCN_GEN_TEX_CONCRETE, 0.9f, 0.88f, 0.85f, false);
    in.furniture = scn_gen_material(b, "furniture", SCN_GEN_TEX_WOOD, 0.8f, tint, 0.7f, false);
    in.partition = scn_gen_material(b, "partition", SCN_GEN_TEX_TILES, 0.6f, 0.7f, 0.9f, true);
    _floor_ceiling(&in, -24.0f, 24.0f, -1.5f, 1.5f);
    _corridor_wall(&in, 1.0f);
    _corridor_wall(&in, -1.0f);
    _box(&in, -24.0f - WALL, 0, -1.5f - WALL, -24.0f, H, 1.5f + WALL, SCN_FACE_ALL & ~(SCN_FACE_NEG_Y | SCN_FACE_POS_Y), in.wall);
    _box(&in, 24.0f, 0, -1.5f - WALL, 24.0f + WALL, H, 1.5f + WALL, SCN_FACE_ALL & ~(SCN_FACE_NEG_Y | SCN_FACE_POS_Y), in.wall);
    for (int r = 0; r < 4; r++) {
        _room(&in, room_x[r], 1.0f);
        _room(&in, room_x[r], -1.0f);
    }
    scn_gen_interior_movers(b, seed, movers);
}
