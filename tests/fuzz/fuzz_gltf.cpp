// libFuzzer target: the glTF loader on arbitrary bytes, as .gltf text or .glb binary (by the first
// byte), from a file in a private folder (the loader reads paths: buffer URIs resolve beside it).
// Any ssao::Error is a correct answer; a crash, a sanitizer report, a hang or an escape is not.
#include "scene/load/gltf_loader.h"
#include "util/error.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string dir = [] {
        const std::string d = std::filesystem::temp_directory_path().string() + "/ssaolab_fuzz_gltf_" +
                              std::to_string(::getpid());
        std::filesystem::create_directories(d);
        return d;
    }();
    const bool glb = size >= 4 && data[0] == 'g' && data[1] == 'l' && data[2] == 'T' && data[3] == 'F';
    const std::string path = dir + (glb ? "/scene.glb" : "/scene.gltf");
    if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
        if (size) std::fwrite(data, 1, size, f);
        std::fclose(f);
    }
    try {
        ssao::loadGltf(path);
    } catch (const ssao::Error&) {
    }
    return 0;
}
