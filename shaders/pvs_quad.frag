#version 460
// P2, trim-region and umbra quads into their k-buffers (depth + region id):
// each fragment of the one quad (pvs_quad.vert) pushes one trim entry per
// trim depth and the umbra entry.
#extension GL_GOOGLE_include_directive : require
#include "pvs_kbuffer.glsl"

layout(location = 0) flat in uint v_region;
layout(location = 1) in vec3 v_w_over; // pvs_quad.vert

layout(location = 0) out uint o_unused; // colour writes are masked off

// Within the raster's depth range only, as when each trim depth had its own
// draw, clipped by the near and far planes.
void push_trim(uint p, float depth)
{
    if (depth >= view.near_dist && depth <= view.far_dist * TV_PVS_RASTER_FAR_SCALE)
        pvs_push(p, TV_PVS_KIND_TRIM, depth, v_region);
}

void main()
{
    o_unused = 0u;
    uint p = pvs_pixel();
    if (pvs_sealed(p))
        return;
    float depth = pvs_depth();
    push_trim(p, depth);              // the midpoint
    push_trim(p, depth / v_w_over.x); // the nearer plane
    push_trim(p, depth / v_w_over.y); // the farther plane
    pvs_push(p, TV_PVS_KIND_UMBRA, depth / v_w_over.z, v_region);
}
