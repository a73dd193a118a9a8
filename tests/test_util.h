// Small helpers shared by every test binary: files under the build's test tmp folder.
#pragma once
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace ssaotest {

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

} // namespace ssaotest
