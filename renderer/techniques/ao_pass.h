// What every technique's AO pass shares: it writes the chain's ao.raw (R32F at the AO resolution:
// never 8-bit, which turns a NaN into 1.0 on llvmpipe and hides the bug from every test), draws one
// fullscreen triangle with its fragment shader, and replays that shader with INSPECT for the
// sample inspector. Its config (graph/pass_config.h) is the technique's constant block, the frame
// block and the shared textures it binds - all derived from the settings by config(), so run()
// and the inspector use nothing else.
#pragma once
#include "gl/shader_library.h"
#include "graph/inspect_probe.h"
#include "graph/pass.h"
#include "techniques/deinterleave.h"
#include "techniques/noise/noise.h"
#include "techniques/technique_settings.h"

#include "../../shaders/include/bindings.h"

#include <functional>
#include <string>

namespace ssao {

// The MIP a tap d pixels away reads from the position pyramid, log2(d) - offset, of the two families
// (shaders/include/position_taps.glsl).
constexpr float kSaoMipOffset = 3.0f;    // SAO's LOG_MAX_OFFSET (SAO and HBAO)
constexpr float kXeGtaoMipOffset = 3.3f; // XeGTAO's depthMIPSamplingOffset (GTAO, visibility bitmask)

SSAO_CONFIG_BEGIN
// The CPU choices every AO pass makes, from the settings (never from packed GPU words).
struct AoBindings {
    int32_t gbufferNormals = 0; // reads and binds gbuffer.normal (else normals come from positions)
    int32_t blueNoise = 0;      // binds the blue-noise tile (the technique's noise is `blue`)
    int32_t pyramid = 0;        // reads and binds gbuffer.position_mips (passes/position_pyramid_pass.h)
    int32_t guardBand = 0;      // reads and binds gbuffer.guard_band (passes/guard_band_pass.h)
    int32_t backDepth = 0;      // reads and binds gbuffer.back_depth (passes/back_face_pass.h)
    int32_t secondLayer = 0;    // reads and binds gbuffer.second_layer (passes/second_layer_pass.h)
    int32_t deinterleave = 0;   // ao.deinterleave in effect: drawn over 16 layers (techniques/deinterleave.h)
};

// The config of a technique that is one constant block and one shader.
template <class Constants> struct AoConfig {
    Constants constants;       // the technique's block, from its pure pack function
    gpu::FrameConstants frame; // the frame block its shader reads
    AoBindings bind;
};
SSAO_CONFIG_END

// The chain's ao.raw at the AO resolution.
ResourceDesc aoRawOutput(const Chain& chain, const Settings& s);
// The shared AO block for these settings and this frame: radius (in displayed pixels for screen
// mode), power, target size, sky skip, adaptive samples, the G-buffer's normal encoding, and the
// technique's noise kind and position-pyramid offset (0 = no pyramid).
gpu::AoCommon aoCommonFor(const Settings& s, const FrameInfo& f, AoNoise noise, float pyramidOffset);
// `band`: the technique reads the guard band and the back-face layer when the settings have them
// (its taps go through aoTapHeld and aoBackGap, shaders/include/position_taps.glsl).
AoBindings aoBindings(const Settings& s, AoNoise noise, bool pyramid, bool band = true);
// Declares `positions` (the G-buffer's positions, or the depth buffer it rebuilds them from), the
// reads AoBindings imply (gbuffer.normal, gbuffer.position_mips) and the ao.raw write.
void declareAoInputs(PassBuilder& b, const Chain& chain, const Settings& s, const AoBindings& bind,
                     const std::string& positions);

// The shader variant for a packed block: AO_PYRAMID, AO_BAND, AO_BACK_DEPTH and AO_NORMALS_DEPTH
// for the optional inputs and the depth-normal estimator the block enables (position_taps.glsl,
// ao_common.glsl), AO_NOISE for its noise kind (noise.glsl) and AO_POWER_ONE for a power of 1.
// Derived from the packed words themselves, so the variant cannot disagree with its constants;
// what they leave off is not compiled in (a uniform branch is not free on llvmpipe).
gl::Defines aoFeatureDefines(const gpu::AoCommon& c);

// GL state an AO pass keeps: the blue-noise tile (made on first use) and the inspector's probe.
class AoShared {
  public:
    // Binds gbuffer.normal, the blue-noise tile and the pyramid as `bind` says.
    void bind(PassContext& ctx, const AoBindings& bind, const std::string& pass);
    // Draws `shader`, in the variant `common` calls for, over the chain's ao.raw (or, inspect =
    // true, the INSPECT variant into the probe); with bind.deinterleave over the 16 layers of
    // `frame`'s G-buffer, interleaved back into ao.raw.
    void draw(PassContext& ctx, const Chain& chain, const std::string& shader, const gpu::AoCommon& common,
              const AoBindings& bind, const gpu::FrameConstants& frame, bool inspect);
    // Deinterleaved, the pixel's own layer is probed (the layers of the last run), its taps
    // given as uvs of the frame.
    bool inspect(PassContext& ctx, const Chain& chain, glm::ivec2 pixel, PixelInspection& out, bool deinterleaved,
                 const std::function<void()>& drawInspect);

  private:
    gl::Texture2D blueNoise_;
    InspectProbe probe_;
    Deinterleaver deinterleaver_;
    int inspectLayer_ = 0; // the layer the INSPECT draw binds (deinterleaved)
};

template <class Config> class AoPass : public ConfiguredPass<Config> {
  public:
    explicit AoPass(const Chain& c) : ConfiguredPass<Config>(c.res("ao"), c) {}
    bool inspect(PassContext& ctx, glm::ivec2 pixel, PixelInspection& out) override {
        const Config c = ctx.config().template as<Config>();
        return shared_.inspect(ctx, this->chain(), pixel, out, c.bind.deinterleave != 0, [&] { draw(ctx, c, true); });
    }

  protected:
    void run(PassContext& ctx, const Config& c) override { draw(ctx, c, false); }
    // Binds the technique's inputs and constants; returns its fragment shader (under shaders/).
    virtual std::string prepare(PassContext& ctx, const Config& c) = 0;
    AoShared shared_;

  private:
    void draw(PassContext& ctx, const Config& c, bool inspect) {
        shared_.draw(ctx, this->chain(), prepare(ctx, c), c.constants.aoCommon, c.bind, c.frame, inspect);
    }
};

// The pass of a technique that is one constant block and one shader over positions and normals
// (SAO, HBAO, GTAO, visibility bitmask). Module gives:
//   using Constants;                       its std140 block (shaders/techniques/ID/layout.h)
//   static constexpr const char* shader;   its fragment shader
//   static constexpr float pyramidOffset;  kSaoMipOffset or kXeGtaoMipOffset
//   static AoNoise noise(const Settings&); static bool pyramid(const Settings&);
//   static Constants pack(const Settings&, const gpu::AoCommon&);   pure, tested
template <class Module> class OneBlockPass final : public AoPass<AoConfig<typename Module::Constants>> {
    using Config = AoConfig<typename Module::Constants>;

  public:
    using AoPass<Config>::AoPass;
    void setup(PassBuilder& b, const Settings& s) const override {
        declareAoInputs(b, this->chain(), s, aoBindings(s, Module::noise(s), Module::pyramid(s)), "gbuffer.position");
    }
    Config config(const Settings& s, const FrameInfo& f) const override {
        Config c{};
        const AoNoise noise = Module::noise(s);
        const bool pyramid = Module::pyramid(s);
        c.constants = Module::pack(s, aoCommonFor(s, f, noise, pyramid ? Module::pyramidOffset : 0.0f));
        c.frame = f.constants;
        c.bind = aoBindings(s, noise, pyramid);
        return c;
    }

  private:
    std::string prepare(PassContext& ctx, const Config& c) override {
        if (!ubo_) ubo_ = gl::UniformBuffer(sizeof(c.constants), this->name() + ".constants");
        ubo_.upload(&c.constants, sizeof c.constants);
        ubo_.bind(SSAO_UBO_AO);
        ctx.in("gbuffer.position").bind(SSAO_TEX_POSITION);
        this->shared_.bind(ctx, c.bind, this->name());
        return Module::shader;
    }
    gl::UniformBuffer ubo_;
};

} // namespace ssao
