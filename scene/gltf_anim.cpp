// gltf_anim.cpp - glTF animations into movers (scene/mover.h): node
// translation, rotation and scale channels with LINEAR and STEP
// interpolation; CUBICSPLINE keys play LINEAR through their values (a
// warning says so). Every animation of the file plays at once, looping.
#include "gltf_internal.hpp"

#include "log.h"

#include <cmath>
#include <cstdlib>
#include <cstring>

namespace tv_gltf {

void warn_once(Loader& L, bool& flag, const char* what)
{
    if (!flag)
        tv_log(TV_LOG_WARN, "%s: %s", L.path, what);
    flag = true;
}

bool is_animated(const Loader& L, int index)
{
    if (index < 0 || (size_t)index >= L.anim.size())
        return false;
    for (int k = 0; k < SCN_TRACK_COUNT; k++)
        if (!L.anim[index].times[k].empty())
            return true;
    return false;
}

static bool read_channel(Loader& L, const tinygltf::Animation& a, const tinygltf::AnimationChannel& ch)
{
    int which = ch.target_path == "translation" ? SCN_TRACK_TRANSLATION
                : ch.target_path == "rotation"  ? SCN_TRACK_ROTATION
                : ch.target_path == "scale"     ? SCN_TRACK_SCALE
                                                : -1;
    if (which < 0) { // "weights": morph targets
        warn_once(L, L.warned_morph, "morph target animations are not supported: meshes keep their base shape");
        return true;
    }
    if (ch.target_node < 0 || (size_t)ch.target_node >= L.model.nodes.size() || ch.sampler < 0 ||
        (size_t)ch.sampler >= a.samplers.size()) {
        L.problem = "an animation channel names a missing node or sampler";
        return false;
    }
    const tinygltf::AnimationSampler& s = a.samplers[ch.sampler];
    int width = which == SCN_TRACK_ROTATION ? 4 : 3;
    std::vector<float> times, values;
    if (!read_floats(L, s.input, 1, times) || !read_floats(L, s.output, width, values))
        return false;
    bool cubic = s.interpolation == "CUBICSPLINE";
    size_t per_key = cubic ? 3 : 1; // in-tangent, value, out-tangent
    if (times.empty() || values.size() != times.size() * width * per_key) {
        L.problem = "animation sampler " + std::to_string(ch.sampler) + " has " + std::to_string(times.size()) +
                    " key times but " + std::to_string(values.size() / width) + " values";
        return false;
    }
    if (cubic) {
        warn_once(L, L.warned_cubic, "CUBICSPLINE animation keys play LINEAR between their values");
        std::vector<float> middle(times.size() * width);
        for (size_t i = 0; i < times.size(); i++)
            std::memcpy(&middle[i * width], &values[(3 * i + 1) * width], width * sizeof(float));
        values.swap(middle);
    }
    NodeAnim& n = L.anim[ch.target_node];
    n.times[which] = times;
    n.values[which] = values;
    n.interp[which] = s.interpolation == "STEP" ? SCN_INTERP_STEP : SCN_INTERP_LINEAR;
    return true;
}

bool read_animations(Loader& L)
{
    L.anim.assign(L.model.nodes.size(), NodeAnim());
    for (const tinygltf::Animation& a : L.model.animations)
        for (const tinygltf::AnimationChannel& ch : a.channels)
            if (!read_channel(L, a, ch))
                return false;
    return true;
}

static float* copy_floats(const std::vector<float>& v)
{
    float* out = (float*)std::malloc((v.empty() ? 1 : v.size()) * sizeof(float));
    if (out)
        std::memcpy(out, v.data(), v.size() * sizeof(float));
    return out;
}

bool append_movers(Loader& L, char* err, size_t err_size)
{
    for (size_t i = 0; i < L.anim.size(); i++) {
        NodeAnim& n = L.anim[i];
        if (n.meshes.empty())
            continue;
        scn_builder_mover_begin(&L.builder);
        for (const DeferredMesh& d : n.meshes)
            if (!append_primitive(L, *d.prim, d.local.data(), err, err_size))
                return false;
        const tinygltf::Node& node = L.model.nodes[i];
        std::string name = node.name.empty() ? "node " + std::to_string(i) : node.name;
        scn_mover* m = scn_builder_mover_end(&L.builder, name.c_str());
        if (!m)
            continue; // the builder failed: scn_builder_finish reports it
        std::memcpy(m->parent, n.parent, sizeof m->parent);
        for (int k = 0; k < 3; k++) {
            if (node.translation.size() == 3)
                m->base_t[k] = (float)node.translation[k];
            if (node.scale.size() == 3)
                m->base_s[k] = (float)node.scale[k];
        }
        for (int k = 0; node.rotation.size() == 4 && k < 4; k++)
            m->base_r[k] = (float)node.rotation[k];
        for (int k = 0; k < SCN_TRACK_COUNT; k++) {
            if (n.times[k].empty())
                continue;
            scn_track* tr = &m->track[k];
            tr->times = copy_floats(n.times[k]);
            tr->values = copy_floats(n.values[k]);
            if (!tr->times || !tr->values) {
                L.problem = "out of memory for animation keys";
                return false;
            }
            tr->count = (uint32_t)n.times[k].size();
            tr->interp = n.interp[k];
        }
    }
    return true;
}

} // namespace tv_gltf
