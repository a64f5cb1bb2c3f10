/* procgen_movers.c - the moving objects of builtin:city and builtin:interior
 * (`movers=N`).
 *
 * Drawn from their own PCG32 stream, after every static triangle, so
 * movers=0 leaves the scenes bit-identical and movers=N leaves their static
 * part so. Every path keeps to space the layout contracts (procedural.h)
 * keep free: street clearances in the city, the doorway boxes and the
 * corridor in the interior. Paths go back and forth (first key = last key),
 * so a loop never jumps.
 */
#include "procgen.h"
#include "procedural.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* One track of `count` keys (times in s, `width` floats each) for mover m;
 * false (builder failed) when out of memory. */
static bool _track(scn_builder* b, scn_mover* m, int which, const float* times, const float* values, uint32_t count,
                   int width)
{
    scn_track* tr = &m->track[which];
    tr->times = malloc(count * sizeof *tr->times);
    tr->values = malloc((size_t)count * width * sizeof *tr->values);
    if (!tr->times || !tr->values) {
        b->failed = true;
        return false;
    }
    memcpy(tr->times, times, count * sizeof *tr->times);
    memcpy(tr->values, values, (size_t)count * width * sizeof *tr->values);
    tr->count = count;
    return true;
}

/* A box mover [lo, hi] (local frame: origin on the ground at its centre)
 * going from a to b in `travel` s, waiting `pause` (> 0) s at each end, and back. */
static void _shuttle(scn_builder* b, const char* name, const float lo[3], const float hi[3], const float a[3],
                     const float bp[3], float travel, float pause, uint32_t material)
{
    scn_builder_mover_begin(b);
    scn_gen_box(b, lo, hi, SCN_FACE_NO_BOTTOM, 0.0f, material);
    scn_mover* m = scn_builder_mover_end(b, name);
    if (!m)
        return;
    float t[6] = {0, pause, pause + travel, 2 * pause + travel, 2 * pause + 2 * travel, 3 * pause + 2 * travel};
    float v[18];
    for (int k = 0; k < 6; k++)
        memcpy(v + 3 * k, (k == 0 || k == 1 || k == 5) ? a : (k == 4 ? a : bp), 3 * sizeof(float));
    _track(b, m, SCN_TRACK_TRANSLATION, t, v, 6, 3);
}

void scn_gen_city_movers(scn_builder* b, uint64_t seed, int blocks, uint32_t count)
{
    if (!count)
        return;
    tv_rng rng;
    tv_rng_seed(&rng, seed, 0x30E5);
    uint32_t vehicle = scn_gen_material(b, "vehicle", SCN_GEN_TEX_CONCRETE, 0.8f, 0.15f, 0.1f, false);
    uint32_t person = scn_gen_material(b, "pedestrian", SCN_GEN_TEX_TILES, 0.2f, 0.3f, 0.8f, false);
    const float P = SCN_CITY_BLOCK_PITCH, extent = blocks * P;
    for (uint32_t i = 0; i < count; i++) {
        bool car = i % 3 != 2;
        /* every fourth mover uses the streets of paths/city-walk.csv (z = 0,
         * then x = 40), in front of its walker; the rest any street */
        bool near_walk = i % 4 == 0;
        bool along_x = near_walk ? (i / 4) % 2 == 0 : tv_rng_u32(&rng) % 2 == 0;
        float line = near_walk ? (along_x ? 0.0f : P) : P * (float)((int)(tv_rng_u32(&rng) % (2 * blocks + 1)) - blocks);
        float side = tv_rng_u32(&rng) % 2 ? 1.0f : -1.0f;
        float offset = side * (car ? scn_rng_range(&rng, 1.0f, 2.0f) : scn_rng_range(&rng, 3.0f, 3.5f));
        float len = car ? scn_rng_range(&rng, 40.0f, 2.0f * extent) : scn_rng_range(&rng, 15.0f, 40.0f);
        float start = near_walk ? scn_rng_range(&rng, 0.0f, 30.0f) : scn_rng_range(&rng, -extent, extent - len);
        float speed = car ? scn_rng_range(&rng, 4.0f, 12.0f) : scn_rng_range(&rng, 1.0f, 1.6f);
        float half[3] = {car ? 2.1f : 0.25f, 0, car ? 0.9f : 0.25f}, height = car ? 1.6f : 1.8f;
        if (!along_x) { /* vehicles face along their street */
            float swap = half[0];
            half[0] = half[2], half[2] = swap;
        }
        float lo[3] = {-half[0], 0.0f, -half[2]}, hi[3] = {half[0], height, half[2]};
        float a[3] = {along_x ? start : line + offset, 0.0f, along_x ? line + offset : start};
        float e[3] = {along_x ? start + len : a[0], 0.0f, along_x ? a[2] : start + len};
        char name[32];
        snprintf(name, sizeof name, "%s%u", car ? "vehicle" : "pedestrian", i);
        _shuttle(b, name, lo, hi, a, e, len / speed, scn_rng_range(&rng, 0.1f, 2.0f), car ? vehicle : person);
    }
}

void scn_gen_interior_movers(scn_builder* b, uint64_t seed, uint32_t count)
{
    if (!count)
        return;
    static const float room_x[4] = {-18.0f, -6.0f, 6.0f, 18.0f};
    tv_rng rng;
    tv_rng_seed(&rng, seed, 0x30E5);
    uint32_t door = scn_gen_material(b, "door", SCN_GEN_TEX_WOOD, 0.6f, 0.4f, 0.25f, false);
    uint32_t cart = scn_gen_material(b, "cart", SCN_GEN_TEX_CONCRETE, 0.2f, 0.6f, 0.3f, false);
    for (uint32_t i = 0; i < count; i++) {
        uint32_t room = (i / 3) % 8;
        float cx = room_x[room % 4], s = room < 4 ? 1.0f : -1.0f;
        char name[32];
        if (i % 3 == 0) { /* a door hinged at the doorway's -x jamb, swinging 90 degrees into its room */
            snprintf(name, sizeof name, "door%u", i);
            scn_builder_mover_begin(b);
            float lo[3] = {0.02f, 0.0f, -0.03f}, hi[3] = {1.18f, 2.1f, 0.03f};
            scn_gen_box(b, lo, hi, SCN_FACE_NO_BOTTOM, 0.0f, door);
            scn_mover* m = scn_builder_mover_end(b, name);
            if (!m)
                return;
            m->base_t[0] = cx - 0.6f, m->base_t[2] = s * 1.6f;
            float open = scn_rng_range(&rng, 1.0f, 2.5f), hold = scn_rng_range(&rng, 0.5f, 2.0f);
            float t[4] = {0.0f, open, open + hold, 2 * open + hold};
            float half = 0.78539816f * -s; /* half the swing: y-rotation quaternion (0, sin, 0, cos) */
            float q[16] = {0, 0, 0, 1, 0, sinf(half), 0, cosf(half), 0, sinf(half), 0, cosf(half), 0, 0, 0, 1};
            _track(b, m, SCN_TRACK_ROTATION, t, q, 4, 4);
        } else if (i % 3 == 1) { /* a cart along the corridor */
            snprintf(name, sizeof name, "cart%u", i);
            float lo[3] = {-0.4f, 0.0f, -0.3f}, hi[3] = {0.4f, 0.9f, 0.3f};
            float z = scn_rng_range(&rng, -0.9f, 0.9f);
            float a[3] = {scn_rng_range(&rng, -23.0f, -10.0f), 0.0f, z}, e[3] = {scn_rng_range(&rng, 10.0f, 23.0f), 0.0f, z};
            _shuttle(b, name, lo, hi, a, e, (e[0] - a[0]) / scn_rng_range(&rng, 0.8f, 2.0f),
                     scn_rng_range(&rng, 0.1f, 1.0f), cart);
        } else { /* an object crossing its room from the doorway towards the room centre */
            snprintf(name, sizeof name, "crosser%u", i);
            float lo[3] = {-0.3f, 0.0f, -0.3f}, hi[3] = {0.3f, 1.2f, 0.3f};
            float a[3] = {cx, 0.0f, s * 2.2f}, e[3] = {cx, 0.0f, s * 6.0f};
            _shuttle(b, name, lo, hi, a, e, 3.8f / scn_rng_range(&rng, 0.5f, 1.5f), scn_rng_range(&rng, 0.1f, 1.5f),
                     cart);
        }
    }
}
