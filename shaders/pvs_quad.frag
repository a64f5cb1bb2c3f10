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
    if (!pvs_sealed(p))
        pvs_push(p, pc.kind, pvs_depth(), v_region);
}
