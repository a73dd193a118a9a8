#include "measure/measurement.h"

#include "gl/readback.h"

#include <algorithm>

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
    case Phase::Timing: {
        r.setSettings(settings_);
        r.invalidate(); // every pass runs: the time of a whole frame of this configuration
        const FrameReport fr = r.render();
        // Per category, the passes that ran (a pass that did not - the composite when only the AO
        // is wanted, as bench judges it - has no time: its category stays NaN, "not run").
        const double nan = std::numeric_limits<double>::quiet_NaN();
        double part[PassTimes::kParts] = {nan, nan, nan, nan, nan};
        for (const auto& p : fr.passes) {
            const int k = passCategory(p.name);
            if (k < 0 || p.culled || !(p.gpuMs >= 0)) continue;
            part[k] = (std::isnan(part[k]) ? 0.0 : part[k]) + p.gpuMs;
        }
        if (timed_++ >= warmup_) {
            double sum = 0; // every pass but the G-buffer and the composite, as every row compares
            for (int k = 1; k <= 3; ++k)
                sum += std::isnan(part[k]) ? 0.0 : part[k];
            ms_.push_back(sum);
            for (int k = 0; k < PassTimes::kParts; ++k)
                parts_[k].push_back(part[k]);
        }
        if (timed_ >= warmup_ + frames_) {
            result_.gpuMs = median(ms_);
            for (int k = 0; k < PassTimes::kParts; ++k)
                result_.passMs.ms[k] = median(parts_[k]);
            result_.gpuMsMin = *std::min_element(ms_.begin(), ms_.end());
            result_.gpuMsMax = *std::max_element(ms_.begin(), ms_.end());
            phase_ = Phase::Done;
        }
        break;
    }
    case Phase::Done:
        break;
    }
    return done();
}

double Measurement::progress() const {
    if (phase_ == Phase::Done) return 1.0;
    const double total = 1.0 + (result_.frames - 1) + warmup_ + frames_;
    const double doneFrames = (phase_ == Phase::First ? 0.0 : 1.0 + (result_.frames - 1)) + timed_;
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
