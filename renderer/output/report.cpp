#include "output/report.h"

#include "output/image.h"
#include "settings/params.h"
#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace ssao {

namespace {

struct Buffers {
    Image position, normal, albedo, depth, aoRaw, ao, composite;
};

Buffers readAll(const Renderer& r) {
    Buffers b;
    b.position = readBack(r.gbuffer().position(), 4);
    b.normal = readBack(r.gbuffer().normal(), 3);
    if (r.settings().gbuffer.normalFormat == TargetFormat::RGBA8) // stored (n+1)/2: write decoded n
        for (auto& v : b.normal.data)
            v = v * 2.0f - 1.0f;
    b.albedo = readBack(r.gbuffer().albedo(), 3);
    b.depth = readBack(r.gbuffer().linearDepth(), 1);
    b.aoRaw = readBack(r.ssao().aoRaw(), 1);
    b.ao = readBack(r.blur().ao(), 1);
    b.composite = readBack(r.composite().color(), 3);
    return b;
}

nlohmann::json statsJson(const Stats& s) {
    return {{"min", s.min}, {"mean", s.mean}, {"max", s.max}, {"pixels", s.count}};
}

nlohmann::json statistics(const Buffers& b) {
    Image mask = b.position.channel(3); // w = 1 on geometry, 0 on sky
    nlohmann::json j;
    j["nonfinite"] = {{"position", stats(b.position).nonFinite},
                      {"normal", stats(b.normal).nonFinite},
                      {"depth", stats(b.depth).nonFinite},
                      {"ao_raw", stats(b.aoRaw).nonFinite},
                      {"ao", stats(b.ao).nonFinite}};
    j["ao_raw"] = statsJson(stats(b.aoRaw, &mask));
    j["ao"] = statsJson(stats(b.ao, &mask));
    j["geometry_pixels"] = stats(mask, &mask).count;
    return j;
}

} // namespace

nlohmann::json frameStatistics(const Renderer& r) {
    return statistics(readAll(r));
}

nlohmann::json writeOutputs(const Renderer& r, const std::string& dir, const RunInfo& info,
                            const FrameReport& firstFrame, const nlohmann::json& timing) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw Error("cannot create output folder " + dir + ": " + ec.message());
    const Buffers b = readAll(r);
    auto path = [&](const char* f) { return (std::filesystem::path(dir) / f).string(); };

    Image pos3{b.position.width, b.position.height, 3, {}};
    for (size_t i = 0; i < size_t(pos3.width) * pos3.height; ++i)
        for (int c = 0; c < 3; ++c)
            pos3.data.push_back(b.position.data[i * 4 + c]);
    writeExr(pos3, path("position.exr"));
    writeExr(b.normal, path("normal.exr"));
    writeExr(b.depth, path("depth.exr"));
    writeExr(b.aoRaw, path("ao_raw.exr"));
    writeExr(b.ao, path("ao.exr"));

    // Previews: position and depth scaled by the scene's extent seen in this frame.
    float maxDepth = 0.0f;
    for (float v : b.depth.data)
        if (std::isfinite(v)) maxDepth = std::max(maxDepth, v);
    const float posScale = maxDepth > 0 ? 0.5f / maxDepth : 1.0f;
    writePng(pos3, path("position.png"), posScale, 0.5f);
    writePng(b.normal, path("normal.png"), 0.5f, 0.5f);
    writePng(b.depth, path("depth.png"), maxDepth > 0 ? 1.0f / maxDepth : 1.0f);
    writePng(b.albedo, path("albedo.png"));
    writePng(b.aoRaw, path("ao_raw.png"));
    writePng(b.ao, path("ao.png"));
    writePng(b.composite, path("composite.png"));

    const Camera& c = r.camera();
    nlohmann::json m;
    m["scene"] = {{"name", info.sceneName}, {"triangles", info.triangles}};
    m["camera"] = {{"eye", {c.eye.x, c.eye.y, c.eye.z}},
                   {"target", {c.target.x, c.target.y, c.target.z}},
                   {"up", {c.up.x, c.up.y, c.up.z}},
                   {"fov_y_deg", c.fovYDeg},
                   {"near", c.nearZ},
                   {"far", c.farZ},
                   {"source", info.cameraSource}};
    m["size"] = {r.width(), r.height()};
    m["gl_renderer"] = info.glRenderer;
    m["gl_platform"] = info.glPlatform;
    m["settings"] = toJson(r.settings());
    m["passes_run"] = firstFrame.ran();
    m["gpu_ms"] = timing;
    m.update(statistics(b));
    std::ofstream out(path("metrics.json"));
    if (!out) throw Error("cannot write " + path("metrics.json"));
    out << m.dump(2) << "\n";
    return m;
}

} // namespace ssao
