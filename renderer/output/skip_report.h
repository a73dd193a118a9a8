// What the frame skipped, as counters for metrics.json ("skips"): passes that ran, were clean
// (inputs unchanged) or culled (nothing wanted reads them); the G-buffer's draws and triangles
// culled outside the view and targets left unwritten; the sky share AO returns at once; and the
// samples the adaptive count saved.
#pragma once
#include "output/frame_capture.h"

#include <nlohmann/json.hpp>

namespace ssao {

// `frame`: the report of the frame the counters describe (which passes ran); the capture's
// gbuffer.depth gives the sky and adaptive counts.
nlohmann::json skipCounters(const FrameCapture& c, const FrameReport& frame);

} // namespace ssao
