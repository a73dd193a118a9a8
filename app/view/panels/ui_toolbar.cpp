// The main view's toolbar: the view mode, the render scales and the display style, and under them
// the enlarged buffer (Single) or what B is and what A | B compares (Split). The rows after a choice
// follow it in the same frame: they draw from the toolbar's own copies of the fields it edits.
#include "view/panels/ui_panels.h"

namespace ssao {

namespace {

// The second row of the toolbar in Split mode: what B is, what A | B compares.
void splitControls(const ToolbarView& in, UiActions& out) {
    const ViewState& v = in.view;
    act::SetSplit split{v.splitKind, v.splitPresetB, v.splitBuffer, v.splitDifference, v.diffScale};
    bool changed = false;
    int kind = int(split.kind);
    ImGui::RadioButton("AO on | off", &kind, int(SplitKind::AoOnOff));
    ImGui::SameLine();
    ImGui::RadioButton("current | preset", &kind, int(SplitKind::Preset));
    if (!v.splitCandidateB.empty()) { // a point picked on the front (shift+click in the Front tab)
        ImGui::SameLine();
        ImGui::RadioButton(("current | " + v.splitCandidateB).c_str(), &kind, int(SplitKind::Candidate));
    }
    if (kind != int(split.kind)) split.kind = SplitKind(kind), changed = true;
    // ViewState::imageB with the kind chosen this frame.
    const bool imageB = split.kind == SplitKind::Candidate && v.splitCandidateImage;
    if (split.kind == SplitKind::Preset) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(150);
        if (ImGui::BeginCombo("B", split.presetB.c_str())) {
            for (const auto& e : in.store.entries())
                if (ImGui::Selectable(e.name.c_str(), e.name == split.presetB)) split.presetB = e.name, changed = true;
            ImGui::EndCombo();
        }
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(130);
    const Renderer& r = in.frames.renderer();
    if (ImGui::BeginCombo(imageB ? "A shows" : "compare", split.buffer.c_str())) {
        // Every buffer chain B has too (its own or shared with A), from the graph; against an
        // engine's frame (an image, no chain B) every buffer of A.
        for (const Resource* res : r.buffers()) {
            const std::string& b = res->desc.name;
            if ((imageB || r.graph().find("b." + b)) && ImGui::Selectable(b.c_str(), split.buffer == b))
                split.buffer = b, changed = true;
        }
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    ImGui::BeginDisabled(imageB); // A - B is drawn from two chains of the renderer
    changed |= ImGui::Checkbox("A - B", &split.difference);
    ImGui::EndDisabled();
    rememberRect(out, "split#difference");
    if (imageB && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("B is the engine's AO frame from Chromium, an image: A - B needs two of ssaolab's chains");
    if (split.difference) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(90);
        changed |= ImGui::SliderFloat("x", &split.diffScale, 1.0f, 100.0f, "%.0f", ImGuiSliderFlags_Logarithmic);
    }
    if (changed) out.push(split);
}

// The first row: view mode, render scales and the display style; returns the mode chosen.
ViewMode modeAndScales(const ViewState& v, const FrameDriver& f, UiActions& out) {
    int mode = int(v.mode);
    ImGui::RadioButton("Grid", &mode, int(ViewMode::Grid));
    ImGui::SameLine();
    ImGui::RadioButton("Single", &mode, int(ViewMode::Single));
    ImGui::SameLine();
    ImGui::RadioButton("Split A|B", &mode, int(ViewMode::Split));
    rememberRect(out, "mode#split");
    if (mode != int(v.mode)) out.push(act::SelectView{ViewMode(mode), v.enlarged});
    act::SetDisplay d{f.renderScale, f.interactiveScale, v.style};
    bool changed = false;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    changed |= ImGui::SliderFloat("resolution", &d.renderScale, 0.25f, 1.0f, "%.2fx", ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Render resolution relative to the view when input is still");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    changed |= ImGui::SliderFloat("moving", &d.interactiveScale, 0.1f, 1.0f, "%.2fx", ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Resolution while the camera moves or a slider is dragged; refined to full when input stops");
    ImGui::SameLine();
    changed |= ImGui::Checkbox("fit range", &d.style.fit);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Stretch every buffer over its 1st..99th percentile on geometry (depth and position always are)");
    ImGui::SameLine();
    changed |= ImGui::Checkbox("false colour", &d.style.falseColor);
    if (changed) out.push(d);
    return ViewMode(mode);
}

} // namespace

void drawViewToolbar(const ToolbarView& in, UiActions& out) {
    const ViewState& v = in.view;
    const ViewMode mode = modeAndScales(v, in.frames, out);
    // The second row always exists (with frame height), so switching modes never resizes the image
    // and never re-renders everything.
    if (mode == ViewMode::Grid) {
        ImGui::AlignTextToFramePadding();
        ImGui::TextDisabled("click a buffer to enlarge it; drag: orbit, right-drag: pan, wheel: zoom; "
                            "ranges are printed on each view");
    }
    if (mode == ViewMode::Single) {
        ImGui::SetNextItemWidth(170);
        if (ImGui::BeginCombo("buffer", v.enlarged.c_str())) {
            for (const Resource* r : in.frames.renderer().buffers())
                if (ImGui::Selectable(r->desc.name.c_str(), r->desc.name == v.enlarged))
                    out.push(act::SelectView{mode, r->desc.name});
            ImGui::EndCombo();
        }
    }
    if (mode == ViewMode::Split) splitControls(in, out);
}

} // namespace ssao
