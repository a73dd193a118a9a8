#include "util/paths.h"

#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;

namespace ssao {

namespace {
bool holdsData(const fs::path& p) {
    std::error_code ec;
    return fs::is_directory(p / "shaders", ec) && fs::is_directory(p / "assets", ec);
}

std::pair<std::string, std::string> locate() {
    if (const char* env = std::getenv("SSAOLAB_DATA_DIR"); env && *env) return {env, "SSAOLAB_DATA_DIR"};
    const std::string exe = executablePath();
    if (!exe.empty()) {
        const fs::path bin = fs::path(exe).parent_path();
        if (holdsData(bin / ".." / "share" / "ssaolab"))
            return {fs::weakly_canonical(bin / ".." / "share" / "ssaolab").string(), "installed"};
        if (holdsData(bin)) return {bin.string(), "beside the binary"};
    }
    return {SSAOLAB_SOURCE_DIR, "source tree"};
}
} // namespace

std::string executablePath() {
    std::error_code ec;
    const fs::path p = fs::read_symlink("/proc/self/exe", ec);
    return ec ? std::string() : p.string();
}

std::string dataRoot() {
    static const std::string root = locate().first;
    return root;
}

std::string dataRootSource() {
    static const std::string source = locate().second;
    return source;
}

} // namespace ssao
