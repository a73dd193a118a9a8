// Writes a rendered frame to disk: every buffer of the frame graph as EXR (float buffers) and a
// PNG preview (the app's display mapping), and metrics.json.
#pragma once
#include "display/display_range.h"
#include "renderer.h"

#include <nlohmann/json.hpp>

#include <string>

namespace ssao {

struct RunInfo {
    std::string sceneName;
    size_t triangles = 0;
    glm::dvec3 sceneOrigin{0.0}; // Scene::origin: metrics.json gives the camera in file coordinates
    std::string cameraSource; // "file", "builtin", "framed", "preset" or "--camera"
    std::string glRenderer;
    std::string glPlatform;
    int timingFrames = 0;
    ViewStyle style; // PNG previews: the same mapping as the app's views
};

// Statistics of the current frame: per buffer (size, non-finite count, min/mean/max/p05 over
// geometry) and the AO summary ("ao": the denoised AO, "ao_raw"), plus the radius in use.
nlohmann::json frameStatistics(const Renderer& r);

// Writes NAME.exr for every float buffer, NAME.png for every buffer, and metrics.json into `dir`
// (created if missing). Returns the metrics.
nlohmann::json writeOutputs(Renderer& r, const std::string& dir, const RunInfo& info,
                            const FrameReport& firstFrame, const nlohmann::json& timing);

} // namespace ssao
