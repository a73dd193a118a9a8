// The explorer's panels: each is given the state it draws (const, gathered by AppCore) and appends
// what the person asked for to a UiActions (ui_actions.h), which AppCore applies after it.
#pragma once
#include "settings/preset.h"
#include "settings/preset_store.h"
#include "view/frame/camera_controller.h"
#include "view/frame/frame_driver.h"
#include "view/frame/front_panel.h"
#include "view/frame/inspector.h"
#include "view/panels/ui_actions.h"
#include "view/frame/view_state.h"

#include <imgui.h>

#include <optional>
#include <string>
#include <vector>

namespace ssao {

// The top of the control panel (ui_panels.cpp): its window, the status and the tab strip; the tab
// chosen is drawn after it, then ImGui::End closes the window.
struct PanelHeader {
    const std::string& status;
    bool statusIsError;
    const std::string& shaderError;
    int tab; // ViewState::panelTab
};
void beginControlPanel(const PanelHeader& in, ImVec2 pos, ImVec2 size, UiActions& out);

// The Parameters tab (ui_params.cpp), generated from the parameter table.
struct ParamsView {
    const Settings& settings;
    const Preset& loaded;              // what * and R compare with
    const RadiusInfo* radius;          // null before the first frame
    const ViewRadiusCheck* viewRadius; // null before the first frame
};
void drawParameters(const ParamsView& in, UiActions& out);

// The Scene & camera tab (ui_panels.cpp).
struct SceneView {
    const Scene& scene;
    const CameraController& camera;
    const Camera& rendered; // the camera as rendered (fitted near/far)
};
void drawSceneTab(const SceneView& in, UiActions& out);

// The Presets tab (ui_panels.cpp).
struct PresetsView {
    const PresetStore& store;
    const Preset& loaded;
    bool unsaved;
    const std::vector<std::string>& descriptions; // of store.entries(), in their order
    const std::string& newName;                   // ViewState::newPresetName
};
void drawPresetsTab(const PresetsView& in, UiActions& out);

// The Front tab (ui_front.cpp) and its web engines (ui_engines.cpp).
struct FrontTabView {
    const FrontPanel& front;
    const Settings& settings;
    const PresetStore& store;
    const std::string& engineFile; // ViewState::engineFile
};
void drawFrontTab(const FrontTabView& in, UiActions& out);
void drawEngineSection(const FrontTabView& in, FrontPanel::Axis axis, UiActions& out);

// The main view (ui_views.cpp), in the order AppCore calls it: the toolbar (then the frame is
// rendered), the mouse and keys over the images (then the hover is known), the images.
struct ToolbarView {
    const ViewState& view;
    const FrameDriver& frames;
    const PresetStore& store;
};
void drawViewToolbar(const ToolbarView& in, UiActions& out);
struct ViewArea {
    const ViewState& view;
    const Renderer& renderer;
    ImVec2 origin, avail; // the view's rectangle under the toolbar
};
void drawViewInput(const ViewArea& area, CameraController::Mode cameraMode, UiActions& out);
struct ViewImages {
    ViewMode mode; // as the input phase found it: a grid cell clicked shows enlarged from the next frame
    const FrameDriver& frames;
    glm::ivec2 hoverPixel;
    const std::optional<PixelInspection>* inspection; // null when the view draws no samples
    const gl::Texture2D* imageB;                      // split B as an image (ViewState::imageB)
    std::string whyNoImageB;
    const BufferViews::View* difference; // A - B, when the split view shows it
};
void drawViewImages(const ViewArea& area, const ViewImages& in, UiActions& out);

// Each panel gets the parts it draws: the strip under the image reads the frames and the inspector.
void drawInfoStrip(FrameDriver& frames, Inspector& inspector, ViewState& view, ImVec2 pos,
                   ImVec2 size);                             // timing and inspector, always visible
void drawReferenceSection(FrameDriver& frames, ViewState& view); // the "vs reference" block of the strip
std::string referenceTag(const FrameDriver& frames); // rays per pixel so far, for the labels of its views
// Why a reference.* buffer has nothing of this view to show yet (it reads 0 then); "" when it has,
// or for any other buffer. Views cover such a buffer with this text, the readout prints "-".
std::string referenceEmptyReason(const FrameDriver& frames, const std::string& buffer);
void rememberRect(ViewState& view, const std::string& key); // the last item's rectangle, for tests
void rememberRect(UiActions& out, const std::string& key);
// Text in the current colour wrapped at spaces only (ImGui's wrap splits "0.8617" after "0."), as
// one item (a group); hovering it shows the whole text when a word alone overruns the width.
void wrappedText(const std::string& text, bool disabled = false);
// A window of the fixed layout (the three tile the screen): drawn without a background of its own,
// the clear beneath it (clearUiBackground) is its background.
void beginFixedWindow(const char* name, ImVec2 pos, ImVec2 size, ImGuiWindowFlags extra = 0);
// Clears the bound framebuffer to the style's window colour, opaque: the fixed windows' background.
void clearUiBackground();

} // namespace ssao
