// gltf_loader.cpp - tinygltf adapter: reads accessors, walks nodes, hands
// float arrays to scene_build.c, which does the geometry work in C.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include "gltf_internal.hpp" // includes tiny_gltf.h: first here, with the implementation

#include "gltf_loader.h"
#include "image_io.h"
#include "log.h"
#include "scene_build.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace tv_gltf {

bool image_callback(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
                    const unsigned char* bytes, int size, void* user)
{
    const char* path = (const char*)user;
    std::string name = image->uri.empty() ? "image " + std::to_string(index) : image->uri;
    uint8_t* rgba = nullptr;
    uint32_t w = 0, h = 0;
    char msg[512];
    if (!scn_image_read_memory(bytes, (size_t)size, name.c_str(), &rgba, &w, &h, msg, sizeof msg)) {
        *err += std::string(path) + ": " + msg;
        return false;
    }
    image->width = (int)w;
    image->height = (int)h;
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image.assign(rgba, rgba + (size_t)w * h * 4);
    scn_image_free(rgba);
    return true;
}

// Start of accessor data after checking that every element lies inside its
// buffer view and buffer; nullptr (problem set) otherwise.
const unsigned char* accessor_data(Loader& L, int index, size_t* stride, size_t* elem_size)
{
    const tinygltf::Model& m = L.model;
    if (index < 0 || (size_t)index >= m.accessors.size()) {
        L.problem = "accessor " + std::to_string(index) + " does not exist";
        return nullptr;
    }
    const tinygltf::Accessor& a = m.accessors[index];
    std::string what = "accessor " + std::to_string(index);
    if (a.sparse.isSparse) {
        L.problem = what + " is sparse (unsupported)";
        return nullptr;
    }
    int csize = tinygltf::GetComponentSizeInBytes((uint32_t)a.componentType);
    int ncomp = tinygltf::GetNumComponentsInType((uint32_t)a.type);
    if (csize <= 0 || ncomp <= 0 || a.bufferView < 0 || (size_t)a.bufferView >= m.bufferViews.size()) {
        L.problem = what + " has an invalid type or buffer view";
        return nullptr;
    }
    const tinygltf::BufferView& v = m.bufferViews[a.bufferView];
    *elem_size = (size_t)csize * ncomp;
    *stride = v.byteStride ? v.byteStride : *elem_size;
    if (v.buffer < 0 || (size_t)v.buffer >= m.buffers.size()) {
        L.problem = what + " uses a buffer view without a buffer";
        return nullptr;
    }
    // Offsets and counts come from the file: a sum near 2^64 must not wrap
    // into a small "in bounds" value.
    size_t buffer_size = m.buffers[v.buffer].data.size(), view_end = 0, need = 0;
    bool wrapped = __builtin_add_overflow(v.byteOffset, v.byteLength, &view_end);
    if (a.count) {
        wrapped |= __builtin_mul_overflow(*stride, a.count - 1, &need);
        wrapped |= __builtin_add_overflow(need, a.byteOffset, &need);
        wrapped |= __builtin_add_overflow(need, *elem_size, &need);
    }
    if (wrapped || view_end > buffer_size || need > v.byteLength) {
        L.problem = what + " (" + std::to_string(a.count) + " elements at offset " + std::to_string(a.byteOffset) +
                    " of buffer view " + std::to_string(a.bufferView) + ", offset " + std::to_string(v.byteOffset) +
                    ", length " + std::to_string(v.byteLength) + ") reads past the end of buffer " +
                    std::to_string(v.buffer) + " (" + std::to_string(buffer_size) + " bytes)";
        return nullptr;
    }
    return m.buffers[v.buffer].data.data() + v.byteOffset + a.byteOffset;
}

float component(const unsigned char* p, int type, bool normalized)
{
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: { int8_t x; std::memcpy(&x, p, 1); return normalized ? std::max(x / 127.0f, -1.0f) : x; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? *p / 255.0f : *p;
    case TINYGLTF_COMPONENT_TYPE_SHORT: { int16_t x; std::memcpy(&x, p, 2); return normalized ? std::max(x / 32767.0f, -1.0f) : x; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t x; std::memcpy(&x, p, 2); return normalized ? x / 65535.0f : x; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { uint32_t x; std::memcpy(&x, p, 4); return (float)x; }
    default: { float x; std::memcpy(&x, p, 4); return x; }
    }
}

bool read_floats(Loader& L, int index, int want_components, std::vector<float>& out)
{
    size_t stride, elem;
    const unsigned char* p = accessor_data(L, index, &stride, &elem);
    if (!p)
        return false;
    const tinygltf::Accessor& a = L.model.accessors[index];
    if (tinygltf::GetNumComponentsInType((uint32_t)a.type) != want_components) {
        L.problem = "accessor " + std::to_string(index) + " has " +
                    std::to_string(tinygltf::GetNumComponentsInType((uint32_t)a.type)) + " components, expected " +
                    std::to_string(want_components);
        return false;
    }
    size_t csize = elem / want_components;
    out.resize(a.count * want_components);
    for (size_t i = 0; i < a.count; i++)
        for (int c = 0; c < want_components; c++)
            out[i * want_components + c] = component(p + i * stride + c * csize, a.componentType, a.normalized);
    return true;
}

bool read_indices(Loader& L, const tinygltf::Primitive& prim, size_t vertex_count, std::vector<uint32_t>& out)
{
    if (prim.indices < 0) {
        out.resize(vertex_count);
        for (size_t i = 0; i < vertex_count; i++)
            out[i] = (uint32_t)i;
        return true;
    }
    size_t stride, elem;
    const unsigned char* p = accessor_data(L, prim.indices, &stride, &elem);
    if (!p)
        return false;
    const tinygltf::Accessor& a = L.model.accessors[prim.indices];
    // glTF 2.0 (3.7.2.1): indices are unsigned-integer scalars; a float NaN cast to uint32_t is undefined
    if (a.type != TINYGLTF_TYPE_SCALAR || (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                           a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                           a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)) {
        L.problem = "index accessor " + std::to_string(prim.indices) + " is not of unsigned-integer scalars (type " +
                    std::to_string(a.type) + ", component type " + std::to_string(a.componentType) + ")";
        return false;
    }
    out.resize(a.count);
    for (size_t i = 0; i < a.count; i++) {
        const unsigned char* e = p + i * stride;
        // component() is exact for u8/u16; u32 indices may exceed a float's 24-bit mantissa.
        uint32_t v = 0;
        if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            std::memcpy(&v, e, 4);
        else
            v = (uint32_t)component(e, a.componentType, false);
        if (v >= vertex_count) {
            L.problem = "index " + std::to_string(v) + " out of range (accessor " + std::to_string(prim.indices) +
                        ", " + std::to_string(vertex_count) + " vertices)";
            return false;
        }
        out[i] = v;
    }
    return true;
}

// Turns strip/fan index lists into a triangle list (same winding rules as GL).
void to_triangle_list(int mode, std::vector<uint32_t>& idx)
{
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        idx.resize(idx.size() / 3 * 3);
        return;
    }
    std::vector<uint32_t> list;
    for (size_t i = 2; i < idx.size(); i++) {
        bool odd = (i & 1) == 1;
        if (mode == TINYGLTF_MODE_TRIANGLE_FAN)
            list.insert(list.end(), { idx[0], idx[i - 1], idx[i] });
        else if (odd)
            list.insert(list.end(), { idx[i - 1], idx[i - 2], idx[i] });
        else
            list.insert(list.end(), { idx[i - 2], idx[i - 1], idx[i] });
    }
    idx.swap(list);
}

int texture_for(Loader& L, const tinygltf::Material& mat)
{
    int tex = mat.pbrMetallicRoughness.baseColorTexture.index;
    if (tex == -1)
        return -1;
    if (tex < 0 || (size_t)tex >= L.model.textures.size()) {
        L.problem = "material '" + mat.name + "' references missing texture " + std::to_string(tex) + " (the file has " +
                    std::to_string(L.model.textures.size()) + ")";
        return -2;
    }
    int image = L.model.textures[tex].source;
    if (image < 0 || (size_t)image >= L.model.images.size()) {
        L.problem = "texture " + std::to_string(tex) + " of material '" + mat.name + "' references missing image " +
                    std::to_string(image) + " (the file has " + std::to_string(L.model.images.size()) + ")";
        return -2;
    }
    int src = L.model.textures[tex].source;
    if (L.image_map[src] >= 0)
        return L.image_map[src];
    const tinygltf::Image& img = L.model.images[src];
    if (img.image.empty()) {
        L.problem = "texture image '" + (img.uri.empty() ? img.name : img.uri) + "' of material '" + mat.name +
                    "' is missing or could not be read";
        return -2;
    }
    uint8_t* copy = (uint8_t*)malloc(img.image.size());
    if (!copy) {
        L.problem = "out of memory for texture images";
        return -2;
    }
    std::memcpy(copy, img.image.data(), img.image.size());
    L.image_map[src] = (int)scn_builder_texture(&L.builder, (uint32_t)img.width, (uint32_t)img.height, copy);
    return L.image_map[src];
}

// scn material index for glTF material `index` (-1: a white default), or -1 on failure.
int material_for(Loader& L, int index)
{
    if (index < -1 || (index >= 0 && (size_t)index >= L.model.materials.size())) {
        L.problem = "a primitive references missing material " + std::to_string(index) + " (the file has " +
                    std::to_string(L.model.materials.size()) + ")";
        return -1;
    }
    if (index < 0) {
        if (L.default_material < 0) {
            scn_material m = {};
            std::snprintf(m.name, sizeof m.name, "default");
            m.base_color[0] = m.base_color[1] = m.base_color[2] = m.base_color[3] = 1.0f;
            m.texture = -1;
            m.alpha_cutoff = 0.5f;
            L.default_material = (int)scn_builder_material(&L.builder, &m);
        }
        return L.default_material;
    }
    if (L.material_map[index] >= 0)
        return L.material_map[index];
    const tinygltf::Material& g = L.model.materials[index];
    scn_material m = {};
    std::snprintf(m.name, sizeof m.name, "%s", g.name.c_str());
    const std::vector<double>& f = g.pbrMetallicRoughness.baseColorFactor;
    for (int i = 0; i < 4; i++)
        m.base_color[i] = f.size() == 4 ? (float)f[i] : 1.0f;
    m.texture = texture_for(L, g);
    if (m.texture == -2)
        return -1;
    m.alpha_mode = g.alphaMode == "MASK" ? SCN_ALPHA_MASK : g.alphaMode == "BLEND" ? SCN_ALPHA_BLEND : SCN_ALPHA_OPAQUE;
    m.alpha_cutoff = (float)g.alphaCutoff;
    m.double_sided = g.doubleSided;
    tv_log(TV_LOG_DEBUG, "%s: material %d '%s'", L.path, index, m.name);
    L.material_map[index] = (int)scn_builder_material(&L.builder, &m);
    return L.material_map[index];
}

bool append_primitive(Loader& L, const tinygltf::Primitive& prim, const float world[16], char* err, size_t err_size)
{
    int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        tv_log(TV_LOG_DEBUG, "%s: skipping a primitive of mode %d (points/lines)", L.path, mode);
        L.skipped_mode = mode;
        return true;
    }
    auto pos_it = prim.attributes.find("POSITION");
    if (pos_it == prim.attributes.end()) {
        L.problem = "a primitive has no POSITION attribute";
        return false;
    }
    std::vector<float> pos, nrm, uv;
    if (!read_floats(L, pos_it->second, 3, pos))
        return false;
    size_t n = pos.size() / 3;
    auto nit = prim.attributes.find("NORMAL"), tit = prim.attributes.find("TEXCOORD_0");
    if (nit != prim.attributes.end() && !read_floats(L, nit->second, 3, nrm))
        return false;
    if (tit != prim.attributes.end() && !read_floats(L, tit->second, 2, uv))
        return false;
    if ((!nrm.empty() && nrm.size() != 3 * n) || (!uv.empty() && uv.size() != 2 * n)) {
        L.problem = "attribute counts of a primitive differ from its POSITION count";
        return false;
    }
    std::vector<uint32_t> idx;
    if (!read_indices(L, prim, n, idx))
        return false;
    to_triangle_list(mode, idx);
    int material = material_for(L, prim.material);
    if (material < 0)
        return false;
    scn_mesh_input in = {};
    in.positions = pos.data();
    in.normals = nrm.empty() ? nullptr : nrm.data();
    in.uvs = uv.empty() ? nullptr : uv.data();
    in.vertex_count = (uint32_t)n;
    in.indices = idx.data();
    in.triangle_count = (uint32_t)(idx.size() / 3);
    std::memcpy(in.world, world, sizeof in.world);
    in.material = (uint32_t)material;
    return scn_builder_append_mesh(&L.builder, &in, L.path, err, err_size);
}

bool visit_node(Loader& L, int index, const float parent[16], int depth, int moving, char* err, size_t err_size)
{
    if (index < 0 || (size_t)index >= L.model.nodes.size() || depth > 256) {
        L.problem = depth > 256 ? "node hierarchy is deeper than 256 (a cycle?)" : "node " + std::to_string(index) + " does not exist";
        return false;
    }
    const tinygltf::Node& node = L.model.nodes[index];
    float local[16], world[16];
    if (node.matrix.size() == 16) {
        for (int i = 0; i < 16; i++)
            local[i] = (float)node.matrix[i];
    } else {
        const double t0[3] = { 0, 0, 0 }, r0[4] = { 0, 0, 0, 1 }, s0[3] = { 1, 1, 1 };
        scn_mat4_trs(local, node.translation.size() == 3 ? node.translation.data() : t0,
                     node.rotation.size() == 4 ? node.rotation.data() : r0, node.scale.size() == 3 ? node.scale.data() : s0);
    }
    scn_mat4_mul(world, parent, local);
    // an animated node starts a mover: its subtree's meshes wait in its
    // local frame (identity here) until every static mesh is in
    if (moving < 0 && is_animated(L, index)) {
        moving = index;
        std::memcpy(L.anim[index].parent, parent, sizeof L.anim[index].parent);
        const float identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
        std::memcpy(world, identity, sizeof world);
    } else if (moving >= 0 && is_animated(L, index)) {
        warn_once(L, L.warned_nested, "a node animated inside an animated node moves with the outer one only");
    }
    if (node.skin >= 0)
        warn_once(L, L.warned_skin, "skins are not supported: skinned meshes stay in their bind pose");
    if (node.mesh >= 0) {
        if ((size_t)node.mesh >= L.model.meshes.size()) {
            L.problem = "node " + std::to_string(index) + " references missing mesh " + std::to_string(node.mesh);
            return false;
        }
        for (const tinygltf::Primitive& prim : L.model.meshes[node.mesh].primitives) {
            if (!prim.targets.empty())
                warn_once(L, L.warned_morph, "morph targets are not supported: meshes keep their base shape");
            if (moving >= 0)
                L.anim[moving].meshes.push_back({ &prim, std::vector<float>(world, world + 16) });
            else if (!append_primitive(L, prim, world, err, err_size))
                return false;
        }
    }
    for (int child : node.children)
        if (!visit_node(L, child, world, depth + 1, moving, err, err_size))
            return false;
    return true;
}

// Nodes of the file's "scene" (or the first scene, or every parentless node
// when the file has no scenes); false (problem set) if "scene" is missing.
bool root_nodes(Loader& L, std::vector<int>& roots)
{
    const tinygltf::Model& m = L.model;
    if (m.defaultScene >= 0 && (size_t)m.defaultScene >= m.scenes.size()) {
        L.problem = "\"scene\" is " + std::to_string(m.defaultScene) + " but the file has " +
                    std::to_string(m.scenes.size()) + " scenes";
        return false;
    }
    if (!m.scenes.empty()) {
        roots = m.scenes[m.defaultScene >= 0 ? m.defaultScene : 0].nodes;
        return true;
    }
    std::vector<bool> is_child(m.nodes.size(), false);
    for (const tinygltf::Node& n : m.nodes)
        for (int c : n.children)
            if (c >= 0 && (size_t)c < is_child.size())
                is_child[c] = true;
    for (size_t i = 0; i < m.nodes.size(); i++)
        if (!is_child[i])
            roots.push_back((int)i);
    return true;
}

// The JSON text of a .gltf, or the JSON chunk of a .glb; empty if unreadable
// (tinygltf then reports the problem).
std::string json_text(const char* path, bool binary)
{
    std::string text;
    FILE* f = std::fopen(path, "rb");
    if (!f)
        return text;
    unsigned char head[20];
    uint32_t len = 0;
    if (!binary) {
        char buf[65536];
        for (size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;)
            text.append(buf, n);
    } else if (std::fread(head, 1, sizeof head, f) == sizeof head && std::memcmp(head + 16, "JSON", 4) == 0) {
        std::memcpy(&len, head + 12, 4);
        // The chunk length is the file's claim: never allocate past its size.
        long here = std::ftell(f);
        std::fseek(f, 0, SEEK_END);
        long size = std::ftell(f);
        std::fseek(f, here, SEEK_SET);
        text.resize(std::min((size_t)len, (size_t)std::max(size - here, 0L)));
        text.resize(std::fread(&text[0], 1, len, f));
    }
    std::fclose(f);
    return text;
}

// What tinygltf lets through silently: a glTF 1.0 file (it then finds no
// meshes) and offsets or indices that are not non-negative integers (it
// then uses 0 or treats them as absent). Empty when the JSON is fine.
std::string check_json(const std::string& text)
{
    using nlohmann::json;
    json j = json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object())
        return "";
    auto asset = j.find("asset");
    if (asset != j.end() && asset->is_object()) {
        auto version = asset->find("version");
        if (version != asset->end() && version->is_string() && version->get<std::string>().rfind("2.", 0) != 0)
            return "is glTF " + version->get<std::string>() + "; trimvr reads glTF 2.0 only (convert the file)";
    }
    if (j.contains("scene") && !j["scene"].is_number_unsigned())
        return "\"scene\" is " + j["scene"].dump() + ", not a scene index";
    static const char* const checks[][2] = { { "bufferViews", "byteOffset" }, { "bufferViews", "byteStride" },
                                              { "accessors", "byteOffset" }, { "nodes", "mesh" } };
    for (const auto& c : checks) {
        auto arr = j.find(c[0]);
        if (arr == j.end() || !arr->is_array())
            continue;
        for (size_t i = 0; i < arr->size(); i++) {
            const json& e = (*arr)[i];
            if (e.is_object() && e.contains(c[1]) && !e[c[1]].is_number_unsigned())
                return std::string(c[0]) + "[" + std::to_string(i) + "]." + c[1] + " is " + e[c[1]].dump() +
                       ", not a non-negative integer";
        }
    }
    return "";
}

std::string one_line(std::string s)
{
    for (char& c : s)
        if (c == '\n' || c == '\r')
            c = ' ';
    while (!s.empty() && s.back() == ' ')
        s.pop_back();
    return s;
}

bool load(const char* path, scn_scene* out, char* err, size_t err_size)
{
    Loader L;
    L.path = path;
    scn_builder_init(&L.builder, out, false);
    err[0] = '\0';
    FILE* probe = std::fopen(path, "rb");
    if (!probe) {
        std::snprintf(err, err_size, "%s: file not found or unreadable", path);
        return false;
    }
    std::fclose(probe);
    tinygltf::TinyGLTF gltf;
    gltf.SetImageLoader(image_callback, (void*)path);
    std::string terr, twarn;
    size_t len = std::strlen(path);
    bool binary = len >= 4 && (path[len - 1] == 'b' || path[len - 1] == 'B');
    std::string problem = check_json(json_text(path, binary));
    if (!problem.empty()) {
        std::snprintf(err, err_size, "%s: %s", path, problem.c_str());
        return false;
    }
    bool ok = binary ? gltf.LoadBinaryFromFile(&L.model, &terr, &twarn, path)
                     : gltf.LoadASCIIFromFile(&L.model, &terr, &twarn, path);
    if (!twarn.empty())
        tv_log(TV_LOG_DEBUG, "%s: tinygltf: %s", path, one_line(twarn).c_str());
    if (!ok) {
        std::string msg = one_line(terr.empty() ? "cannot parse the file" : terr);
        // Image errors already carry the path; tinygltf's own do not.
        if (msg.compare(0, len, path) == 0)
            std::snprintf(err, err_size, "%s", msg.c_str());
        else
            std::snprintf(err, err_size, "%s: %s", path, msg.c_str());
        return false;
    }
    L.material_map.assign(L.model.materials.size(), -1);
    L.image_map.assign(L.model.images.size(), -1);
    const char* base = std::strrchr(path, '/');
    std::snprintf(out->name, sizeof out->name, "%s", base ? base + 1 : path);
    const float identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
    std::vector<int> roots;
    bool ok_nodes = root_nodes(L, roots);
    ok_nodes = ok_nodes && read_animations(L);
    for (size_t i = 0; ok_nodes && i < roots.size(); i++)
        ok_nodes = visit_node(L, roots[i], identity, 0, -1, err, err_size);
    ok_nodes = ok_nodes && append_movers(L, err, err_size);
    if (ok_nodes && out->triangle_count == 0) {
        L.problem = L.skipped_mode >= 0 ? "has only point/line primitives (mode " + std::to_string(L.skipped_mode) +
                                              "); trimvr renders triangles only"
                                        : "contains no triangles";
        ok_nodes = false;
    }
    if (!ok_nodes) {
        if (!L.problem.empty())
            std::snprintf(err, err_size, "%s: %s", path, L.problem.c_str());
        scn_builder_abort(&L.builder);
        return false;
    }
    return scn_builder_finish(&L.builder, path, err, err_size);
}

} // namespace tv_gltf

extern "C" bool scn_load_gltf(const char* path, scn_scene* out, char* err, size_t err_size)
{
    // No C++ exception may cross into C: bad_alloc inside tinygltf or the
    // vectors becomes an ordinary error.
    try {
        return tv_gltf::load(path, out, err, err_size);
    } catch (const std::exception& e) {
        scn_scene_free(out);
        std::snprintf(err, err_size, "%s: %s", path, tv_gltf::one_line(e.what()).c_str());
        return false;
    }
}
