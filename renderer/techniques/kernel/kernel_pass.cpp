#include "techniques/kernel/kernel_pass.h"

#include "techniques/kernel/pack.h"
#include "techniques/kernel/sampling.h"

namespace ssao {

void KernelPass::setup(PassBuilder& b, const Settings& s) const {
    b.read(s.kernel.positionSource == PositionSource::Depth ? "gbuffer.zbuffer" : "gbuffer.position");
    if (s.ao.normals == NormalSource::GBuffer) b.read("gbuffer.normal"); // else rebuilt from positions
    b.write(rawOutput(s));
    b.settings("ao");
    b.settings("kernel");
    b.settings("skip.sky");
    b.usesScene();  // scene-relative radius
    b.usesCamera(); // screen-space radius, projection
    b.usesFrameIndex(); // the noise tile's shift
}

std::string KernelPass::prepare(PassContext& ctx) {
    const Settings& s = ctx.settings;
    if (!ubo_) ubo_ = gl::UniformBuffer(sizeof(gpu::KernelConstants), name() + ".constants");
    if (noiseSeed_ != s.kernel.seed) {
        // 4x4 tile of rotation vectors (seed 000), REPEAT-wrapped across the screen.
        noise_ = gl::Texture2D(4, 4, GL_RGBA32F, name() + ".noise");
        noise_.setWrap(GL_REPEAT);
        std::vector<glm::vec4> texels;
        for (auto& v : makeNoise(uint32_t(s.kernel.seed)))
            texels.emplace_back(v, 0.0f);
        glTextureSubImage2D(noise_.id(), 0, 0, 0, 4, 4, GL_RGBA, GL_FLOAT, texels.data());
        noiseSeed_ = s.kernel.seed;
    }
    const gpu::KernelConstants c = packKernelConstants(s.kernel, common(ctx), normalUnorm(ctx));
    ubo_.upload(&c, sizeof c);
    ubo_.bind(SSAO_UBO_AO);
    if (s.kernel.positionSource == PositionSource::Depth)
        ctx.in("gbuffer.zbuffer").bind(SSAO_TEX_DEPTH);
    else
        ctx.in("gbuffer.position").bind(SSAO_TEX_POSITION);
    if (s.ao.normals == NormalSource::GBuffer) ctx.in("gbuffer.normal").bind(SSAO_TEX_NORMAL);
    noise_.bind(KERNEL_TEX_NOISE);
    return "techniques/kernel/kernel.frag";
}

} // namespace ssao
