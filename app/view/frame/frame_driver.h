// The explorer's frames: the renderer, the render size (reduced while the camera moves or a slider
// is dragged, full a quarter second after input stops), the background reference and its error,
// per-pass timings and the frame-time plot, shader hot reload, and whether the app may sleep.
#pragma once
#include "metrics/radius_check.h"
#include "renderer.h"
#include "view/frame/buffer_views.h"
#include "view/live/live_reference.h"
#include "view/frame/view_state.h"

#include <atomic>
#include <deque>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace ssao {

class FrameDriver {
  public:
    FrameDriver(const std::string& shaderDir, float renderScale, float interactiveScale, bool reference,
                const std::function<void()>& wake);

    // What one frame is drawn from.
    struct Input {
        const Camera& camera;
        const Settings& settings;
        std::optional<Settings> settingsB; // chain B of the split view
        std::shared_ptr<const Scene> scene;
    };
    // Renders what changed at `viewW x viewH` view pixels times the current scale, paints the
    // buffers the view shows and keeps the reference going.
    void render(const Input& in, const ViewState& view, int viewW, int viewH);
    void sceneChanged(const Scene& s); // new scene: timings start over

    Renderer& renderer() { return *renderer_; }
    const Renderer& renderer() const { return *renderer_; }
    BufferViews& views() { return views_; }
    const BufferViews& views() const { return views_; }
    const LiveReference& reference() const { return reference_; }
    const FrameReport& lastReport() const { return lastReport_; }
    int framesRendered() const { return framesRendered_; } // frames in which any pass ran
    bool renderedInteractive() const { return renderedInteractive_; }
    std::pair<int, int> fullSize() const { return fullSize_; } // the render size when input is still
    // The radius at the centre of the view, recomputed when the depth or the settings change.
    const RadiusInfo& radiusInfo();
    // The scene radius against what the view spans (metrics/radius_check.h), from the depth of the
    // last full-size still frame (read back once per new depth; while input moves, the last one).
    const ViewRadiusCheck& viewRadius();

    // Idle costs nothing: true while something is still changing (input, a pending render, news from
    // the reference's threads); false = the app may sleep.
    bool busy() const { return busyFrames_ > 0 || reference_.hasNews() || news_; }
    // Another background thread has news (any thread may call it); taken by the UI frame that reads it.
    void postNews() { news_ = true; }
    bool takeNews() { return news_.exchange(false); }
    void keepAwake(int frames = 3) { busyFrames_ = std::max(busyFrames_, frames); }
    void endUiFrame() {
        if (busyFrames_ > 0) --busyFrames_;
    }
    // A camera move or slider drag: render at the interactive scale until input stops.
    void noteInteraction();
    bool interacting() const;

    // Recompiles shaders if a file in shaders/ changed; keeps the last good programs on error.
    void pollShaderReload();
    const std::string& shaderError() const { return shaderError_; }
    void setShaderError(const std::string& e) { shaderError_ = e; }
    bool reloadedShaders() { return std::exchange(reloaded_, false); }

    struct Timing {
        int width = 0, height = 0;
        std::map<std::string, std::deque<double>> ms; // pass → its last runs
        double average(const std::string& pass) const;
    };
    const Timing& timing(bool interactive) const { return interactive ? timingInteractive_ : timingFull_; }
    const std::deque<float>& frameMs() const { return frameMs_; }
    void noteFrameMs(float ms);

    float renderScale = 1.0f;
    float interactiveScale = 0.35f;
    bool referenceOn = true; // the ray-traced reference and the error against it
    int referenceRays = 512; // rays per pixel the reference refines to (XeGTAO's 512)

  private:
    void recordTimings(const FrameReport& rep, bool interactive, int w, int h);
    void paintViews(const ViewState& view);

    std::unique_ptr<Renderer> renderer_;
    BufferViews views_;
    LiveReference reference_;
    FrameReport lastReport_;
    Timing timingFull_, timingInteractive_;
    std::deque<float> frameMs_;
    std::string shaderError_;
    bool reloaded_ = false;
    int busyFrames_ = 3;
    std::atomic<bool> news_{false};
    int framesRendered_ = 0;
    double lastInteraction_ = -1e9;
    bool renderedInteractive_ = false;
    std::filesystem::file_time_type shaderTime_{};
    RadiusInfo radius_;
    std::string radiusKey_;
    ViewRadiusCheck viewRadius_;
    std::string viewRadiusKey_;
    std::pair<int, int> fullSize_{0, 0};
};

} // namespace ssao
