// The denoise stage: a separable filter of the raw AO (box 4x4 of seed 004 or gaussian of seed 003),
// x pass at the AO's resolution, y pass at full resolution — so reduced-resolution AO is
// upsampled (bilinearly) here — or the edge-aware bilateral, which reads depth and normals and
// upsamples jointly; then, when on, temporal accumulation.
#pragma once
#include "graph/pass.h"
#include "passes/temporal_accumulator.h"

namespace ssao {

SSAO_CONFIG_BEGIN
struct DenoiseConfig {
    int32_t bilateral;     // the edge-aware filter (x: its constants), else the separable x and y passes
    int32_t passes;        // bilateral passes; separable: 2 (x, then y), or 1 for none (one copy, upsampling)
    int32_t bilinearTaps;  // both passes read bilinearly (the centred box's half-texel taps)
    int32_t skipSky;       // reads gbuffer.depth: the last pass returns 1 on sky pixels
    gpu::DenoiseConstants x, y;
    TemporalConfig temporal;
};
SSAO_CONFIG_END

class DenoisePass final : public ConfiguredPass<DenoiseConfig> {
  public:
    explicit DenoisePass(const Chain& c) : ConfiguredPass(c.res("denoise"), c) {}
    void setup(PassBuilder& b, const Settings& s) const override;
    DenoiseConfig config(const Settings& s, const FrameInfo& f) const override;

  private:
    void run(PassContext& ctx, const DenoiseConfig& c) override;
    void separable(PassContext& ctx, const DenoiseConfig& c); // box or gaussian, x then y
    void bilateral(PassContext& ctx, const DenoiseConfig& c); // edge-aware, 1-3 passes at full resolution
    gl::UniformBuffer ubo_[2];
    gl::Sampler linear_;
    TemporalAccumulator temporal_; // when temporal.enabled: accumulates ao.denoised over frames
};

} // namespace ssao
