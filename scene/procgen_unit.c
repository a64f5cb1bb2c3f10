/* procgen_unit.c - builtin:unit, objects whose visibility is known analytically.
 *
 * One table drives both the geometry and scn_unit_object(), so the id ranges
 * tests ask for cannot drift from what is emitted.
 */
#include "procedural.h"
#include "procgen.h"

#include <string.h>

typedef struct unit_object {
    const char* name;
    float lo[3], hi[3];
    unsigned faces;
} unit_object;

static const unit_object objects[] = {
    { "ground", { -10.0f, -1.0f, -15.0f }, { 10.0f, 0.0f, 5.0f }, SCN_FACE_POS_Y },
    { "wall", { -2.0f, 0.0f, -5.1f }, { 2.0f, 3.0f, -5.0f }, SCN_FACE_NO_BOTTOM },
    { "box_b", { -0.5f, 0.0f, -8.0f }, { 0.5f, 1.0f, -7.0f }, SCN_FACE_NO_BOTTOM },
    { "box_c", { 4.0f, 0.0f, -6.0f }, { 5.0f, 1.0f, -5.0f }, SCN_FACE_NO_BOTTOM },
};

static uint32_t _face_count(unsigned faces)
{
    uint32_t n = 0;
    for (; faces; faces &= faces - 1)
        n++;
    return n;
}

void scn_gen_unit(scn_builder* b)
{
    scn_gen_add_textures(b);
    static const struct { const char* name; scn_gen_texture tex; float rgb[3]; } looks[] = {
        { "ground", SCN_GEN_TEX_TILES, { 0.7f, 0.7f, 0.7f } },
        { "wall", SCN_GEN_TEX_BRICKS, { 1.0f, 1.0f, 1.0f } },
        { "box_b", SCN_GEN_TEX_WOOD, { 1.0f, 0.6f, 0.6f } },
        { "box_c", SCN_GEN_TEX_CONCRETE, { 0.6f, 0.7f, 1.0f } },
    };
    for (size_t i = 0; i < sizeof objects / sizeof objects[0]; i++) {
        uint32_t m = scn_gen_material(b, looks[i].name, looks[i].tex, looks[i].rgb[0], looks[i].rgb[1], looks[i].rgb[2], false);
        scn_gen_box(b, objects[i].lo, objects[i].hi, objects[i].faces, 0.0f, m);
    }
}

bool scn_unit_object(const char* name, uint32_t* first, uint32_t* count)
{
    uint32_t start = 0;
    for (size_t i = 0; i < sizeof objects / sizeof objects[0]; i++) {
        uint32_t n = 2 * _face_count(objects[i].faces); /* one cell per face */
        if (strcmp(name, objects[i].name) == 0) {
            *first = start;
            *count = n;
            return true;
        }
        start += n;
    }
    return false;
}
