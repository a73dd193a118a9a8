// Small helpers shared by every test binary: files under the build's test tmp folder.
#pragma once
#include "util/error.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace ssaotest {

// The message of the ssao::Error `f` throws ("" when it throws none).
template <class F> std::string errorOf(F&& f) {
    try {
        f();
    } catch (const ssao::Error& e) {
        return e.what();
    }
    return "";
}

// Writes `text` to SSAOLAB_TEST_TMP/name (binary) and returns the path.
inline std::string writeTemp(const std::string& name, const std::string& text) {
    std::filesystem::create_directories(SSAOLAB_TEST_TMP);
    const std::string path = std::string(SSAOLAB_TEST_TMP) + "/" + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

inline std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Every .gltf of the third-party scenes beside the repository (../shared/scenes), sorted.
inline std::vector<std::filesystem::path> sharedSceneFiles() {
    std::vector<std::filesystem::path> out;
    for (auto& dir : std::filesystem::directory_iterator(SSAOLAB_SCENES_DIR)) {
        if (!dir.is_directory()) continue;
        for (auto& f : std::filesystem::directory_iterator(dir.path()))
            if (f.path().extension() == ".gltf") out.push_back(f.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace ssaotest
