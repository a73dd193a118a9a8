// What the cursor points at in the explorer: the GPU taps the AO pass took for that pixel (replayed
// with INSPECT) and every buffer's value there, cached so that hovering does not read the GPU back
// every frame and moving the view does not re-run the probe.
#pragma once
#include "renderer.h"
#include "view/frame/view_state.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ssao {

class Inspector {
  public:
    // The G-buffer pixel under view.hoverUv at the renderer's current size; (-1, -1) when nowhere.
    static glm::ivec2 hoverPixel(const Renderer& r, const ViewState& view);
    // The GPU taps at the hovered pixel of the hovered chain; not re-run while the view moves
    // (`interacting`: the last record is kept). A replay that throws leaves `error` set.
    const std::optional<PixelInspection>& inspection(Renderer& r, const ViewState& view, bool interacting,
                                                     std::string& error);
    // Decoded value(s) of a buffer at a G-buffer pixel (y from the top); `channels` of them. Empty
    // when the current view did not compute that buffer this frame.
    std::vector<float> valueAt(const Renderer& r, const std::string& buffer, glm::ivec2 pixel);

  private:
    std::optional<PixelInspection> inspection_;
    glm::ivec2 inspectedPixel_{-1, -1};
    int inspectedChain_ = -1;
    uint64_t inspectedVersion_ = 0;
    struct CachedValue {
        glm::ivec2 pixel{-1};
        uint64_t version = 0;
        unsigned generation = 0;
        std::vector<float> values;
    };
    std::map<std::string, CachedValue> values_;
};

} // namespace ssao
