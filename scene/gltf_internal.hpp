// gltf_internal.hpp - what gltf_loader.cpp (nodes, meshes, materials) and
// gltf_anim.cpp (animations into movers) share. Internal to scene/.
#ifndef TRIMVR_SCENE_GLTF_INTERNAL_HPP
#define TRIMVR_SCENE_GLTF_INTERNAL_HPP

#include <tiny_gltf.h>

#include "scene_build.h"

#include <string>
#include <vector>

namespace tv_gltf {

// A primitive under an animated node, with its matrix into that node's frame.
struct DeferredMesh {
    const tinygltf::Primitive* prim;
    std::vector<float> local; // 16, column-major
};

// Per node: its animation channels (empty when not animated) and, once the
// node walk has reached it, the frame it moves in and its subtree's meshes.
struct NodeAnim {
    std::vector<float> times[SCN_TRACK_COUNT], values[SCN_TRACK_COUNT];
    scn_interp interp[SCN_TRACK_COUNT] = {};
    float parent[16] = {};
    std::vector<DeferredMesh> meshes;
};

struct Loader {
    const char* path;
    tinygltf::Model model;
    scn_builder builder;
    std::vector<int> material_map; // glTF material -> scn material, -1 until used
    std::vector<int> image_map;    // glTF image -> scn texture, -1 until used
    int default_material = -1;
    int skipped_mode = -1;         // mode of a points/lines primitive left out, -1 if none
    std::string problem;           // set on failure (without the file name)
    std::vector<NodeAnim> anim;    // per node (read_animations)
    bool warned_skin = false, warned_morph = false, warned_nested = false, warned_cubic = false;
};

bool read_floats(Loader& L, int index, int want_components, std::vector<float>& out);
bool append_primitive(Loader& L, const tinygltf::Primitive& prim, const float world[16], char* err, size_t err_size);

// One warning line naming the file, the first time `flag` is seen unset.
void warn_once(Loader& L, bool& flag, const char* what);

// Reads every animation's channels into L.anim; false (problem set) on a
// bad sampler (times not increasing, counts that do not match).
bool read_animations(Loader& L);

// True when node `index` has an animation channel.
bool is_animated(const Loader& L, int index);

// Appends each animated node's meshes as one mover (after all static
// geometry) with its tracks.
bool append_movers(Loader& L, char* err, size_t err_size);

} // namespace tv_gltf

#endif
