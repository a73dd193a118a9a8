// Drives the real app UI (AppCore + Dear ImGui + the OpenGL3 backend) on a headless EGL context:
// frames are drawn into an offscreen framebuffer, input is injected through ImGuiIO.
#pragma once
#include "gl/resources.h"
#include "view/app/app_core.h"

#include <memory>
#include <string>

namespace ssaotest {

class UiDriver {
  public:
    UiDriver(const ssao::AppOptions& o, int width = 1600, int height = 2600);
    ~UiDriver();

    ssao::AppCore& app() { return *app_; }
    // One frame with the mouse at (x, y), button 0 `down`.
    void frame(float x = -1, float y = -1, bool down = false);
    void frames(int n) {
        for (int i = 0; i < n; ++i)
            frame(mx_, my_, false);
    }
    // Press and release at the centre of a widget recorded under `key` (or at a fraction of its width).
    void click(const std::string& key, float fx = 0.5f, bool ctrl = false);
    void clickAt(float x, float y, bool ctrl = false, bool shift = false);
    void drag(float x0, float y0, float x1, float y1, int steps = 5);
    void type(const std::string& text);
    void pressEnter();
    void wheel(float x, float y, float steps);
    // Frames with no input until the app renders at full resolution again (input settled).
    void settle();
    bool has(const std::string& key) const { return app_->view().widgetRects.count(key) != 0; }
    ImVec4 rect(const std::string& key) const;
    // The last UI frame as PNG (to look at what a test saw).
    void save(const std::string& path) const;

  private:
    int w_, h_;
    float mx_ = -1, my_ = -1;
    std::unique_ptr<ssao::AppCore> app_;
    ssao::gl::RenderTarget target_;
};

} // namespace ssaotest
