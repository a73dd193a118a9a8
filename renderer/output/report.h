// Writes a rendered frame to disk: EXR float buffers, PNG previews, metrics.json.
#pragma once
#include "renderer.h"

#include <nlohmann/json.hpp>

#include <string>

namespace ssao {

struct RunInfo {
    std::string sceneName;
    size_t triangles = 0;
    std::string cameraSource; // "file", "builtin", "framed" or "--camera"
    std::string glRenderer;
    std::string glPlatform;
    int timingFrames = 0;
};

// Per-buffer statistics of the current frame (non-finite counts, AO min/mean/max on geometry).
nlohmann::json frameStatistics(const Renderer& r);

// Writes position/normal/depth/ao_raw/ao .exr, a .png preview of each plus albedo and
// composite, and metrics.json into `dir` (created if missing). Returns the metrics.
nlohmann::json writeOutputs(const Renderer& r, const std::string& dir, const RunInfo& info,
                            const FrameReport& firstFrame, const nlohmann::json& timing);

} // namespace ssao
