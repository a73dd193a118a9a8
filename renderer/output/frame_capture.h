// A rendered frame as plain data: every buffer read back (the values as they mean, and the preview
// the display mapping paints), with what the frame was drawn from. The reports (metrics.json,
// EXR/PNG files, the reference's judgement, the skip counters) are written from this alone, so
// output/ needs no GL and no renderer (display/capture.h fills it on the GL side).
#pragma once
#include "base/image.h"
#include "graph/frame_report.h"
#include "metrics/radius_check.h"
#include "scene/camera.h"
#include "settings/settings.h"
#include "techniques/ao_common.h"

#include <glm/glm.hpp>

#include <string>
#include <utility>
#include <vector>

namespace ssao {

struct CapturedBuffer {
    std::string name, format, help, unit; // format: "r32f", "rgba16f", "rgba8", "depth32f"
    int channels = 1, width = 0, height = 0;
    float scale = 1.0f;    // size relative to the frame (AO at half resolution: 0.5)
    bool floatData = true; // written as EXR (RGBA8 colour buffers are previews only)
    bool grey = false;     // the preview is one grey channel
    Image values;          // decoded: normals as n, not (n+1)/2
    Image preview;         // the display mapping in [0,1] (empty when not painted)
    glm::vec3 rangeLo{0.0f}, rangeHi{1.0f}; // the display range the preview used (scalars: x)
    bool rangeFitted = false;
};

struct FrameCapture {
    std::vector<CapturedBuffer> buffers; // chain A's and the shared ones, in production order
    Settings settings;
    Camera camera; // as rendered (fitted clip planes), in the scene frame
    int width = 0, height = 0;
    float sceneRadius = 1.0f;
    RadiusInfo radius;                   // the AO radius at the centre of the view
    std::vector<std::string> passOrder;  // the graph's
    std::vector<std::pair<std::string, double>> gbufferCounters; // the G-buffer pass's last run

    const CapturedBuffer* find(const std::string& name) const;
    const CapturedBuffer& get(const std::string& name) const; // throws ssao::Error naming it
};

// The view-radius check (metrics/radius_check.h) of a rendered frame: its gbuffer.depth, camera,
// AO settings and scene diagonal.
ViewRadiusCheck checkViewRadius(const FrameCapture& frame);

} // namespace ssao
