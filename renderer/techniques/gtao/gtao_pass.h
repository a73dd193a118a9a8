// GTAO's pass: reads the G-buffer (positions, normals), writes ao.raw (R32F, never 8-bit: an
// 8-bit target turns a NaN into 1.0 on llvmpipe and hides the bug from every test).
#pragma once
#include "graph/inspect_probe.h"
#include "graph/pass.h"

namespace ssao {

class GtaoPass final : public Pass {
  public:
    explicit GtaoPass(const Branch& b) : Pass(b.res("ao"), b) {}
    void setup(PassBuilder& b, const Settings& s) const override;
    void execute(PassContext& ctx) override;
    bool inspect(PassContext& ctx, glm::ivec2 pixel, PixelInspection& out) override;

  private:
    void draw(PassContext& ctx, bool inspect);
    gl::UniformBuffer ubo_;
    InspectProbe probe_;
};

} // namespace ssao
