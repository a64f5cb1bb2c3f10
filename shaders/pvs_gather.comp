#version 460
// P4: every id of the visibility buffer (the nearest front of each pixel
// from v*, trimmed pixels included: it is visible from v*, a point of the
// viewcell) and of the wide (dilated) visibility buffer joins the trimmed
// primitives already flagged by P2/P3. So does the front that ends what a
// trimmed pixel still carries after its last layer: P3 carries a run whose
// first front has no back yet to the next layer that reaches the pixel, and
// where none does the run never closes. Without a carried trim its first
// front outside the carried hidden range is then the pixel's terminator, as
// pvs_resolve_pixel's walk makes a front whose interval does not validate;
// candidates before it are output too, as the walk outputs them. With one,
// the run is validated and every front of it outside that range is output.
// (Until 2026-11-24 such runs were dropped: an open surface seen through a
// trimmed pixel, oasago2's far floors past a ledge.)
#extension GL_GOOGLE_include_directive : require
#include "pvs_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = TV_PVS_SET, binding = TV_PVS_BIND_VIS_IDS, r32ui) uniform readonly uimage2D vis_ids;
layout(set = TV_PVS_SET, binding = TV_PVS_BIND_VIS_WIDE, r32ui) uniform readonly uimage2D vis_wide;

void main()
{
    uvec2 xy = gl_GlobalInvocationID.xy;
    if (xy.x >= view.tile_w || xy.y >= view.tile_h)
        return;
    ivec2 image_xy = ivec2(xy + uvec2(view.tile_x, view.tile_y)); // the visibility buffers hold the whole image
    uint id = imageLoad(vis_ids, image_xy).x;
    if (id != TV_NO_TRIANGLE)
        pvs_mark(id, TV_REASON_VIS);
    id = imageLoad(vis_wide, image_xy).x;
    if (id != TV_NO_TRIANGLE)
        pvs_mark(id, TV_REASON_VIS_WIDE);
    uint p = xy.y * view.tile_w + xy.x;
    uvec4 st = pixstate[p];
    float hide_begin = uintBitsToFloat(st.z), hide_end = pvs_umbra_centre(uintBitsToFloat(st.w)); // packed while trimmed
    // A carried trim lies at or behind the run's first front (P3 carries
    // only those), so its region meets the interval the run forms with a
    // back at infinity: validated, every front of it is output, as the walk
    // outputs the fronts of a validated interval. An open-bottomed solid
    // seen near its eroded edge is such a run, and what the eyes see past
    // the edge lies behind its first front (a slot under a lifted wall).
    bool validated = false;
    for (uint c = 0u; st.x != TV_STENCIL_SEALED && c < st.y; c++)
        validated = validated || (carry_buf[p * TV_K_CARRY + c].y & TV_CARRY_KIND) == TV_ENTRY_TRIM;
    for (uint c = 0u; st.x != TV_STENCIL_SEALED && c < st.y; c++) {
        uvec4 e = carry_buf[p * TV_K_CARRY + c];
        float depth = uintBitsToFloat(e.x);
        if (e.y != TV_ENTRY_FRONT || (hide_begin < hide_end && depth >= hide_begin && depth < hide_end))
            continue;
        if (e.z != TV_ID_PRIOR)
            pvs_mark(e.z & ~TV_ID_CANDIDATE, TV_REASON_OPEN_RUN);
        if ((e.z & TV_ID_CANDIDATE) == 0u && !validated)
            break;
    }
}
