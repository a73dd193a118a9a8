// The scene's triangles in an Embree 3 BVH (RAII over the device and scene handles), for the
// reference tracer. Built once per scene; queries are thread-safe.
#pragma once
#include "scene/scene.h"

#include <embree3/rtcore.h>

#include <memory>
#include <string>
#include <vector>

namespace ssao {

class EmbreeScene {
  public:
    // Throws ssao::Error naming the problem (Embree device or build failure).
    explicit EmbreeScene(const Scene& scene);
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    RTCScene handle() const { return scene_; }
    const Scene& scene() const { return *source_; }
    double buildMs() const { return buildMs_; }
    // Whether triangle `primID` belongs to a MASK draw: a cut-out sheet (the oracle, screen_layers.h).
    bool sheet(unsigned primID) const {
        return mask_ && primID < mask_->drawOf.size() && mask_->drawOf[primID] >= 0;
    }

    // What the MASK filter reads (alpha_mask.h): per triangle its draw, -1 when not MASK.
    struct MaskData {
        const Scene* scene = nullptr;
        std::vector<int32_t> drawOf;
    };

  private:
    std::unique_ptr<MaskData> mask_; // set when the scene has MASK draws
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    const Scene* source_;
    double buildMs_ = 0;
    std::string error_; // the first message Embree reported
};

} // namespace ssao
