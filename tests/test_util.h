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

// Standard base64 (RFC 4648), for data URIs in generated glTF files.
inline std::string base64(const std::vector<unsigned char>& in) {
    static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < in.size(); i += 3) {
        unsigned v = in[i] << 16 | (i + 1 < in.size() ? in[i + 1] << 8 : 0) | (i + 2 < in.size() ? in[i + 2] : 0);
        out += t[(v >> 18) & 63];
        out += t[(v >> 12) & 63];
        out += i + 1 < in.size() ? t[(v >> 6) & 63] : '=';
        out += i + 2 < in.size() ? t[v & 63] : '=';
    }
    return out;
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
