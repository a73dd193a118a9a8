// Everything the interactive explorer knows and does, independent of GLFW: the renderer(s),
// settings, presets, camera, inspectors, timings, hot reload. The window (window_app.cpp) feeds
// it input and a GL context; tests drive the same object through Dear ImGui on a headless one.
#pragma once
#include "output/image.h"
#include "passes/buffer_views.h"
#include "renderer.h"
#include "settings/preset.h"
#include "ssao/sample_inspector.h"
#include "view/camera_controller.h"
#include "view/preset_store.h"

#include <imgui.h>

#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ssao {

struct AppOptions {
    std::string scene = "builtin:showcase";
    std::string preset;    // name or path; empty = defaults
    std::string shaderDir; // empty = the source tree's shaders/
    std::string userPresetDir;
    float renderScale = 1.0f; // render resolution relative to the view's pixels (0.25..1)
};

enum class ViewMode { Grid, Single, Split };
enum class SplitKind { Presets, AoOnOff };

class AppCore {
  public:
    explicit AppCore(const AppOptions& o); // needs a current GL 4.5 context; throws on bad initial input
    ~AppCore();

    // ---- Actions: each reports failure in the status line and keeps the current state ----
    bool openScene(const std::string& spec);
    bool openPreset(const std::string& nameOrPath);
    void dropFiles(const std::vector<std::string>& paths); // .gltf/.glb → scene, .json → preset
    bool savePreset(const std::string& name);
    bool renamePreset(const std::string& from, const std::string& to);
    bool deletePreset(const std::string& name);
    void setSettings(const Settings& s) { settings_ = s; }
    void resetCamera();
    void selectSceneCamera(int index);

    // ---- Per frame ----
    // Builds the whole UI (call between ImGui::NewFrame and ImGui::Render); renders what changed.
    void drawUi();
    // Recompiles shaders if a file in shaders/ changed; keeps the last good programs on error.
    void pollShaderReload();
    // True while something is still changing (input, pending render); false = the app may sleep.
    bool busy() const { return busyFrames_ > 0; }
    void poke(int frames = 3) { busyFrames_ = std::max(busyFrames_, frames); }

    // ---- State (read by the UI code and tests) ----
    Settings& settings() { return settings_; }
    const Preset& loadedPreset() const { return loaded_; }
    bool unsavedChanges() const;
    Renderer& renderer() { return *rendererA_; }
    Renderer* rendererB() { return rendererB_.get(); }
    const Scene& scene() const { return scene_; }
    const std::string& status() const { return status_; }
    bool statusIsError() const { return statusError_; }
    const std::string& shaderError() const { return shaderError_; }
    PresetStore& presets() { return store_; }
    CameraController& cameraController() { return camera_; }
    const FrameReport& lastReport() const { return lastReport_; }
    int framesRendered() const { return framesRendered_; } // frames in which any pass ran

    // UI state
    ViewMode viewMode = ViewMode::Grid;
    BufferId enlarged = BufferId::Composite;
    SplitKind splitKind = SplitKind::AoOnOff;
    std::string splitPresetB = "crytek-sphere";
    float splitPosition = 0.5f;
    float renderScale = 1.0f;
    bool showSamples = true;
    bool pinPixel = false;
    glm::ivec2 hoverPixel{-1, -1};
    std::string newPresetName;
    // Rectangles of widgets drawn last frame, by parameter key or action name (for tests).
    std::map<std::string, ImVec4> widgetRects;

    // Helpers for the UI code
    void renderIfNeeded(int width, int height);
    const gl::Texture2D& viewTexture(BufferId id) const { return views_.view(id); }
    const PixelInspection& inspection();
    glm::vec4 texelOf(BufferId id, int x, int y);
    struct PassTiming {
        std::deque<double> ms; // last runs of the pass
        double average() const;
    };
    const std::map<std::string, PassTiming>& timings() const { return timings_; }
    const std::deque<float>& frameMs() const { return frameMs_; }
    void noteFrameMs(float ms);
    void setStatus(const std::string& s, bool error);

  private:
    // Runs an action that returns its success message; on an exception shows the error instead.
    bool attempt(const char* what, const std::function<std::string()>& action);
    void adoptScene(Scene s, bool keepCamera);
    Settings settingsB();

    AppOptions opts_;
    std::string cachedSplitPreset_;
    Settings cachedSplitSettings_;
    PresetStore store_;
    Scene scene_;
    Settings settings_;
    Preset loaded_;
    CameraController camera_;
    std::unique_ptr<Renderer> rendererA_, rendererB_;
    BufferViews views_;
    FrameReport lastReport_;
    std::map<std::string, PassTiming> timings_;
    std::deque<float> frameMs_;
    std::string status_, shaderError_;
    bool statusError_ = false;
    int busyFrames_ = 3;
    int framesRendered_ = 0;
    std::filesystem::file_time_type shaderTime_{};
    // Sample inspector cache
    Image cpuPos_, cpuNormal_, cpuDepth_;
    unsigned cpuVersion_ = ~0u;
    PixelInspection inspection_;
    glm::ivec2 inspectedPixel_{-1, -1};
    Settings inspectedSettings_;
    bool inspectionStale_ = true;
};

// UI pieces (ui_panels.cpp, ui_views.cpp).
void drawControlPanel(AppCore& app, ImVec2 pos, ImVec2 size);
void drawMainView(AppCore& app, ImVec2 pos, ImVec2 size);

} // namespace ssao
