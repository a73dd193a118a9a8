#include "measure/measurement.h"

#include "gl/readback.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ssao {

void Measurement::judge(Renderer& r, const ReferenceImage& ref, const ReferenceImage* oracle) {
    const Image ao = readBack(r.texture("ao.denoised"), 1);
    eval_ = evaluate(ao, ref);
    result_.error = eval_.metrics;
    if (oracle) {
        result_.vsOracle = evaluate(ao, *oracle).metrics;
        result_.hasSplit = true;
    }
}

bool Measurement::step(Renderer& r, const ReferenceImage& ref, const ReferenceImage* oracle) {
    switch (phase_) {
    case Phase::First:
        r.setSettings(settings_);
        r.render();
        judge(r, ref, oracle);
        result_.rmseFirstFrame = result_.error.rmse;
        phase_ = r.accumulating() ? Phase::Accumulating : frames_ > 0 ? Phase::Timing : Phase::Done;
        break;
    case Phase::Accumulating: // temporal: judge the image after its frames are blended
        r.setSettings(settings_); // unchanged settings keep the accumulation going
        r.render();
        ++result_.frames;
        if (!r.accumulating()) {
            judge(r, ref, oracle);
            phase_ = frames_ > 0 ? Phase::Timing : Phase::Done;
        }
        break;
    case Phase::Timing:
        timeFrame(r);
        break;
    case Phase::TwinTiming:
        timeTwin(r);
        break;
    case Phase::Done:
        break;
    }
    return done();
}

namespace {
// Per category, the passes that ran (a pass that did not - the composite when only the AO is
// wanted, as bench judges it - has no time: its category stays NaN, "not run").
std::array<double, PassTimes::kParts> partsOf(const FrameReport& fr) {
    std::array<double, PassTimes::kParts> part;
    part.fill(std::numeric_limits<double>::quiet_NaN());
    for (const auto& p : fr.passes) {
        const int k = passCategory(p.name);
        if (k < 0 || p.culled || !(p.gpuMs >= 0)) continue;
        part[k] = (std::isnan(part[k]) ? 0.0 : part[k]) + p.gpuMs;
    }
    return part;
}

bool singlePassLayer(const Settings& s) {
    return s.gbuffer.secondLayer && s.gbuffer.secondLayerBuild == SecondLayerBuild::Previous;
}
} // namespace

void Measurement::timeFrame(Renderer& r) {
    r.setSettings(settings_);
    r.invalidate(); // every pass runs: the time of a whole frame of this configuration
    const auto part = partsOf(r.render());
    if (timed_++ >= warmup_) {
        double sum = 0; // every pass but the G-buffer and the composite, as every row compares
        for (int k = 1; k <= 3; ++k)
            sum += std::isnan(part[k]) ? 0.0 : part[k];
        ms_.push_back(sum);
        for (int k = 0; k < PassTimes::kParts; ++k)
            parts_[k].push_back(part[k]);
    }
    if (timed_ < warmup_ + frames_) return;
    result_.gpuMs = median(ms_);
    for (int k = 0; k < PassTimes::kParts; ++k)
        result_.passMs.ms[k] = median(parts_[k]);
    result_.gpuMsMin = *std::min_element(ms_.begin(), ms_.end());
    result_.gpuMsMax = *std::max_element(ms_.begin(), ms_.end());
    timed_ = 0;
    phase_ = singlePassLayer(settings_) ? Phase::TwinTiming : Phase::Done;
}

// The single-pass second layer is drawn inside the G-buffer pass, which no row's time counts: its
// share is the G-buffer's time less the one-layer twin's on the same view, counted as the layer's.
void Measurement::timeTwin(Renderer& r) {
    Settings twin = settings_;
    twin.gbuffer.secondLayer = false;
    r.setSettings(twin);
    r.invalidate();
    const auto part = partsOf(r.render());
    if (timed_++ >= warmup_) twinGBuffer_.push_back(part[0]);
    if (timed_ < warmup_ + frames_) return;
    const double layer = std::max(0.0, result_.passMs.ms[0] - median(twinGBuffer_));
    if (std::isfinite(layer)) {
        double& layers = result_.passMs.ms[1];
        layers = (std::isnan(layers) ? 0.0 : layers) + layer;
        result_.gpuMs += layer, result_.gpuMsMin += layer, result_.gpuMsMax += layer;
    }
    phase_ = Phase::Done;
}

double Measurement::progress() const {
    if (phase_ == Phase::Done) return 1.0;
    const int timing = warmup_ + frames_; // per timed configuration: the row's, and its twin's
    const double total = 1.0 + (result_.frames - 1) + timing * (singlePassLayer(settings_) ? 2 : 1);
    const double doneFrames = (phase_ == Phase::First ? 0.0 : 1.0 + (result_.frames - 1)) + timed_ +
                              (phase_ == Phase::TwinTiming ? timing : 0);
    return std::min(doneFrames / std::max(total + (phase_ == Phase::Accumulating ? 1.0 : 0.0), 1.0), 0.99);
}

ViewResult measure(Renderer& r, const Settings& s, const ReferenceImage& ref, int warmup, int frames,
                   const ReferenceImage* oracle) {
    Measurement m(s, warmup, frames);
    while (!m.step(r, ref, oracle)) {
    }
    return m.result();
}

} // namespace ssao
