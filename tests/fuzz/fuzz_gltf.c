/* fuzz_gltf.c - libFuzzer target for the glTF loader (scene/gltf_loader.cpp):
 * .glb when the input starts with the binary magic, .gltf otherwise. Any
 * crash, sanitizer report, or failure that leaves a partial scene or a
 * multi-line message is a finding. */
#include "fuzz_common.h"
#include "gltf_loader.h"

#include <assert.h>

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    bool glb = size >= 4 && memcmp(data, "glTF", 4) == 0;
    const char* file = fuzz_write_input(data, size, glb ? "glb" : "gltf");
    if (!file)
        return 0;
    scn_scene scene;
    char err[512];
    if (scn_load_gltf(file, &scene, err, sizeof err)) {
        assert(scene.triangle_count > 0);
        scn_scene_free(&scene);
    } else {
        assert(scene.triangle_count == 0 && scene.positions == NULL && strchr(err, '\n') == NULL);
    }
    remove(file);
    return 0;
}
