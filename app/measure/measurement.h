// One configuration measured on one view, one rendered frame per step: the error of the judged
// image against the reference (after temporal accumulation when it is on), then the GPU time of
// AO + denoise over timed frames. `bench` and `tune` run every step at once (measure()); the
// explorer's front panel runs a few steps between its own frames. Same steps, same numbers.
#pragma once
#include "metrics/bench_summary.h"
#include "metrics/evaluate.h"
#include "reference/reference_ao.h"
#include "renderer.h"

#include <vector>

namespace ssao {

class Measurement {
  public:
    // `frames` = 0 judges the error only (no timing).
    Measurement(const Settings& s, int warmup, int frames) : settings_(s), warmup_(warmup), frames_(frames) {}

    // Renders one frame on `r` (its scene, camera and size already set; it may have rendered other
    // settings in between: each step sets this measurement's own). With the view's screen-space
    // oracle, the judged frame is also compared with it (ViewResult::vsOracle). Returns true once done.
    bool step(Renderer& r, const ReferenceImage& ref, const ReferenceImage* oracle = nullptr);
    bool done() const { return phase_ == Phase::Done; }
    // 0..1: frames rendered of the frames this measurement needs (temporal frames counted as they come).
    double progress() const;

    const ViewResult& result() const { return result_; }
    // The judged frame against the reference: the AO at the reference's size and the signed error
    // (for thumbnails); empty until judged.
    const Evaluation& evaluation() const { return eval_; }
    const Settings& settings() const { return settings_; }

  private:
    enum class Phase { First, Accumulating, Timing, TwinTiming, Done };
    void judge(Renderer& r, const ReferenceImage& ref, const ReferenceImage* oracle);
    void timeFrame(Renderer& r);
    void timeTwin(Renderer& r);

    Settings settings_;
    int warmup_ = 0, frames_ = 0;
    Phase phase_ = Phase::First;
    int timed_ = 0; // timing frames rendered (warm-up included)
    std::vector<double> ms_;
    std::vector<double> parts_[PassTimes::kParts]; // per timed frame, per part (PassTimes)
    std::vector<double> twinGBuffer_; // the one-layer twin's G-buffer pass (second_layer_build = previous)
    ViewResult result_;
    Evaluation eval_;
};

// Every step at once.
ViewResult measure(Renderer& r, const Settings& s, const ReferenceImage& ref, int warmup, int frames,
                   const ReferenceImage* oracle = nullptr);

} // namespace ssao
