// The SSAO shader (shaders/passes/ssao.frag) replayed on the CPU for one pixel: where each
// kernel sample lands on screen and whether it counted as occluded. The app draws this over the
// image (like ASSAO's taps-at-cursor view); a test checks it reproduces the GPU's AO.
#pragma once
#include "output/image.h"
#include "settings/settings.h"

#include "../../shaders/include/bindings.h"

#include <glm/glm.hpp>

#include <vector>

namespace ssao {

// G-buffer read back to the CPU (Image rows top-to-bottom, as readBack returns them).
struct GBufferImages {
    const Image* position = nullptr; // 4 channels, w = geometry mask
    const Image* normal = nullptr;   // 3 channels, raw texel values (encoded when rgba8)
    const Image* depth = nullptr;    // 1 channel, hardware depth [0,1]
};

struct SampleTap {
    enum class State { Open, Occluded, BehindEye, Offscreen, Sky };
    glm::vec3 viewPos{0.0f}; // sample point, view space
    glm::vec2 uv{0.0f};      // where it projects (GL uv: origin bottom-left)
    float occlusion = 0.0f;  // contribution, range-check weight included
    State state = State::Open;
    int set = 0; // 0 = main / x-plane set, 1 = y-plane set (separable)
};

struct PixelInspection {
    bool geometry = false;
    glm::vec3 position{0.0f}, normal{0.0f};
    std::vector<SampleTap> taps;
    float ao = 1.0f; // what the shader writes to ao_raw for this pixel
};

// x, y: pixel, y counted from the top of the image.
PixelInspection inspectPixel(const SsaoSettings& s, const GBufferSettings& g,
                             const gpu::FrameConstants& frame, const GBufferImages& gb, int x, int y);

const char* tapStateName(SampleTap::State s);

} // namespace ssao
