// What `bench` and `tune` share: measuring one configuration on one view (error against the
// reference from the first frame, AO + denoise GPU time over timed frames), and run facts.
#pragma once
#include "metrics/bench_summary.h"
#include "reference/reference_ao.h"
#include "renderer.h"

#include <nlohmann/json.hpp>

#include <string>

namespace ssao {

// The settings a configuration runs with: its own, with the bench's world radius R.
Settings withRadius(Settings s, float radius);

// Renders `s` (the renderer's scene, camera and size already set), judges ao.denoised against
// `ref`, then times `frames` frames after `warmup` (every pass forced; AO + denoise summed:
// every pass but the G-buffer and the composite). frames = 0 skips timing.
ViewResult measure(Renderer& r, const Settings& s, const ReferenceImage& ref, int warmup, int frames);

// Machine, GL renderer, build type, date, git revision.
nlohmann::json runFacts(const std::string& glRenderer);

} // namespace ssao
