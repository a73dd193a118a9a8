// The denoise stage: a separable filter of the raw AO (box 4x4 of seed 004 or gaussian of seed 003)
// or the edge-aware bilateral (depth and normals); then, when on, temporal accumulation.
// Reduced-resolution AO (denoise.upsample): joint - every filter pass at the AO's resolution, then
// one joint-bilateral 2x2 upsample (passes/upsample_joint.frag); filter - the separable y pass (or
// the copy of none) upsamples bilinearly, the bilateral runs at full resolution and upsamples with
// its own weights.
#pragma once
#include "graph/pass.h"
#include "passes/temporal_accumulator.h"
#include "settings/settings.h"

namespace ssao {

SSAO_CONFIG_BEGIN
struct DenoiseConfig {
    int32_t bilateral;     // the edge-aware filter (x: its constants), else the separable x and y passes
    int32_t passes;        // bilateral passes; separable: 2 (x, then y), or 1 for none (one copy, upsampling)
    int32_t bilinearTaps;  // both passes read bilinearly (the centred box's half-texel taps)
    int32_t skipSky;       // reads gbuffer.depth: the last pass returns 1 on sky pixels
    int32_t joint;         // reduced AO: filter at its resolution, then the joint 2x2 upsample (up)
    int32_t copy;          // none at full resolution: ao.raw copied as it is (copiesRaw)
    gpu::DenoiseConstants x, y, up;
    TemporalConfig temporal;
};
SSAO_CONFIG_END

// Denoise `none` with the AO at full resolution is the identity: ao.raw is copied, no pass runs a
// shader and nothing else (the depth for the sky) is read.
bool copiesRaw(const Settings& s);

class DenoisePass final : public ConfiguredPass<DenoiseConfig> {
  public:
    explicit DenoisePass(const Chain& c) : ConfiguredPass(c.res("denoise"), c) {}
    void setup(PassBuilder& b, const Settings& s) const override;
    DenoiseConfig config(const Settings& s, const FrameInfo& f) const override;

  private:
    void run(PassContext& ctx, const DenoiseConfig& c) override;
    void separable(PassContext& ctx, const DenoiseConfig& c, const std::string& out); // box or gaussian, x then y
    // Edge-aware, 1-3 passes from `input`, ending in `last` (the other target is `spare`).
    void bilateral(PassContext& ctx, const DenoiseConfig& c, const std::string& input, const std::string& spare,
                   const std::string& last);
    void jointUpsample(PassContext& ctx, const DenoiseConfig& c, const std::string& input);
    gl::UniformBuffer ubo_[3]; // x, y, upsample
    gl::Sampler linear_;
    TemporalAccumulator temporal_; // when temporal.enabled: accumulates ao.denoised over frames
};

} // namespace ssao
