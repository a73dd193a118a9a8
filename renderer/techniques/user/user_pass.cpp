#include "techniques/user/user_pass.h"

#include "techniques/user/user_technique.h"
#include "util/error.h"

#include <cstring>

namespace ssao {

UserAoPass::UserAoPass(const Chain& c, std::shared_ptr<const UserTechnique> technique)
    : AoPass(c), technique_(std::move(technique)) {
    if (!technique_) throw Error("user technique pass: no technique");
    source_ = userShaderSource(*technique_);
}

void UserAoPass::setup(PassBuilder& b, const Settings& s) const {
    declareAoInputs(b, chain(), s, aoBindings(s, userNoise(*technique_, s), false), "gbuffer.position");
}

UserAoConfig UserAoPass::config(const Settings& s, const FrameInfo& f) const {
    UserAoConfig c{};
    const AoNoise noise = userNoise(*technique_, s);
    c.constants.aoCommon = aoCommonFor(s, f, noise, 0.0f);
    c.frame = f.constants;
    c.bind = aoBindings(s, noise, false);
    c.bind.deinterleave = 0; // interface 1 draws the frame's pixels only
    const std::vector<unsigned char> packed = packUserParams(technique_->header, userParamValues(*technique_, s));
    if (packed.size() > sizeof c.params) // 24 parameters of 4 bytes: never, by the header's limit
        throw Error(technique_->path + ": " + std::to_string(packed.size()) + " bytes of parameters");
    std::memcpy(c.params, packed.data(), packed.size());
    c.paramBytes = uint32_t(packed.size());
    const unsigned long long h = std::stoull(technique_->hash, nullptr, 16);
    c.fileHash[0] = uint32_t(h), c.fileHash[1] = uint32_t(h >> 32);
    return c;
}

std::string UserAoPass::prepare(PassContext& ctx, const UserAoConfig& c) {
    if (!ubo_) ubo_ = gl::UniformBuffer(sizeof(c.constants), name() + ".constants");
    if (!paramsUbo_) paramsUbo_ = gl::UniformBuffer(sizeof(c.params), name() + ".user_params");
    ubo_.upload(&c.constants, sizeof c.constants);
    ubo_.bind(SSAO_UBO_AO);
    paramsUbo_.upload(c.params, c.paramBytes);
    paramsUbo_.bind(SSAO_UBO_USER);
    ctx.in("gbuffer.position").bind(SSAO_TEX_POSITION);
    shared_.bind(ctx, c.bind, name());
    ctx.shaders.setSource(technique_->path, source_);
    return technique_->path;
}

} // namespace ssao
