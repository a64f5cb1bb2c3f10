// mesh_push.glsl - push constants of the mesh pass (rnd_mesh_push in
// render/render_vk.h mirrors this layout).
layout(push_constant) uniform tv_mesh_push {
    mat4 view_proj;
    uint use_draw_ids;
    uint skip_blend;
} pc;
