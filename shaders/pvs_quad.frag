#version 460
// P2, trim-region and umbra quads into the pixel's region list: each
// fragment of the one quad (pvs_quad.vert) pushes its trim depths and its
// umbra's as one entry (the farther plane's in a second).
#extension GL_GOOGLE_include_directive : require
#include "pvs_kbuffer.glsl"

layout(location = 0) flat in uint v_region;
layout(location = 1) in vec3 v_w_over; // pvs_quad.vert

layout(location = 0) out uint o_unused; // colour writes are masked off

// Within the raster's depth range only (else 0, none), as when each trim
// depth had its own draw, clipped by the near and far planes.
float clipped(float depth)
{
    return depth >= view.near_dist && depth <= view.far_dist * TV_PVS_RASTER_FAR_SCALE ? depth : 0.0;
}

void main()
{
    o_unused = 0u;
    // The umbra's footprint for the spill span (pvs_umbra_pack): its nearest
    // depth over the square of two pixels' side around the centre. A margin,
    // not a bound: below 0.99 px of half side interior_walk loses a false
    // positive that covers the walk's centre-umbra loss (docs/pvs-edge-cases.md,
    // journal/2026-12-03-fp098.md); 1 / depth is affine in the image, so it is
    // exact; derivatives before any return (uniform flow).
    float inv_umbra = v_w_over.z * gl_FragCoord.w;
    float footprint = 1.0 / (inv_umbra + (abs(dFdx(inv_umbra)) + abs(dFdy(inv_umbra))));
    uint p = pvs_pixel();
    if (pvs_sealed(p))
        return;
    float depth = pvs_depth(), umbra = pvs_umbra_pack(depth / v_w_over.z, footprint);
    // the midpoint, the nearer plane and the umbra in one entry; the farther
    // plane (grazing fronts only) in a second, without umbra
    pvs_push_region(p, clipped(depth), clipped(depth / v_w_over.x), umbra, v_region);
    pvs_push_region(p, clipped(depth / v_w_over.y), 0.0, 0.0, v_region);
}
