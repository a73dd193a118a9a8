// Display images (RGBA8) of the renderer's buffers for the app, painted by the same ViewPainter
// as the PNG previews. A view is repainted only when its buffer or the display style changed.
#pragma once
#include "display/view_painter.h"
#include "renderer.h"

#include <map>
#include <string>
#include <vector>

namespace ssao {

class BufferViews {
  public:
    struct View {
        gl::RenderTarget target;
        DisplayRange range;
        uint64_t version = 0;
        unsigned generation = 0;
        ViewStyle style;
        std::string label; // "ao.raw  0 .. 1"
        bool refit = false; // painted with a kept range that a fit is to replace (see update)
    };
    // Brings the views of `names` up to date (others are left as they are), each painted at most
    // `maxWidth` pixels wide (0: the buffer's own size; a grid cell: the cell's).
    // keepRanges: fitted ranges stay those of the last fit (while the camera moves: the view does not
    // flicker as the range follows every frame, and nothing is read back). Without it a view that has
    // a range of the same style is first painted with that range and fitted on the next call: a fit
    // reads texels back, which waits for the GPU, so the first full-resolution frame after a drag
    // shows the new image at once and its ranges follow a frame later (fitsPending() until then).
    void update(Renderer& r, const ViewStyle& style, const std::vector<std::string>& names, int maxWidth = 0,
                bool keepRanges = false);
    // Whether a view still owes the fit of its range (the caller draws one more frame).
    bool fitsPending() const;
    // Forget every fitted range (a new scene: its ranges have nothing to do with the last one's).
    void forgetRanges();
    // The signed difference (a - b) * scale; repainted when either buffer or the scale changed.
    const View& difference(Renderer& r, const std::string& a, const std::string& b, float scale);
    const View* find(const std::string& name) const;

  private:
    std::map<std::string, View> views_;
    std::vector<std::string> shown_; // the names of the last update
    View diff_;
    std::string diffKey_;
    ViewPainter painter_;
};

} // namespace ssao
