#version 460
// P2, trim-region and umbra quads into their k-buffers (depth + region id).
#extension GL_GOOGLE_include_directive : require
#include "pvs_kbuffer.glsl"

layout(location = 0) flat in uint v_region;

layout(location = 0) out uint o_unused; // colour writes are masked off

void main()
{
    o_unused = 0u;
    uint p = pvs_pixel();
    // umbrae, drawn in the wide pass: nothing to store where P3 does not resolve
    if (!pvs_sealed(p) && (pc.kind == TV_PVS_KIND_TRIM || pvs_resolves(p)))
        pvs_push(p, pc.kind, pvs_depth(), v_region);
}
