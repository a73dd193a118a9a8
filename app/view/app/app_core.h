// Everything the interactive explorer knows and does, independent of GLFW. The window
// (window_app.cpp) feeds it input and a GL context; tests drive the same object through Dear ImGui
// on a headless one.
#pragma once
#include "renderer.h"
#include "settings/preset.h"
#include "settings/preset_store.h"
#include "view/frame/camera_controller.h"
#include "view/frame/frame_driver.h"
#include "view/frame/front_panel.h"
#include "view/frame/image_texture.h"
#include "view/frame/inspector.h"
#include "view/live/technique_watch.h"
#include "view/panels/ui_actions.h"
#include "view/panels/ui_panels.h"
#include "view/frame/view_state.h"

#include <imgui.h>

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
    // The folder of the user techniques registered at start (app/cli/user_techniques.h): the
    // explorer watches its NAME.ao.glsl files and adopts each new version that passes a probe.
    std::string techniqueDir;
    std::string probeProgram; // the ssaolab binary the watch probes with ("" = this program)
    float renderScale = 1.0f;       // render resolution relative to the view's pixels (0.25..1)
    float interactiveScale = 0.35f; // while the camera moves or a slider is dragged
    bool reference = true;          // trace the ray-traced reference of the view in the background
    std::optional<Projection> projection; // the camera's lens and depth mapping (default: the camera's)
    std::optional<DepthMode> depth;
    std::string engineModules; // the web engines' npm packages ("" = the build folder's peers/node_modules)
    // Called from the reference's worker thread when it has news (the window posts an empty event
    // to wake its loop); may be empty.
    std::function<void()> wake;
};

// The explorer's core: the scene, the settings and presets, the camera and the status line, with
// the actions on them; and its three parts - what the person looks at (ViewState), the frames
// (FrameDriver: renderer, reference, timings) and what the cursor points at (Inspector).
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
    // BLEND/transmissive surfaces skipped or drawn as opaque (scene.h Transparent): the scene is
    // loaded again with the camera kept; on failure the mode and the scene stay as they were.
    bool setTransparent(Transparent mode);
    // A point of the front: its settings become the current ones (with the user's radius), or B of
    // the split view, so A | B compares it with the current setting. A web engine's point has no
    // ssaolab settings: B is its AO frame (an image), and applying it compares it.
    void applyCandidate(const Candidate& c);
    void compareCandidate(const Candidate& c);
    // Split B as an image (ViewState::imageB): the engine point's AO frame of this view as a texture
    // (top row at v = 0), or null with why there is none yet.
    const gl::Texture2D* splitImageB(std::string& why);
    // The world radius that spans of this view what the scene mode spans of a framed scene
    // (metrics/radius_check.h): when the scene radius is far larger than the view.
    void useViewRadius();

    // ---- Per frame ----
    // Builds the whole UI (call between ImGui::NewFrame and ImGui::Render); renders what changed.
    void drawUi();
    // Renders what changed at `viewW x viewH` view pixels (the main view calls it).
    void renderIfNeeded(int viewW, int viewH);
    // Recompiles shaders if a file in shaders/ changed; keeps the last good programs on error. And
    // adopts each new version of a user technique that passed its probe (technique_watch.h).
    void pollShaderReload();

    // ---- The parts ----
    // The panels (ui_*.cpp) never call these: AppCore gives each what it draws (ui_panels.h) and
    // applies the actions it returns. The window and the tests read and drive the parts through them.
    ViewState& view() { return view_; }
    FrameDriver& frames() { return frames_; }
    FrontPanel& front() { return front_; }
    Renderer& renderer() { return frames_.renderer(); }

    // ---- State ----
    Settings& settings() { return settings_; }
    const Preset& loadedPreset() const { return loaded_; }
    // The preset file's "description" (read once per file; a file that no longer reads says why).
    const std::string& presetDescription(const PresetEntry& e);
    bool unsavedChanges() const;
    const Scene& scene() const { return *scene_; }
    const std::string& sceneSpec() const { return sceneSpec_; }
    const std::string& status() const { return status_; }
    // What --scene or --preset got wrong at start ("" when both loaded): the window shows it, the
    // caller prints it on stderr and exits non-zero, so a script learns of it too.
    const std::string& startupError() const { return startupError_; }
    bool statusIsError() const { return statusError_; }
    // How many versions of user techniques the watch has adopted or refused so far (tests wait on it).
    unsigned techniqueVerdicts() const { return techniqueVerdicts_; }
    const PresetStore& presets() const { return store_; }
    CameraController& cameraController() { return camera_; }
    std::optional<Settings> settingsB(); // chain B of the split view, or nullopt
    // The GPU taps at the hovered pixel (Inspector::inspection on this app's renderer and view).
    const std::optional<PixelInspection>& inspection();
    std::vector<float> valueAt(const std::string& buffer, glm::ivec2 pixel) {
        return inspector_.valueAt(frames_.renderer(), buffer, pixel);
    }
    glm::ivec2 hoverPixel() const { return Inspector::hoverPixel(frames_.renderer(), view_); }
    void setStatus(const std::string& s, bool error);

    // Carries out what a panel asked for (app_actions.cpp), and takes its widgets' rectangles.
    void apply(const UiAction& a);
    void apply(const UiActions& actions);

  private:
    // The panels, each given what it draws, their actions applied after each (app_actions.cpp).
    void drawControlPanel(ImVec2 pos, ImVec2 size);
    void drawMainView(ImVec2 pos, ImVec2 size);
    struct Applier; // one overload per action (app_actions.cpp)
    void resetCameraKeepingLens(Camera c);
    // Runs an action that returns its success message; on an exception shows the error instead.
    bool attempt(const char* what, const std::function<std::string()>& action);
    void adoptScene(Scene s, const std::string& spec, bool keepCamera);
    std::string radiusNote() const;
    // Says once, in the status, when a view's scene radius is far past what it spans.
    void noteViewRadius();

    AppOptions opts_;
    PresetStore store_;
    std::shared_ptr<const Scene> scene_; // shared with the reference's worker thread, never changed
    std::string sceneSpec_;
    Settings settings_;
    Preset loaded_;
    CameraController camera_;
    ViewState view_;
    FrameDriver frames_;
    Inspector inspector_;
    std::string status_;
    std::string startupError_;
    bool statusError_ = false;
    std::string cachedSplitPreset_;
    std::optional<Settings> cachedSplitSettings_;
    std::optional<Settings> splitCandidate_; // B when SplitKind::Candidate
    ImageTexture splitImage_;                // B when it is an engine's frame
    std::string renderedTechnique_; // of the last render (a change compiles shaders: announced first)
    bool announced_ = false;
    bool radiusHinted_ = false; // the status says the radius is too large for the view
    std::map<std::string, std::string> descriptions_; // preset path -> its description
    FrontPanel front_;
    TechniqueWatch techniques_;
    unsigned techniqueVerdicts_ = 0;
};

} // namespace ssao
