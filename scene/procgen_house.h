/* procgen_house.h - the builtin:house generator's shared state (internal to
 * scene/procgen_house*.c). Layout: procedural.h and docs/scenes.md. */
#ifndef TRIMVR_SCENE_PROCGEN_HOUSE_H
#define TRIMVR_SCENE_PROCGEN_HOUSE_H

#include "procgen.h"

typedef struct house {
    scn_builder* b;
    tv_rng rng;
    uint32_t wall, slab, frame, door, stair, wood, fabric, metal, book, tile;
} house;

/* The box [x0,x1] x [y0,y1] x [z0,z1], all faces, one cell per face. */
void house_part(house* h, float x0, float y0, float z0, float x1, float y1, float z1, uint32_t m);

/* The box with span [s0,s1] along axis `along` (0: x, 2: z), [t0,t1] across
 * (the other horizontal axis) and [y0,y1] up, in cells of at most `cell`. */
void house_span(house* h, int along, float s0, float s1, float t0, float t1, float y0, float y1, float cell,
                uint32_t m);

/* Furniture of every room of both storeys (procgen_house_furniture.c). */
void house_furnish(house* h);

#endif
