#include "output/report.h"

#include "display/view_painter.h"
#include "output/image.h"
#include "output/skip_report.h"
#include "settings/params.h"
#include "settings/preset.h"
#include "util/atomic_file.h"
#include "util/error.h"

#include <filesystem>
#include <fstream>

namespace ssao {

namespace {

const char* formatName(GLenum f) {
    switch (f) {
    case GL_R32F:
        return "r32f";
    case GL_RGBA32F:
        return "rgba32f";
    case GL_RGBA16F:
        return "rgba16f";
    case GL_RGBA8:
        return "rgba8";
    case GL_DEPTH_COMPONENT32F:
        return "depth32f";
    default:
        return "other";
    }
}

// One buffer read back once: the raw texels (what the display mapping fits) and the values as
// they mean (decoded: normals as n, not (n+1)/2), which statistics and EXR files use.
struct Buffer {
    const Resource* res = nullptr;
    Image raw, values;
};

Buffer readBuffer(const Resource& r) {
    Buffer b{&r, readBack(r.texture, std::max(1, r.desc.channels)), {}};
    b.values = b.raw;
    if (r.desc.decodeScale != 1.0f || r.desc.decodeOffset != 0.0f)
        for (auto& v : b.values.data)
            v = v * r.desc.decodeScale + r.desc.decodeOffset;
    return b;
}

std::vector<Buffer> readBuffers(const Renderer& r) {
    std::vector<Buffer> out;
    for (const Resource* res : r.buffers())
        out.push_back(readBuffer(*res));
    return out;
}

const Buffer& find(const std::vector<Buffer>& all, const std::string& name) {
    for (const Buffer& b : all)
        if (b.res->desc.name == name) return b;
    throw Error("no buffer named '" + name + "' in the frame");
}

nlohmann::json statsJson(const Stats& s) {
    return {{"min", s.min}, {"mean", s.mean},  {"max", s.max},
            {"p05", s.p05}, {"median", s.p50}, {"pixels", s.count}};
}

nlohmann::json bufferJson(const Resource& r, const Image& img, const Image& mask) {
    const Stats s = stats(img, &mask);
    nlohmann::json j = {
        {"format", formatName(r.desc.format)}, {"size", {r.width(), r.height()}}, {"scale", r.desc.scale},
        {"channels", r.desc.channels},         {"nonfinite", s.nonFinite},        {"help", r.desc.help}};
    if (r.desc.channels == 1) j["geometry"] = statsJson(s);
    return j;
}

nlohmann::json statistics(const Renderer& r, const std::vector<Buffer>& all) {
    const Image& mask = find(all, "gbuffer.depth").values; // linear depth: > 0 on geometry
    nlohmann::json j;
    for (const Buffer& b : all)
        j["buffers"][b.res->desc.name] = bufferJson(*b.res, b.values, mask);
    j["ao"] = statsJson(stats(find(all, "ao.denoised").values, &mask));
    j["ao_raw"] = statsJson(stats(find(all, "ao.raw").values, &mask));
    j["geometry_pixels"] = stats(mask, &mask).count;
    const RadiusInfo ri = r.radiusAtCentre();
    const Param* mode = findParam("ao.radius_mode");
    j["radius"] = {{"mode", mode->format(mode->get(r.settings()))},
                   {"world_at_centre", ri.world},
                   {"pixels_at_centre", ri.pixels},
                   {"centre_depth", ri.depth},
                   {"scene_diagonal", ri.sceneDiagonal}};
    return j;
}

} // namespace

nlohmann::json frameStatistics(const Renderer& r) {
    return statistics(r, readBuffers(r));
}

nlohmann::json writeOutputs(Renderer& r, const std::string& dir, const RunInfo& info,
                            const FrameReport& firstFrame, const nlohmann::json& timing) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw Error("cannot create output folder " + dir + ": " + ec.message());
    auto path = [&](const std::string& f) { return (fs::path(dir) / f).string(); };

    const std::vector<Buffer> all = readBuffers(r); // each buffer read back once
    nlohmann::json m = statistics(r, all);
    const Resource& mask = r.resource("gbuffer.depth");
    ViewPainter painter;
    gl::RenderTarget view;
    for (const Buffer& b : all) {
        const Resource& res = *b.res;
        const std::string& name = res.desc.name;
        auto& entry = m["buffers"][name];
        if (res.desc.format != GL_RGBA8) { // float data keeps NaN/inf and full precision
            writeExr(b.values, path(name + ".exr"));
            entry["exr"] = name + ".exr";
        }
        const DisplayRange range =
            painter.paint(res, mask, info.style, view, r.shaders(), r.triangle(), &b.raw);
        const bool grey = (res.desc.display == Display::Unit || res.desc.display == Display::Scalar) &&
                          !info.style.falseColor;
        writePng(readBack(view.texture(), grey ? 1 : 3), path(name + ".png"));
        entry["png"] = name + ".png";
        entry["display_range"] =
            res.desc.channels == 1
                ? nlohmann::json{range.lo.x, range.hi.x}
                : nlohmann::json{{range.lo.x, range.lo.y, range.lo.z}, {range.hi.x, range.hi.y, range.hi.z}};
        entry["display_range_fitted"] = range.fitted;
    }

    const Camera& c = r.camera();
    m["scene"] = {
        {"name", info.sceneName}, {"triangles", info.triangles}, {"diagonal", 2.0f * r.sceneRadius()}};
    if (info.sceneOrigin != glm::dvec3(0.0))
        m["scene"]["origin"] = {info.sceneOrigin.x, info.sceneOrigin.y, info.sceneOrigin.z};
    Camera fileCamera = c; // in the file's coordinates, as --camera and presets take it
    fileCamera.eye = glm::vec3(info.sceneOrigin + glm::dvec3(c.eye));
    fileCamera.target = glm::vec3(info.sceneOrigin + glm::dvec3(c.target));
    m["camera"] = cameraToJson(fileCamera);
    m["camera"]["source"] = info.cameraSource;
    m["size"] = {r.width(), r.height()};
    m["gl_renderer"] = info.glRenderer;
    m["gl_platform"] = info.glPlatform;
    m["settings"] = toJson(r.settings());
    m["passes"] = r.graph().passOrder();
    m["passes_run"] = firstFrame.ran();
    m["skips"] = skipCounters(r, firstFrame);
    m["gpu_ms"] = timing;
    writeFileAtomically(path("metrics.json"), m.dump(2) + "\n");
    return m;
}

} // namespace ssao
