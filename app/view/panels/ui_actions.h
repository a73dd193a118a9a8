// What the explorer's panels ask for: each panel draws the state it is given (const) and appends
// these to a UiActions; AppCore::apply (app_actions.cpp) carries them out after the panel, in one
// place, so no panel changes the app's state behind its back.
#pragma once
#include "front/candidates.h"
#include "scene/scene.h"
#include "view/frame/camera_controller.h"
#include "view/frame/view_state.h"

#include <imgui.h>

#include <glm/glm.hpp>

#include <map>
#include <string>
#include <variant>
#include <vector>

namespace ssao {
namespace act {

// Scenes, presets, the camera and the status (AppCore's actions of the same names).
struct OpenScene { std::string spec; };
struct SetTransparent { Transparent mode; };
struct OpenPreset { std::string name; };
struct SavePreset { std::string name; };
struct RenamePreset { std::string from, to; };
struct DeletePreset { std::string name; };
struct ResetCamera {};
struct SelectSceneCamera { int index = 0; };
struct SetStatus { std::string text; bool error = false; };
// One parameter of the settings, by its key in the parameter table.
struct SetParam { std::string key; double value = 0; };
struct UseViewRadius {};
struct ApplyCandidate { Candidate candidate; };
struct CompareCandidate { Candidate candidate; };

// The camera: its mode and lens, and the moves of the mouse and keys over the image.
struct SetCameraMode { CameraController::Mode mode; };
struct SetClip { ClipMode clip; };
struct SetProjection { Projection projection; };
struct SetDepth { DepthMode depth; };
struct Orbit { float dx = 0, dy = 0, viewWidth = 0; };
struct Pan { float dx = 0, dy = 0, viewportHeight = 0; };
struct Zoom { float steps = 0; };
struct Fly { glm::vec3 rightUpForward{0.0f}; float amount = 0; };

// What the main view shows (ViewState) and at what resolution.
struct SelectView { ViewMode mode; std::string enlarged; };
struct SetSplit { SplitKind kind; std::string presetB, buffer; bool difference = false; float diffScale = 4.0f; };
struct SetDisplay { float renderScale = 1, interactiveScale = 0.35f; ViewStyle style; };
struct SetDivider { bool dragging = false; float position = 0.5f; };
struct SetHover { glm::vec2 uv{-1.0f}; int chain = 0; };
struct CursorOnImage {};
struct TogglePin {};
struct SetGridCellPx { int px = 0; };
struct SelectTab { int tab = 0; };
struct SetNewPresetName { std::string name; };

// The Front tab and its web engines.
struct SetFrontAxis { bool motion = false; };
struct SetFrontPaused { bool paused = false; };
struct SetFrontBudget { double budgetMs = 0, maxError = 0; };
struct SetEnginesOn { bool on = false; };
struct RescanEngines {};
struct SetEngineFile { std::string path; };
struct AddEngineFile { std::string path; };

// Frames: draw a few more (something changed), or render reduced while a slider is dragged.
struct KeepAwake {};
struct NoteInteraction {};

} // namespace act

using UiAction =
    std::variant<act::OpenScene, act::SetTransparent, act::OpenPreset, act::SavePreset, act::RenamePreset,
                 act::DeletePreset, act::ResetCamera, act::SelectSceneCamera, act::SetStatus, act::SetParam,
                 act::UseViewRadius, act::ApplyCandidate, act::CompareCandidate, act::SetCameraMode, act::SetClip,
                 act::SetProjection, act::SetDepth, act::Orbit, act::Pan, act::Zoom, act::Fly, act::SelectView,
                 act::SetSplit, act::SetDisplay, act::SetDivider, act::SetHover, act::CursorOnImage, act::TogglePin,
                 act::SetGridCellPx, act::SelectTab, act::SetNewPresetName, act::SetFrontAxis, act::SetFrontPaused,
                 act::SetFrontBudget, act::SetEnginesOn, act::RescanEngines, act::SetEngineFile, act::AddEngineFile,
                 act::KeepAwake, act::NoteInteraction>;

// What a panel hands back: its actions in the order asked, and the rectangles of the widgets it drew
// (by parameter key or action name; tests click them through ViewState::widgetRects).
struct UiActions {
    std::vector<UiAction> list;
    std::map<std::string, ImVec4> rects;
    void push(UiAction a) { list.push_back(std::move(a)); }
};

} // namespace ssao
