// The ray-traced reference as buffers of the frame graph: reference.ao and reference.error are
// uploaded from CPU images that something outside the graph computes (the app's background
// tracer), so the grid, the single view, the hover readout and the timing table treat them like
// any other buffer. The pass re-runs when the images' version changes (Pass::externalVersion).
#pragma once
#include "graph/pass.h"
#include "settings/settings.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace ssao {

// Single-channel images, row-major, top row first, width * height values each.
struct ReferenceBuffers {
    int width = 0, height = 0; // 0: no reference for this view yet — both buffers read 0
    std::vector<float> ao;     // the reference AO, 1 = unoccluded (sky 1)
    std::vector<float> error;  // signed error ao.denoised - reference (+ = too bright), sky 0
    uint64_t version = 0;      // > 0; a new value for new contents
};

class ReferencePass final : public ConfiguredPass<NoConfig> {
  public:
    ReferencePass() : ConfiguredPass("reference", Chain::a()) {}
    void setBuffers(std::shared_ptr<const ReferenceBuffers> b) { buffers_ = std::move(b); }
    void setup(PassBuilder& b, const Settings& s) const override;
    NoConfig config(const Settings&, const FrameInfo&) const override { return {}; } // its images alone
    uint64_t externalVersion() const override { return buffers_ ? buffers_->version : 0; }

  private:
    void run(PassContext& ctx, const NoConfig& c) override;
    std::shared_ptr<const ReferenceBuffers> buffers_;
};

} // namespace ssao
