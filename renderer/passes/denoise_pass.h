// The denoise stage: a separable filter of the raw AO (box 4x4 of seed 004 or gaussian of seed 003),
// x pass at the AO's resolution, y pass at full resolution — so reduced-resolution AO is
// upsampled (bilinearly) here — or the edge-aware bilateral, which reads depth and normals and
// upsamples jointly.
#pragma once
#include "graph/pass.h"
#include "passes/temporal_accumulator.h"

namespace ssao {

class DenoisePass final : public Pass {
  public:
    explicit DenoisePass(const Branch& b) : Pass(b.res("denoise"), b) {}
    void setup(PassBuilder& b, const Settings& s) const override;
    void execute(PassContext& ctx) override;

  private:
    void separable(PassContext& ctx); // box or gaussian, x then y
    void bilateral(PassContext& ctx); // edge-aware, 1-3 passes at full resolution
    gl::UniformBuffer ubo_[2];
    gl::Sampler linear_;
    TemporalAccumulator temporal_; // when temporal.enabled: accumulates ao.denoised over frames
};

} // namespace ssao
