// G-buffer in view space (seeds 000/003/004): position, normal, albedo, linear depth, and the
// hardware depth buffer — the inputs every AO technique reads.
#pragma once
#include "graph/pass.h"

namespace ssao {

class GBufferPass final : public Pass {
  public:
    GBufferPass() : Pass("gbuffer", Branch::a()) {}
    void setup(PassBuilder& b, const Settings& s) const override;
    void execute(PassContext& ctx) override;
};

GLenum glFormat(TargetFormat f);

} // namespace ssao
