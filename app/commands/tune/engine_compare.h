// ssaolab's answer beside a tuned engine (tune --engine's page): every shipped preset measured on
// a view with bench's steps (measure/measurement.h) at the engine's R, and the most accurate one
// within a time. Times: ssaolab's AO + denoise GPU time (timer queries); an engine's is its frame
// with the pass minus without, in the browser: the same machine, not the same clock.
#pragma once
#include "cli/headless_runner.h"
#include "metrics/evaluate.h"
#include "reference/reference_ao.h"
#include "scene/scene.h"

#include <memory>
#include <string>
#include <vector>

namespace ssao {

struct PresetPoint {
    std::string preset;
    double rmse = 0, ms = 0; // geometry RMSE; median AO + denoise ms
    std::shared_ptr<const Evaluation> eval;
};

// Every shipped preset on `camera` of `scene` at world radius `radius`, sized as `ref`.
std::vector<PresetPoint> measureShippedPresets(const HeadlessRunner& runner, const Scene& scene, const Camera& camera,
                                               const ReferenceImage& ref, float radius, int warmup, int frames);

// The lowest RMSE among points with ms <= `ms`; nullptr when none is that fast.
const PresetPoint* mostAccurateWithin(const std::vector<PresetPoint>& points, double ms);

} // namespace ssao
