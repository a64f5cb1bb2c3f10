/* fuzz_gltf.c - libFuzzer target for the glTF loader (-DTRIMVR_FUZZ=ON, clang).
 *
 * tinygltf reads files, so each input goes through a per-process temp file:
 * .glb when it starts with the binary magic, .gltf otherwise. Any crash,
 * sanitizer report or partial scene left behind on failure is a finding.
 */
#define _DEFAULT_SOURCE /* getpid */
#include "gltf_loader.h"
#include "log.h"

#include <assert.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static void _scn_fuzz_quiet(tv_log_level level, const char* message, void* user)
{
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    static char path[64];
    if (!path[0]) {
        tv_log_set_sink(_scn_fuzz_quiet, NULL);
        snprintf(path, sizeof path, "/tmp/scn_fuzz_%d", (int)getpid());
    }
    char file[80];
    bool glb = size >= 4 && memcmp(data, "glTF", 4) == 0;
    snprintf(file, sizeof file, "%s%s", path, glb ? ".glb" : ".gltf");
    FILE* f = fopen(file, "wb");
    if (!f)
        return 0;
    fwrite(data, 1, size, f);
    fclose(f);
    scn_scene scene;
    char err[512];
    if (scn_load_gltf(file, &scene, err, sizeof err))
        scn_scene_free(&scene);
    else
        assert(scene.triangle_count == 0 && scene.positions == NULL && strchr(err, '\n') == NULL);
    remove(file);
    return 0;
}
