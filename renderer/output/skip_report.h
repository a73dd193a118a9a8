// What the frame skipped, as counters for metrics.json ("skips"): passes that ran, were clean
// (inputs unchanged) or culled (nothing wanted reads them); the G-buffer's draws and triangles
// culled outside the view and targets left unwritten; the sky share AO returns at once; and the
// samples the adaptive count saved.
#pragma once
#include "renderer.h"

#include <nlohmann/json.hpp>

namespace ssao {

// `frame`: the report of the frame the counters describe (which passes ran). Reads back
// gbuffer.depth for the sky and adaptive counts.
nlohmann::json skipCounters(const Renderer& r, const FrameReport& frame);

} // namespace ssao
