#include "output/report.h"

#include "base/image.h"
#include "output/skip_report.h"
#include "settings/params.h"
#include "settings/preset.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/files.h"
#include "util/json_file.h"

#include <filesystem>
#include <fstream>

namespace ssao {

namespace {

nlohmann::json statsJson(const Stats& s) {
    return {{"min", s.min}, {"mean", s.mean},  {"max", s.max},
            {"p05", s.p05}, {"median", s.p50}, {"pixels", s.count}};
}

nlohmann::json bufferJson(const CapturedBuffer& b, const Image& mask) {
    const Stats s = stats(b.values, &mask);
    nlohmann::json j = {{"format", b.format},     {"size", {b.width, b.height}}, {"scale", b.scale},
                        {"channels", b.channels}, {"nonfinite", s.nonFinite},    {"help", b.help}};
    if (b.channels == 1) j["geometry"] = statsJson(s);
    return j;
}

} // namespace

nlohmann::json frameStatistics(const FrameCapture& c) {
    const Image& mask = c.get("gbuffer.depth").values; // linear depth: > 0 on geometry
    nlohmann::json j;
    for (const CapturedBuffer& b : c.buffers)
        j["buffers"][b.name] = bufferJson(b, mask);
    j["ao"] = statsJson(stats(c.get("ao.denoised").values, &mask));
    j["ao_raw"] = statsJson(stats(c.get("ao.raw").values, &mask));
    j["geometry_pixels"] = stats(mask, &mask).count;
    const Param* mode = findParam("ao.radius_mode");
    j["radius"] = {{"mode", mode->format(mode->get(c.settings))},
                   {"world_at_centre", c.radius.world},
                   {"pixels_at_centre", c.radius.pixels},
                   {"centre_depth", c.radius.depth},
                   {"scene_diagonal", c.radius.sceneDiagonal}};
    // What the view spans at its median depth, and the world radius that gives it the scene mode's
    // share of a framed scene (the view-radius check's suggestion, metrics/radius_check.h).
    if (const ViewRadiusCheck vr = checkViewRadius(c); vr.viewExtent > 0) {
        j["radius"]["view_extent"] = vr.viewExtent;
        j["radius"]["for_view"] = vr.suggested;
    }
    return j;
}

nlohmann::json writeOutputs(const FrameCapture& c, const std::string& dir, const RunInfo& info,
                            const FrameReport& firstFrame, const nlohmann::json& timing) {
    namespace fs = std::filesystem;
    makeOutputFolder(dir);
    auto path = [&](const std::string& f) { return (fs::path(dir) / f).string(); };

    nlohmann::json m = frameStatistics(c);
    for (const CapturedBuffer& b : c.buffers) {
        auto& entry = m["buffers"][b.name];
        if (b.floatData) {
            writeExr(b.values, path(b.name + ".exr"));
            entry["exr"] = b.name + ".exr";
        }
        if (b.preview.data.empty()) continue;
        writePng(b.preview, path(b.name + ".png"));
        entry["png"] = b.name + ".png";
        entry["display_range"] =
            b.channels == 1 ? nlohmann::json{b.rangeLo.x, b.rangeHi.x}
                            : nlohmann::json{{b.rangeLo.x, b.rangeLo.y, b.rangeLo.z}, {b.rangeHi.x, b.rangeHi.y, b.rangeHi.z}};
        entry["display_range_fitted"] = b.rangeFitted;
    }
    const Camera& cam = c.camera;
    m["scene"] = {{"name", info.sceneName}, {"triangles", info.triangles}, {"diagonal", 2.0f * c.sceneRadius}};
    // Triangles per glTF material class, and what became of the transparent ones (scene.h Transparent).
    m["scene"]["materials"] = {{"opaque_triangles", info.materials.opaque},
                               {"mask_triangles", info.materials.mask},
                               {"blend_triangles", info.materials.blend},
                               {"blend", info.materials.blend == 0 ? "none"
                                         : info.materials.blendSkipped ? "skipped (not drawn, not an occluder)"
                                                                       : "drawn and traced as opaque"},
                               {"mask", info.materials.mask == 0 ? "none"
                                        : "cut out where base-colour alpha < alphaCutoff (G-buffer discard, reference hit filter)"},
                               {"mask_textures", info.materials.maskTextures},
                               {"mask_texture_pixels", info.materials.maskPixels},
                               {"mask_decode_ms", info.materials.maskDecodeMs}};
    if (info.sceneOrigin != glm::dvec3(0.0))
        m["scene"]["origin"] = {info.sceneOrigin.x, info.sceneOrigin.y, info.sceneOrigin.z};
    Camera fileCamera = cam; // in the file's coordinates, as --camera and presets take it
    fileCamera.eye = glm::vec3(info.sceneOrigin + glm::dvec3(cam.eye));
    fileCamera.target = glm::vec3(info.sceneOrigin + glm::dvec3(cam.target));
    m["camera"] = cameraToJson(fileCamera);
    m["camera"]["source"] = info.cameraSource;
    m["size"] = {c.width, c.height};
    m["gl_renderer"] = info.glRenderer;
    m["gl_platform"] = info.glPlatform;
    m["settings"] = toJson(c.settings);
    m["passes"] = c.passOrder;
    m["passes_run"] = firstFrame.ran();
    m["skips"] = skipCounters(c, firstFrame);
    m["gpu_ms"] = timing;
    writeFileAtomically(path("metrics.json"), dumpJson(m) + "\n");
    return m;
}

} // namespace ssao
