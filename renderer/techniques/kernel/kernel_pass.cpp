#include "techniques/kernel/kernel_pass.h"

#include "techniques/kernel/pack.h"
#include "techniques/kernel/sampling.h"

namespace ssao {

void KernelPass::setup(PassBuilder& b, const Settings& s) const {
    const bool fromDepth = s.kernel.positionSource == PositionSource::Depth;
    declareAoInputs(b, chain(), s, aoBindings(s, AoNoise::None, false, false),
                    fromDepth ? "gbuffer.zbuffer" : "gbuffer.position");
}

KernelConfig KernelPass::config(const Settings& s, const FrameInfo& f) const {
    KernelConfig c{};
    // Its own 4x4 rotation tile (kernel.noise), none of the horizon techniques' kinds; no pyramid:
    // its taps are projected 3-D points.
    c.constants = packKernelConstants(s.kernel, aoCommonFor(s, f, AoNoise::None, 0.0f));
    c.frame = f.constants;
    c.bind = aoBindings(s, AoNoise::None, false, false);
    c.positionsFromDepth = s.kernel.positionSource == PositionSource::Depth;
    c.noiseSeed = s.kernel.seed;
    return c;
}

std::string KernelPass::prepare(PassContext& ctx, const KernelConfig& c) {
    if (!ubo_) ubo_ = gl::UniformBuffer(sizeof(gpu::KernelConstants), name() + ".constants");
    if (noiseSeed_ != c.noiseSeed) {
        // 4x4 tile of rotation vectors (seed 000), REPEAT-wrapped across the screen.
        noise_ = gl::Texture2D(4, 4, GL_RGBA32F, name() + ".noise");
        noise_.setWrap(GL_REPEAT);
        std::vector<glm::vec4> texels;
        for (auto& v : makeNoise(uint32_t(c.noiseSeed)))
            texels.emplace_back(v, 0.0f);
        glTextureSubImage2D(noise_.id(), 0, 0, 0, 4, 4, GL_RGBA, GL_FLOAT, texels.data());
        noiseSeed_ = c.noiseSeed;
    }
    ubo_.upload(&c.constants, sizeof c.constants);
    ubo_.bind(SSAO_UBO_AO);
    if (c.positionsFromDepth)
        ctx.in("gbuffer.zbuffer").bind(SSAO_TEX_DEPTH);
    else
        ctx.in("gbuffer.position").bind(SSAO_TEX_POSITION);
    shared_.bind(ctx, c.bind, name());
    noise_.bind(KERNEL_TEX_NOISE);
    return "techniques/kernel/kernel.frag";
}

} // namespace ssao
