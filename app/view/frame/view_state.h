// What the person chose to look at in the explorer, as plain state: the view mode, the enlarged
// buffer, the split view's settings, the display style, the cursor and the pinned pixel. No GL,
// no renderer: the frame driver and the inspector read it, the panels edit it.
#pragma once
#include "display/display_range.h"

#include <imgui.h>

#include <glm/glm.hpp>

#include <map>
#include <string>

namespace ssao {

enum class ViewMode { Grid, Single, Split };
enum class SplitKind { AoOnOff, Preset, Candidate }; // Candidate: a point picked on the front

struct ViewState {
    ViewMode mode = ViewMode::Grid;
    std::string enlarged = "composite"; // buffer shown in Single mode
    SplitKind splitKind = SplitKind::AoOnOff;
    std::string splitPresetB = "crytek-sphere";
    std::string splitCandidateB; // the label of the front point shown as B (SplitKind::Candidate)
    // B is that point's image, not a chain the renderer draws: a web engine's AO frame.
    bool splitCandidateImage = false;
    bool imageB() const { return mode == ViewMode::Split && splitKind == SplitKind::Candidate && splitCandidateImage; }
    std::string splitBuffer = "composite"; // what A | B compares: composite, ao.denoised or ao.raw
    bool splitDifference = false;          // show (A - B) * diffScale instead of the two halves
    float diffScale = 4.0f;
    float splitPosition = 0.5f; // divider, fraction of the width (dragged in the view)
    bool draggingDivider = false;
    ViewStyle style;
    bool showSamples = true; // the inspector's taps over the enlarged view
    bool pinPixel = false;
    // Where the cursor is (or the pinned point), as uv of the view (y from the top; -1: nowhere):
    // resolution independent, so it stays put when the render size changes while moving.
    glm::vec2 hoverUv{-1.0f, -1.0f};
    float viewWidth = 1000.0f;  // pixels of the main view (orbit speed: its width = half a turn)
    int gridCellPx = 0;         // width of a grid cell's image in framebuffer pixels (0: not drawn yet)
    bool cursorOnImage = false; // the cursor was over the image last frame (the readout wants every buffer)
    int hoverChain = 0; // 1 when the cursor was last over the B half of the split view
    // The cursor is on chain B now: the split view shows B there (not the grid, not A - B).
    bool cursorOnB() const { return hoverChain && mode == ViewMode::Split && !splitDifference && !imageB(); }
    std::string newPresetName;
    std::string engineFile; // the Front tab's "tuned settings" path field
    int panelTab = 0; // the control panel's tab: Parameters, Scene & camera, Presets, Front
    // Rectangles of widgets drawn last frame, by parameter key or action name (for tests).
    std::map<std::string, ImVec4> widgetRects;
};

} // namespace ssao
