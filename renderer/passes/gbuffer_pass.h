// G-buffer in view space: position, normal, albedo, linear depth, hardware depth.
#pragma once
#include "passes/pass.h"

#include <memory>

namespace ssao {

class GBufferPass final : public Pass {
  public:
    const char* name() const override { return "gbuffer"; }
    std::vector<std::string> settingGroups() const override { return {"gbuffer"}; }
    bool readsScene() const override { return true; }
    bool readsCamera() const override { return true; }
    void run(const FrameInputs& in) override;

    const gl::Texture2D& position() const { return position_; }
    const gl::Texture2D& normal() const { return normal_; }
    const gl::Texture2D& albedo() const { return albedo_; }
    const gl::Texture2D& linearDepth() const { return linearDepth_; }
    const gl::Texture2D& depth() const { return depth_; }

  private:
    gl::Texture2D position_, normal_, albedo_, linearDepth_, depth_;
    std::unique_ptr<gl::Framebuffer> fbo_;
    GBufferSettings built_{};
};

GLenum glFormat(TargetFormat f);

} // namespace ssao
