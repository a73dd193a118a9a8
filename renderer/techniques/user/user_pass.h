// A user technique's AO pass (techniques/ao_pass.h), built like OneBlockPass: the shared AO block
// (shaders/techniques/user/layout.h) and the file's shader (user_source.h), plus the parameters'
// std140 block at SSAO_UBO_USER. Its config carries the packed parameter values and the file's
// hash besides, so a changed value or file re-runs it. It reads positions and normals (no position
// pyramid, no deinterleaving: interface 1 offers neither) and the guard band and back-face layer
// where the settings have them.
#pragma once
#include "techniques/ao_pass.h"
#include "techniques/user/user_source.h"

#include "../../../shaders/techniques/user/layout.h"

#include <memory>

namespace ssao {

SSAO_CONFIG_BEGIN
struct UserAoConfig {
    gpu::UserConstants constants;
    gpu::FrameConstants frame;
    AoBindings bind;
    uint32_t params[kMaxUserParams]; // packUserParams' bytes (its 16-byte rounding fits: 24 x 4 = 96)
    uint32_t paramBytes;             // how many of them the block holds
    uint32_t fileHash[2];            // userTechniqueHash, as two words
};
SSAO_CONFIG_END

class UserAoPass final : public AoPass<UserAoConfig> {
  public:
    // Its parameter values and noise kind come from the settings (user_technique.h).
    UserAoPass(const Chain& c, std::shared_ptr<const UserTechnique> technique);
    void setup(PassBuilder& b, const Settings& s) const override;
    UserAoConfig config(const Settings& s, const FrameInfo& f) const override;

  private:
    std::string prepare(PassContext& ctx, const UserAoConfig& c) override;
    std::shared_ptr<const UserTechnique> technique_;
    std::string source_; // userShaderSource(*technique_)
    gl::UniformBuffer ubo_, paramsUbo_;
};

} // namespace ssao
