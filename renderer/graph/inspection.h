// What the sample inspector shows for one pixel: every tap the AO shader took and what it
// contributed, as recorded by the shader itself (a debug storage buffer, see inspect.glsl).
#pragma once
#include <glm/glm.hpp>

#include <vector>

namespace ssao {

enum class TapState { Open, Occluded, BehindEye, Offscreen, Sky };
const char* tapStateName(TapState s);

struct InspectTap {
    glm::vec3 viewPos{0.0f};   // sample point, view space
    glm::vec2 uv{0.0f};        // where it projects (GL uv: origin bottom-left), resolution independent
    float contribution = 0.0f; // occlusion it added (range-check weight included)
    TapState state = TapState::Open;
    int set = 0; // technique-defined group (separable kernel: 0 = x-plane set, 1 = y-plane set)
    bool backLayer = false; // its solid's far side came from the back-face layer (gbuffer.back_faces)
    bool secondLayer = false; // the surface behind it (gbuffer.second_layer) closed sectors
};

// A tap that left the frame and still found a surface: it read the guard band
// (gbuffer.guard_band_px; passes/guard_band_pass.h).
inline bool fromGuardBand(const InspectTap& t) {
    const bool outside = t.uv.x < 0.0f || t.uv.y < 0.0f || t.uv.x > 1.0f || t.uv.y > 1.0f;
    return outside && t.state != TapState::Offscreen && t.state != TapState::BehindEye;
}

struct PixelInspection {
    bool geometry = false;
    glm::ivec2 pixel{-1};     // in the AO buffer's own resolution
    glm::vec3 position{0.0f}; // view space
    glm::vec3 normal{0.0f};
    std::vector<InspectTap> taps;
    bool truncated = false;  // more taps than the debug buffer holds
    float occlusion = 0.0f;  // sum of contributions
    float normaliser = 1.0f; // what the sum is divided by (N, or 2N when separable)
    float radius = 0.0f;     // world radius used at this pixel
    float ao = 1.0f;         // the value the pass wrote for this pixel
};

} // namespace ssao
