#include "bench/bench_run.h"

#include "util/error.h"

#include <array>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <memory>
#include <thread>

namespace ssao {

Settings withRadius(Settings s, float radius) {
    s.ao.radiusMode = RadiusMode::World;
    s.ao.radius = radius;
    return s;
}

namespace {
std::string firstLine(const std::string& cmd) {
    std::array<char, 256> buf{};
    std::string out;
    std::unique_ptr<FILE, int (*)(FILE*)> p(popen(cmd.c_str(), "r"), pclose);
    if (p && std::fgets(buf.data(), int(buf.size()), p.get())) out = buf.data();
    while (!out.empty() && (out.back() == '\n' || out.back() == '\r'))
        out.pop_back();
    return out;
}

std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            return colon == std::string::npos ? line : line.substr(colon + 2);
        }
    return "unknown";
}
} // namespace

nlohmann::json runFacts(const std::string& glRenderer) {
    char date[32];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
    std::string rev = firstLine("git -C '" SSAOLAB_SOURCE_DIR "' rev-parse --short HEAD 2>/dev/null");
    if (!rev.empty() &&
        !firstLine("git -C '" SSAOLAB_SOURCE_DIR "' status --porcelain -uno 2>/dev/null").empty())
        rev += "+dirty";
    return {{"cpu", cpuModel()},
            {"hardware_threads", std::thread::hardware_concurrency()},
            {"gl_renderer", glRenderer},
            {"build_type", SSAOLAB_BUILD_TYPE},
            {"date", date},
            {"git_revision", rev.empty() ? "unknown" : rev}};
}

} // namespace ssao
