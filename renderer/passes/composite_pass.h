// Final image: ambient * albedo * AO + one point light (seed 004), display gamma, RGBA8.
#pragma once
#include "graph/pass.h"

namespace ssao {

class CompositePass final : public Pass {
  public:
    explicit CompositePass(const Branch& b) : Pass(b.res("composite"), b) {}
    void setup(PassBuilder& b, const Settings& s) const override;
    void execute(PassContext& ctx) override;
};

} // namespace ssao
