#include "measure/bench_run.h"

#include "util/error.h"
#include "util/files.h"
#include "util/process.h"

#include <ctime>
#include <sstream>
#include <thread>

namespace ssao {

Settings withRadius(Settings s, float radius) {
    s.ao.radiusMode = RadiusMode::World;
    s.ao.radius = radius;
    return s;
}

namespace {
// The first line git prints for `args` on the source tree ("" when git is absent or fails).
std::string gitLine(std::vector<std::string> args) {
    args.insert(args.begin(), {"git", "-C", SSAOLAB_SOURCE_DIR});
    const ProgramRun r = runProgram(args, ChildStream::Capture, ChildStream::Discard);
    if (!r.started || r.exitCode != 0) return "";
    return r.out.substr(0, r.out.find_first_of("\r\n"));
}

std::string cpuModel() {
    std::string text;
    try {
        text = readRegularFile("/proc/cpuinfo", "CPU description", size_t(4) << 20);
    } catch (const Error&) {
        return "unknown";
    }
    std::istringstream in(text);
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
    std::string rev = gitLine({"rev-parse", "--short", "HEAD"});
    if (!rev.empty() && !gitLine({"status", "--porcelain", "-uno"}).empty()) rev += "+dirty";
    return {{"cpu", cpuModel()},
            {"hardware_threads", std::thread::hardware_concurrency()},
            {"gl_renderer", glRenderer},
            {"build_type", SSAOLAB_BUILD_TYPE},
            {"date", date},
            {"git_revision", rev.empty() ? "unknown" : rev}};
}

} // namespace ssao
