// G-buffer in view space (seeds 000/003/004): position, normal, albedo, linear depth, and the
// hardware depth buffer — the inputs every AO technique reads.
#pragma once
#include "graph/pass.h"
#include "scene/gpu_scene.h"

namespace ssao {

class GBufferPass final : public Pass {
  public:
    GBufferPass() : Pass("gbuffer", Branch::a()) {}
    void setup(PassBuilder& b, const Settings& s) const override;
    void execute(PassContext& ctx) override;
    // draws, draws_culled, triangles, triangles_culled, targets_written, targets_skipped
    std::vector<std::pair<std::string, double>> counters() const override;
    const std::vector<std::string>& written() const { return written_; }

  private:
    DrawStats stats_;
    std::vector<std::string> written_; // colour targets the last run wrote
};

GLenum glFormat(TargetFormat f);

} // namespace ssao
