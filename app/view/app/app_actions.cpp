// AppCore's side of the UI: it gives each panel what it draws, then carries out the actions the
// panel returns (ui_actions.h), panel by panel, so the next panel (and the render in the main view)
// sees them in the same frame.
#include "settings/params.h"
#include "view/app/app_core.h"

#include <algorithm>
#include <variant>

namespace ssao {

struct AppCore::Applier {
    AppCore& app;
    void operator()(const act::OpenScene& a) { app.openScene(a.spec); }
    void operator()(const act::SetTransparent& a) { app.setTransparent(a.mode); }
    void operator()(const act::OpenPreset& a) { app.openPreset(a.name); }
    void operator()(const act::SavePreset& a) { app.savePreset(a.name); }
    void operator()(const act::RenamePreset& a) { app.renamePreset(a.from, a.to); }
    void operator()(const act::DeletePreset& a) { app.deletePreset(a.name); }
    void operator()(const act::ResetCamera&) { app.resetCamera(); }
    void operator()(const act::SelectSceneCamera& a) { app.selectSceneCamera(a.index); }
    void operator()(const act::SetStatus& a) { app.setStatus(a.text, a.error); }
    void operator()(const act::SetParam& a) {
        if (const Param* p = findParam(a.key)) p->set(app.settings_, a.value);
    }
    void operator()(const act::UseViewRadius&) { app.useViewRadius(); }
    void operator()(const act::ApplyCandidate& a) { app.applyCandidate(a.candidate); }
    void operator()(const act::CompareCandidate& a) { app.compareCandidate(a.candidate); }
    void operator()(const act::SetCameraMode& a) { app.camera_.setMode(a.mode); }
    void operator()(const act::SetClip& a) { app.camera_.setClip(a.clip); }
    void operator()(const act::SetProjection& a) { app.camera_.setProjection(a.projection); }
    void operator()(const act::SetDepth& a) { app.camera_.setDepth(a.depth); }
    void operator()(const act::Orbit& a) { app.camera_.rotate(a.dx, a.dy, a.viewWidth); }
    void operator()(const act::Pan& a) { app.camera_.pan(a.dx, a.dy, a.viewportHeight); }
    void operator()(const act::Zoom& a) { app.camera_.zoom(a.steps); }
    void operator()(const act::Fly& a) { app.camera_.move(a.rightUpForward, a.amount); }
    void operator()(const act::SelectView& a) {
        app.view_.mode = a.mode;
        app.view_.enlarged = a.enlarged;
        app.frames_.keepAwake();
    }
    void operator()(const act::SetSplit& a) {
        ViewState& v = app.view_;
        v.splitKind = a.kind, v.splitPresetB = a.presetB, v.splitBuffer = a.buffer;
        v.splitDifference = a.difference, v.diffScale = a.diffScale;
        app.frames_.keepAwake();
    }
    void operator()(const act::SetDisplay& a) {
        app.frames_.renderScale = a.renderScale;
        app.frames_.interactiveScale = a.interactiveScale;
        app.view_.style = a.style;
        app.frames_.keepAwake();
    }
    void operator()(const act::SetDivider& a) {
        app.view_.draggingDivider = a.dragging;
        app.view_.splitPosition = a.position;
    }
    void operator()(const act::SetHover& a) {
        app.view_.hoverUv = a.uv;
        app.view_.hoverChain = a.chain;
    }
    void operator()(const act::CursorOnImage&) { app.view_.cursorOnImage = true; }
    void operator()(const act::TogglePin&) { app.view_.pinPixel = !app.view_.pinPixel; }
    void operator()(const act::SetGridCellPx& a) { app.view_.gridCellPx = a.px; }
    void operator()(const act::SelectTab& a) { app.view_.panelTab = a.tab; }
    void operator()(const act::SetNewPresetName& a) { app.view_.newPresetName = a.name; }
    void operator()(const act::SetFrontAxis& a) {
        app.front_.axis = a.motion ? FrontPanel::Axis::Motion : FrontPanel::Axis::Still;
    }
    void operator()(const act::SetFrontPaused& a) { app.front_.paused = a.paused; }
    void operator()(const act::SetFrontBudget& a) {
        app.front_.budgetMs = a.budgetMs;
        app.front_.maxError = a.maxError;
    }
    void operator()(const act::SetEnginesOn& a) { app.front_.engines().enabled = a.on; }
    void operator()(const act::RescanEngines&) { app.front_.engines().rescan(); }
    void operator()(const act::SetEngineFile& a) { app.view_.engineFile = a.path; }
    void operator()(const act::AddEngineFile& a) {
        const std::string error = app.front_.engines().addFile(a.path);
        app.setStatus(error.empty() ? "engines: added " + a.path : error, !error.empty());
        if (error.empty()) app.view_.engineFile.clear();
    }
    void operator()(const act::KeepAwake&) { app.frames_.keepAwake(); }
    void operator()(const act::NoteInteraction&) { app.frames_.noteInteraction(); }
};

void AppCore::apply(const UiAction& a) {
    std::visit(Applier{*this}, a);
}

void AppCore::apply(const UiActions& actions) {
    for (const auto& [key, r] : actions.rects)
        view_.widgetRects[key] = r;
    for (const UiAction& a : actions.list)
        apply(a);
}

void AppCore::drawUi() {
    const ImGuiIO& io = ImGui::GetIO();
    const float panelWidth = std::min(420.0f * io.FontGlobalScale, io.DisplaySize.x * 0.4f);
    const float infoHeight = std::min(230.0f * io.FontGlobalScale, io.DisplaySize.y * 0.35f);
    drawControlPanel(ImVec2(0, 0), ImVec2(panelWidth, io.DisplaySize.y));
    drawMainView(ImVec2(panelWidth, 0), ImVec2(io.DisplaySize.x - panelWidth, io.DisplaySize.y - infoHeight));
    drawInfoStrip(frames_, inspector_, view_, ImVec2(panelWidth, io.DisplaySize.y - infoHeight),
                  ImVec2(io.DisplaySize.x - panelWidth, infoHeight));
    try { // after the frame on screen: the front's slice of work for this frame
        front_.update(settings_, store_, frames_, scene_, sceneSpec_);
    } catch (const std::exception& e) {
        front_.paused = true;
        setStatus(std::string("front panel: ") + e.what(), true);
    }
    frames_.endUiFrame();
}

void AppCore::drawControlPanel(ImVec2 pos, ImVec2 size) {
    UiActions header;
    beginControlPanel({status_, statusError_, frames_.shaderError(), view_.panelTab}, pos, size, header);
    apply(header); // the tab clicked is drawn this frame
    UiActions tab;
    switch (view_.panelTab) {
    case 0: {
        const bool drawn = frames_.renderer().width() > 0; // the radius is known after the first frame
        drawParameters({settings_, loaded_, drawn ? &frames_.radiusInfo() : nullptr,
                        drawn ? &frames_.viewRadius() : nullptr},
                       tab);
        break;
    }
    case 1: drawSceneTab({*scene_, camera_, frames_.renderer().camera()}, tab); break;
    case 2: {
        std::vector<std::string> descriptions;
        for (const PresetEntry& e : store_.entries())
            descriptions.push_back(presetDescription(e));
        drawPresetsTab({store_, loaded_, unsavedChanges(), descriptions, view_.newPresetName}, tab);
        break;
    }
    default:
        front_.active = true; // measured in the background from now on
        drawFrontTab({front_, settings_, store_, view_.engineFile}, tab);
        break;
    }
    ImGui::End();
    apply(tab); // a scene opened here replaces the one the tab was drawn from only now
}

void AppCore::drawMainView(ImVec2 pos, ImVec2 size) {
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4, 4));
    beginFixedWindow("view", pos, size,
                     ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    UiActions toolbar;
    drawViewToolbar({view_, frames_, store_}, toolbar);
    apply(toolbar); // the render below shows the mode and split chosen
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    view_.viewWidth = avail.x; // a drag across the whole view turns half a turn, in a grid cell too
    // Render at the size the enlarged view shows (1:1 pixels, framebuffer scale included).
    const ImVec2 fbScale = ImGui::GetIO().DisplayFramebufferScale;
    renderIfNeeded(int(avail.x * fbScale.x), int(avail.y * fbScale.y));
    view_.cursorOnImage = false; // set again by the image the cursor is over
    const ViewArea area{view_, frames_.renderer(), origin, avail};
    UiActions input;
    drawViewInput(area, camera_.mode(), input);
    const ViewMode mode = view_.mode;
    apply(input); // the samples below are those under the cursor now
    ViewImages in{mode, frames_, hoverPixel(), nullptr, nullptr, "", nullptr};
    const bool chains = mode == ViewMode::Split && !view_.imageB() && !view_.splitDifference;
    if ((mode == ViewMode::Single || chains) && view_.showSamples && in.hoverPixel.x >= 0)
        in.inspection = &inspection();
    if (view_.imageB())
        in.imageB = splitImageB(in.whyNoImageB);
    else if (mode == ViewMode::Split && view_.splitDifference &&
             frames_.renderer().graph().find("b." + view_.splitBuffer))
        in.difference = &frames_.views().difference(frames_.renderer(), view_.splitBuffer, "b." + view_.splitBuffer,
                                                     view_.diffScale);
    UiActions images;
    drawViewImages(area, in, images);
    apply(images);
    ImGui::End();
    ImGui::PopStyleVar();
}

} // namespace ssao
