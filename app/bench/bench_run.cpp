#include "bench/bench_run.h"
#include "gl/readback.h"

#include "metrics/evaluate.h"
#include "output/image.h"
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

ViewResult measure(Renderer& r, const Settings& s, const ReferenceImage& ref, int warmup, int frames) {
    r.setSettings(s);
    r.render();
    ViewResult v;
    v.error = evaluate(readBack(r.texture("ao.denoised"), 1), ref).metrics;
    v.rmseFirstFrame = v.error.rmse;
    if (r.accumulating()) { // temporal: judge the image after its frames are blended
        do {
            r.render();
            ++v.frames;
        } while (r.accumulating());
        v.error = evaluate(readBack(r.texture("ao.denoised"), 1), ref).metrics;
    }
    std::vector<double> ms;
    for (int f = 0; f < warmup + frames && frames > 0; ++f) {
        r.invalidate();
        const FrameReport fr = r.render();
        double sum = 0;
        for (const auto& p : fr.passes)
            if (p.name != "gbuffer" && p.name != "composite" && p.gpuMs >= 0) sum += p.gpuMs;
        if (f >= warmup) ms.push_back(sum);
    }
    if (!ms.empty()) {
        v.gpuMs = median(ms);
        v.gpuMsMin = *std::min_element(ms.begin(), ms.end());
        v.gpuMsMax = *std::max_element(ms.begin(), ms.end());
    }
    return v;
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
