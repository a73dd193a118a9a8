// What every technique's AO pass shares: it writes the chain's ao.raw (R32F at the AO resolution:
// never 8-bit, which turns a NaN into 1.0 on llvmpipe and hides the bug from every test), draws one
// fullscreen triangle with its fragment shader, and replays that shader with INSPECT for the
// sample inspector. A technique's pass supplies its inputs, constants and shader (prepare()).
#pragma once
#include "graph/inspect_probe.h"
#include "graph/pass.h"
#include "techniques/position_pyramid.h"

#include "../../shaders/include/bindings.h"

namespace ssao {

class AoPass : public Pass {
  public:
    explicit AoPass(const Branch& b) : Pass(b.res("ao"), b) {}
    void execute(PassContext& ctx) override { draw(ctx, false); }
    bool inspect(PassContext& ctx, glm::ivec2 pixel, PixelInspection& out) override;

  protected:
    ResourceDesc rawOutput(const Settings& s) const; // the chain's ao.raw
    // The common declaration of a pass that reads G-buffer positions and normals and the settings
    // groups "ao" and `group`, and writes ao.raw (horizon techniques: HBAO, GTAO...).
    void declarePositionsNormals(PassBuilder& b, const Settings& s, const char* group) const;
    void bindPositionsNormals(PassContext& ctx) const;
    // This frame's shared constants: radius (in displayed pixels for screen mode), power, target.
    gpu::AoCommon common(PassContext& ctx) const;
    bool normalUnorm(PassContext& ctx) const; // the normal target stores (n+1)/2
    // What the packed constants ask of the shared shader code (include/noise.glsl, position_taps.glsl):
    // binds the blue-noise tile when shape.y is SSAO_NOISE_BLUE, and builds and binds the position
    // pyramid when shape.w (its offset) is non-zero.
    void bindShared(PassContext& ctx, const gpu::AoCommon& c);
    // Binds the technique's inputs and constants; returns its fragment shader (under shaders/).
    virtual std::string prepare(PassContext& ctx) = 0;

  private:
    void draw(PassContext& ctx, bool inspect);
    InspectProbe probe_;
    PositionPyramid pyramid_;
    gl::Texture2D blueNoise_;
};

// The pass of a technique that is one constant block and one shader over positions and normals
// (SAO, HBAO, GTAO, visibility bitmask): Traits gives `Constants`, `group`, `shader` and
// `static Constants pack(const Settings&, const gpu::AoCommon&, bool normalUnorm)`.
template <class Traits> class OneBlockPass final : public AoPass {
  public:
    using AoPass::AoPass;
    void setup(PassBuilder& b, const Settings& s) const override {
        declarePositionsNormals(b, s, Traits::group);
    }

  private:
    std::string prepare(PassContext& ctx) override {
        if (!ubo_) ubo_ = gl::UniformBuffer(sizeof(typename Traits::Constants), name() + ".constants");
        const typename Traits::Constants c = Traits::pack(ctx.settings, common(ctx), normalUnorm(ctx));
        ubo_.upload(&c, sizeof c);
        ubo_.bind(SSAO_UBO_AO);
        bindShared(ctx, c.aoCommon);
        bindPositionsNormals(ctx);
        return Traits::shader;
    }
    gl::UniformBuffer ubo_;
};

} // namespace ssao
