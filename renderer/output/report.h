// Writes a captured frame (output/frame_capture.h) to disk: every buffer as EXR (float buffers)
// and its PNG preview (the app's display mapping), and metrics.json. No GL: the capture holds it all.
#pragma once
#include "output/frame_capture.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <string>

namespace ssao {

struct RunInfo {
    std::string sceneName;
    size_t triangles = 0;
    MaterialCounts materials; // the scene's material classes (Scene::materials)
    glm::dvec3 sceneOrigin{0.0}; // Scene::origin: metrics.json gives the camera in file coordinates
    std::string cameraSource; // "file", "builtin", "framed", "preset" or "--camera"
    std::string glRenderer;
    std::string glPlatform;
    int timingFrames = 0;
};

// Statistics of the frame: per buffer (size, non-finite count, min/mean/max/p05 over geometry) and
// the AO summary ("ao": the denoised AO, "ao_raw"), plus the radius in use.
nlohmann::json frameStatistics(const FrameCapture& c);

// Writes NAME.exr for every float buffer, NAME.png for every buffer, and metrics.json into `dir`
// (created if missing). Returns the metrics.
nlohmann::json writeOutputs(const FrameCapture& c, const std::string& dir, const RunInfo& info,
                            const FrameReport& firstFrame, const nlohmann::json& timing);

} // namespace ssao
