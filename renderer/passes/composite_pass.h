// Final image: ambient * albedo * AO + one point light (seed 004), display gamma, RGBA8.
#pragma once
#include "graph/pass.h"
#include "settings/settings.h"

namespace ssao {

SSAO_CONFIG_BEGIN
struct CompositeConfig {
    gpu::FrameConstants frame; // the light's placement in scene radii (without the frame index)
    float ambient, light;
    int32_t useAo;       // reads the chain's ao.denoised
    int32_t normalUnorm; // normals stored as (n+1)/2
    int32_t fused;       // does the joint upsample itself, from the reduced AO (up: its constants)
    int32_t reducedRaw;  // that AO is ao.raw (no filter before the upsample), else denoise.low
    gpu::DenoiseConstants up;
};
SSAO_CONFIG_END

class CompositePass final : public ConfiguredPass<CompositeConfig> {
  public:
    explicit CompositePass(const Chain& c) : ConfiguredPass(c.res("composite"), c) {}
    void setup(PassBuilder& b, const Settings& s) const override;
    CompositeConfig config(const Settings& s, const FrameInfo& f) const override;
    // Whether nothing outside the graph reads this chain's ao.denoised (the renderer knows what
    // is wanted): then, where the settings call for the joint upsample of reduced AO without
    // temporal accumulation and skip.fused_upsample is on, this pass upsamples inline and the
    // denoise pass leaves ao.denoised unwritten - one full-resolution pass fewer. The composite
    // is the same either way (tests/gl/test_upsample.cpp); on llvmpipe the frame is no faster
    // (`ssaolab skips`, row "fused"), hence off by default.
    void allowFusedUpsample(bool allowed) { fuseAllowed_ = allowed; }
    bool fusesUpsample(const Settings& s) const;
    // The widest the final image is shown (pixels; 0: as rendered): a grid cell shows it ~290
    // pixels wide out of 1172. Nothing in the graph reads it, so it is drawn at that size
    // (ResourceDesc::maxWidth, the cell's own size), each pixel reading the G-buffer and AO texels
    // under its centre - what the cell showed of the full-size image before (view.frag), for a
    // seventeenth of the pixels. Not with the fused upsample (its taps follow the full-resolution
    // pixel), which the grid never runs: the grid shows ao.denoised.
    void setDisplayWidth(int px) { displayWidth_ = px; }

  private:
    void run(PassContext& ctx, const CompositeConfig& c) override;
    std::string reducedAo(bool raw) const { return chain().res(raw ? "ao.raw" : "denoise.low"); }
    bool fuseAllowed_ = false;
    int displayWidth_ = 0;
    gl::UniformBuffer ubo_;
};

} // namespace ssao
