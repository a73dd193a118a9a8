// Everything the interactive explorer knows and does, independent of GLFW: the renderer, settings,
// presets, camera, views, inspector, timings, hot reload. The window (window_app.cpp) feeds it
// input and a GL context; tests drive the same object through Dear ImGui on a headless one.
#pragma once
#include "renderer.h"
#include "settings/preset.h"
#include "settings/preset_store.h"
#include "view/buffer_views.h"
#include "view/camera_controller.h"
#include "view/live_reference.h"

#include <imgui.h>

#include <deque>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ssao {

struct AppOptions {
    std::string scene;     // empty: the preset's scene, else builtin:showcase
    std::string preset;    // name or path; empty = defaults
    std::string shaderDir; // empty = the installation's (or source tree's) shaders/
    std::string userPresetDir;
    float renderScale = 1.0f;       // render resolution relative to the view's pixels (0.25..1)
    float interactiveScale = 0.35f; // while the camera moves or a slider is dragged
    bool reference = true;          // trace the ray-traced reference of the view in the background
    std::optional<Projection> projection; // the camera's lens and depth mapping (default: the camera's)
    std::optional<DepthMode> depth;
    // Called from the reference's worker thread when it has news (the window posts an empty event
    // to wake its loop); may be empty.
    std::function<void()> wake;
};

enum class ViewMode { Grid, Single, Split };
enum class SplitKind { AoOnOff, Preset };

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
    void resetCamera();
    void selectSceneCamera(int index);

    // ---- Per frame ----
    // Builds the whole UI (call between ImGui::NewFrame and ImGui::Render); renders what changed.
    void drawUi();
    // Recompiles shaders if a file in shaders/ changed; keeps the last good programs on error.
    void pollShaderReload();
    // True while something is still changing (input, pending render, news from the reference's
    // threads); false = the app may sleep.
    bool busy() const { return busyFrames_ > 0 || reference_.hasNews(); }
    void poke(int frames = 3) { busyFrames_ = std::max(busyFrames_, frames); }
    // A camera move or slider drag: render at the interactive scale until input stops.
    void noteInteraction();
    bool interacting() const;

    // ---- State (read by the UI code and tests) ----
    Settings& settings() { return settings_; }
    const Preset& loadedPreset() const { return loaded_; }
    bool unsavedChanges() const;
    Renderer& renderer() { return *renderer_; }
    const Scene& scene() const { return *scene_; }
    const std::string& sceneSpec() const { return sceneSpec_; }
    const std::string& status() const { return status_; }
    bool statusIsError() const { return statusError_; }
    const std::string& shaderError() const { return shaderError_; }
    PresetStore& presets() { return store_; }
    CameraController& cameraController() { return camera_; }
    const FrameReport& lastReport() const { return lastReport_; }
    int framesRendered() const { return framesRendered_; } // frames in which any pass ran
    BufferViews& views() { return views_; }
    const LiveReference& reference() const { return reference_; }
    std::optional<Settings> settingsB(); // chain B of the split view, or nullopt

    // UI state
    ViewMode viewMode = ViewMode::Grid;
    std::string enlarged = "composite"; // buffer shown in Single mode
    SplitKind splitKind = SplitKind::AoOnOff;
    std::string splitPresetB = "crytek-sphere";
    std::string splitBuffer = "composite"; // what A | B compares: composite, ao.denoised or ao.raw
    bool splitDifference = false;          // show (A - B) * diffScale instead of the two halves
    float diffScale = 4.0f;
    float splitPosition = 0.5f; // divider, fraction of the width (dragged in the view)
    bool draggingDivider = false;
    float renderScale = 1.0f;
    float interactiveScale = 0.35f;
    ViewStyle style;
    bool showSamples = true;
    bool referenceOn = true; // the ray-traced reference and the error against it (AppOptions::reference)
    int referenceRays = 512; // rays per pixel the reference refines to (XeGTAO's 512)
    bool pinPixel = false;
    // Where the cursor is (or the pinned point), as uv of the view (y from the top; -1: nowhere):
    // resolution independent, so it stays put when the render size changes while moving.
    glm::vec2 hoverUv{-1.0f, -1.0f};
    glm::ivec2 hoverPixel() const; // the G-buffer pixel under hoverUv at the current render size
    int hoverBranch = 0;           // 1 when the cursor is over the B half of the split view
    std::string newPresetName;
    // Rectangles of widgets drawn last frame, by parameter key or action name (for tests).
    std::map<std::string, ImVec4> widgetRects;

    // Helpers for the UI code
    // Renders what changed at `viewW x viewH` view pixels times the current scale.
    void renderIfNeeded(int viewW, int viewH);
    bool renderedInteractive() const { return renderedInteractive_; }
    // The GPU taps at hoverPixel(); not re-run while the view moves (the last one is kept).
    const std::optional<PixelInspection>& inspection();
    // The radius at the centre of the view, recomputed when the depth or the settings change.
    const RadiusInfo& radiusInfo();
    // Decoded value(s) of a buffer at a G-buffer pixel (y from the top); `channels` of them. Cached
    // per buffer version and pixel: hovering does not read the GPU back every frame.
    std::vector<float> valueAt(const std::string& buffer, glm::ivec2 pixel);
    struct Timing {
        int width = 0, height = 0;
        std::map<std::string, std::deque<double>> ms; // pass → its last runs
        double average(const std::string& pass) const;
    };
    const Timing& timing(bool interactive) const { return interactive ? timingInteractive_ : timingFull_; }
    const std::deque<float>& frameMs() const { return frameMs_; }
    void noteFrameMs(float ms);
    void setStatus(const std::string& s, bool error);

  private:
    void resetCameraKeepingLens(Camera c);
    // Runs an action that returns its success message; on an exception shows the error instead.
    bool attempt(const char* what, const std::function<std::string()>& action);
    void adoptScene(Scene s, const std::string& spec, bool keepCamera);
    std::string radiusNote() const;

    AppOptions opts_;
    PresetStore store_;
    std::shared_ptr<const Scene> scene_; // shared with the reference's worker thread, never changed
    std::string sceneSpec_;
    Settings settings_;
    Preset loaded_;
    CameraController camera_;
    std::unique_ptr<Renderer> renderer_;
    BufferViews views_;
    FrameReport lastReport_;
    Timing timingFull_, timingInteractive_;
    std::deque<float> frameMs_;
    std::string status_, shaderError_;
    bool statusError_ = false;
    int busyFrames_ = 3;
    int framesRendered_ = 0;
    double lastInteraction_ = -1e9;
    bool renderedInteractive_ = false;
    std::filesystem::file_time_type shaderTime_{};
    std::string cachedSplitPreset_;
    std::optional<Settings> cachedSplitSettings_;
    // Inspector cache: replayed when the pixel, the branch or the AO changed.
    std::optional<PixelInspection> inspection_;
    glm::ivec2 inspectedPixel_{-1, -1};
    int inspectedBranch_ = -1;
    uint64_t inspectedVersion_ = 0;
    struct CachedValue {
        glm::ivec2 pixel{-1};
        uint64_t version = 0;
        unsigned generation = 0;
        std::vector<float> values;
    };
    std::map<std::string, CachedValue> values_;
    LiveReference reference_;
    RadiusInfo radius_;
    std::string radiusKey_;
    std::pair<int, int> fullSize_{0, 0}; // the render size when input is still
};

// UI pieces (ui_panels.cpp, ui_params.cpp, ui_views.cpp, ui_info.cpp).
void drawControlPanel(AppCore& app, ImVec2 pos, ImVec2 size);
void drawParameters(AppCore& app);
void drawMainView(AppCore& app, ImVec2 pos, ImVec2 size);
void drawInfoStrip(AppCore& app, ImVec2 pos, ImVec2 size); // timing and inspector, always visible
void drawReferenceSection(AppCore& app);                   // the "vs reference" block of the strip
std::string referenceTag(AppCore& app); // rays per pixel so far, for the labels of its views
// Why a reference.* buffer has nothing of this view to show yet (it reads 0 then); "" when it has,
// or for any other buffer. Views cover such a buffer with this text, the readout prints "-".
std::string referenceEmptyReason(AppCore& app, const std::string& buffer);
void rememberRect(AppCore& app, const std::string& key); // the last item's rectangle, for tests
void beginFixedWindow(const char* name, ImVec2 pos, ImVec2 size, ImGuiWindowFlags extra = 0);

} // namespace ssao
