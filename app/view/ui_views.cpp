// The main view: a labelled grid of every buffer (click one to enlarge it), a single enlarged
// buffer with the sample inspector drawn over it, and a split A | B comparison (drag the divider)
// or their signed difference. Dragging orbits (left) or pans (right/middle); the wheel zooms;
// WASD/QE fly in fly mode.
#include "view/app_core.h"

#include <epoxy/gl.h>

#include <cmath>

namespace ssao {

namespace {

ImTextureID texId(const gl::Texture2D& t) {
    return (ImTextureID)(intptr_t)t.id();
}

// Largest rectangle of the render's aspect that fits `avail`, centred.
void fit(ImVec2 avail, float aspect, ImVec2& outPos, ImVec2& outSize) {
    ImVec2 s(avail.x, avail.x / aspect);
    if (s.y > avail.y) s = ImVec2(avail.y * aspect, avail.y);
    outPos = ImVec2((avail.x - s.x) * 0.5f, (avail.y - s.y) * 0.5f);
    outSize = s;
}

// The number of grid columns that shows `n` views of this aspect largest (fewer on a tie): the
// grid has 8 buffers, 10 with the reference's, and the window may have any shape.
int gridColumns(int n, ImVec2 avail, float aspect) {
    int best = 1;
    float bestWidth = -1.0f;
    for (int cols = 1; cols <= std::max(n, 1); ++cols) {
        const int rows = (n + cols - 1) / cols;
        ImVec2 off, sz;
        fit(ImVec2(avail.x / float(cols) - 4, avail.y / float(std::max(rows, 1)) - 4), aspect, off, sz);
        if (sz.x > bestWidth + 0.5f) best = cols, bestWidth = sz.x;
    }
    return best;
}

// Camera interaction and hover over an image rectangle; returns true on a click (no drag).
bool interact(AppCore& app, const char* id, ImVec2 pos, ImVec2 size) {
    ImGui::SetCursorScreenPos(pos);
    ImGui::InvisibleButton(id, size,
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    const ImGuiIO& io = ImGui::GetIO();
    CameraController& cc = app.cameraController();
    const bool split = app.view().mode == ViewMode::Split && !app.view().splitDifference;
    const float divider = pos.x + size.x * app.view().splitPosition;
    bool moved = false;
    if (ImGui::IsItemActivated()) // a press near the divider drags it until released
        app.view().draggingDivider = split && ImGui::IsMouseClicked(ImGuiMouseButton_Left) &&
                              std::abs(io.MousePos.x - divider) <= 8.0f;
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) app.view().draggingDivider = false;
    if (ImGui::IsItemActive()) {
        if (app.view().draggingDivider) { // drag the divider, not the camera
            app.view().splitPosition = std::clamp((io.MousePos.x - pos.x) / size.x, 0.0f, 1.0f);
            app.frames().keepAwake();
        } else if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 2.0f) &&
                   (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
            cc.rotate(io.MouseDelta.x, io.MouseDelta.y, app.view().viewWidth);
            moved = true;
        }
        if ((ImGui::IsMouseDown(ImGuiMouseButton_Right) || ImGui::IsMouseDown(ImGuiMouseButton_Middle)) &&
            (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
            cc.pan(io.MouseDelta.x, io.MouseDelta.y, size.y);
            moved = true;
        }
    }
    if (ImGui::IsItemHovered()) {
        if (io.MouseWheel != 0) {
            cc.zoom(io.MouseWheel);
            moved = true;
        }
        if (cc.mode() == CameraController::Mode::Fly) {
            glm::vec3 m(0.0f);
            m.z += float(ImGui::IsKeyDown('W') - ImGui::IsKeyDown('S'));
            m.x += float(ImGui::IsKeyDown('D') - ImGui::IsKeyDown('A'));
            m.y += float(ImGui::IsKeyDown('E') - ImGui::IsKeyDown('Q'));
            if (m != glm::vec3(0.0f)) {
                cc.move(m, 0.6f * io.DeltaTime);
                moved = true;
            }
        }
        app.view().cursorOnImage = true;
        if (!app.view().pinPixel) {
            const ImVec2 rel((io.MousePos.x - pos.x) / size.x, (io.MousePos.y - pos.y) / size.y);
            app.view().hoverUv = glm::vec2(std::clamp(rel.x, 0.0f, 0.99999f), std::clamp(rel.y, 0.0f, 0.99999f));
            app.view().hoverChain = split && io.MousePos.x > divider ? 1 : 0;
        }
    }
    if (moved) app.frames().noteInteraction();
    const bool click = ImGui::IsItemDeactivated() &&
                       ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 2.0f).x == 0.0f &&
                       ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 2.0f).y == 0.0f;
    return click;
}

// A label in the image's top-left corner, clipped to the image (long ranges never spill over).
// A label over the top left of an image, wrapped onto more lines when wider than the image (a
// clipped "x -4.96..4.96 y -4.95." once hid the ranges a user came for).
void label(ImDrawList* dl, ImVec2 pos, const std::string& text, float maxWidth = 1e9f) {
    const float wrap = std::max(maxWidth - 8.0f, 40.0f);
    const ImVec2 ts = ImGui::CalcTextSize(text.c_str(), nullptr, false, wrap);
    dl->AddRectFilled(pos, ImVec2(pos.x + ts.x + 8, pos.y + ts.y + 4), IM_COL32(0, 0, 0, 170));
    dl->AddText(nullptr, 0.0f, ImVec2(pos.x + 4, pos.y + 2), IM_COL32(255, 255, 255, 255), text.c_str(), nullptr,
                wrap);
}

// The reference's buffers say how far the trace is (or why it waits) on their label.
std::string tag(AppCore& app, const std::string& buffer) {
    return buffer.rfind("reference.", 0) == 0 ? referenceTag(app.frames()) : std::string();
}

// A buffer with nothing to show yet (its zeros would read as "fully occluded" or "no error"):
// covered, with the reason wrapped in the middle.
void cover(ImDrawList* dl, ImVec2 p, ImVec2 q, const std::string& why) {
    if (why.empty()) return;
    dl->AddRectFilled(p, q, IM_COL32(28, 28, 32, 255));
    const float wrap = std::max(q.x - p.x - 16.0f, 40.0f);
    const ImVec2 ts = ImGui::CalcTextSize(why.c_str(), nullptr, false, wrap);
    dl->PushClipRect(p, q, true);
    dl->AddText(nullptr, 0.0f, ImVec2((p.x + q.x - ts.x) * 0.5f, (p.y + q.y - ts.y) * 0.5f),
                IM_COL32(200, 200, 200, 255), why.c_str(), nullptr, wrap);
    dl->PopClipRect();
}

void drawSamples(AppCore& app, ImDrawList* dl, ImVec2 pos, ImVec2 size) {
    const glm::ivec2 px = app.hoverPixel();
    if (!app.view().showSamples || px.x < 0) return;
    const auto& pi = app.inspection();
    if (!pi || !pi->geometry) return;
    const Renderer& r = app.renderer();
    const ImVec2 c(pos.x + (float(px.x) + 0.5f) / float(r.width()) * size.x,
                   pos.y + (float(px.y) + 0.5f) / float(r.height()) * size.y);
    dl->AddCircle(c, 6.0f, IM_COL32(255, 255, 0, 255), 12, 2.0f);
    for (const InspectTap& t : pi->taps) {
        if (t.state == TapState::BehindEye) continue;
        const ImVec2 p(pos.x + t.uv.x * size.x, pos.y + (1.0f - t.uv.y) * size.y);
        ImU32 col = t.state == TapState::Occluded ? IM_COL32(255, 60, 60, 255)
                    : t.state == TapState::Open   ? IM_COL32(60, 255, 90, 255)
                    : t.state == TapState::Sky    ? IM_COL32(80, 160, 255, 255)
                                                  : IM_COL32(150, 150, 150, 255);
        dl->AddCircleFilled(p, 2.5f, col);
        if (t.backLayer) dl->AddCircle(p, 4.5f, IM_COL32(255, 255, 255, 200), 10, 1.0f); // read the back layer
    }
}

// The second row of the toolbar in Split mode: what B is, what A | B compares.
void splitControls(AppCore& app) {
    ViewState& v = app.view();
    FrameDriver& f = app.frames();
    int kind = int(v.splitKind);
    ImGui::RadioButton("AO on | off", &kind, int(SplitKind::AoOnOff));
    ImGui::SameLine();
    ImGui::RadioButton("current | preset", &kind, int(SplitKind::Preset));
    if (!v.splitCandidateB.empty()) { // a point picked on the front (shift+click in the Front tab)
        ImGui::SameLine();
        ImGui::RadioButton(("current | " + v.splitCandidateB).c_str(), &kind, int(SplitKind::Candidate));
    }
    if (kind != int(v.splitKind)) v.splitKind = SplitKind(kind), f.keepAwake();
    if (v.splitKind == SplitKind::Preset) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(150);
        if (ImGui::BeginCombo("B", v.splitPresetB.c_str())) {
            for (const auto& e : app.presets().entries())
                if (ImGui::Selectable(e.name.c_str(), e.name == v.splitPresetB)) v.splitPresetB = e.name, f.keepAwake();
            ImGui::EndCombo();
        }
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(130);
    if (ImGui::BeginCombo("compare", v.splitBuffer.c_str())) {
        // Every buffer chain B has too (its own or shared with A), from the graph.
        for (const Resource* r : app.renderer().buffers()) {
            const std::string& b = r->desc.name;
            if (app.renderer().graph().find("b." + b) && ImGui::Selectable(b.c_str(), v.splitBuffer == b))
                v.splitBuffer = b, f.keepAwake();
        }
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    if (ImGui::Checkbox("A - B", &v.splitDifference)) f.keepAwake();
    rememberRect(v, "split#difference");
    if (v.splitDifference) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(90);
        if (ImGui::SliderFloat("x", &v.diffScale, 1.0f, 100.0f, "%.0f", ImGuiSliderFlags_Logarithmic)) f.keepAwake();
    }
}

// The first row: view mode, render scales and the display style.
void modeAndScales(ViewState& v, FrameDriver& f) {
    int mode = int(v.mode);
    ImGui::RadioButton("Grid", &mode, int(ViewMode::Grid));
    ImGui::SameLine();
    ImGui::RadioButton("Single", &mode, int(ViewMode::Single));
    ImGui::SameLine();
    ImGui::RadioButton("Split A|B", &mode, int(ViewMode::Split));
    rememberRect(v, "mode#split");
    if (mode != int(v.mode)) v.mode = ViewMode(mode), f.keepAwake();
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    if (ImGui::SliderFloat("resolution", &f.renderScale, 0.25f, 1.0f, "%.2fx", ImGuiSliderFlags_AlwaysClamp))
        f.keepAwake();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Render resolution relative to the view when input is still");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    if (ImGui::SliderFloat("moving", &f.interactiveScale, 0.1f, 1.0f, "%.2fx", ImGuiSliderFlags_AlwaysClamp))
        f.keepAwake();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Resolution while the camera moves or a slider is dragged; refined to full when input stops");
    ImGui::SameLine();
    if (ImGui::Checkbox("fit range", &v.style.fit)) f.keepAwake();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Stretch every buffer over its 1st..99th percentile on geometry (depth and position always are)");
    ImGui::SameLine();
    if (ImGui::Checkbox("false colour", &v.style.falseColor)) f.keepAwake();
}

void toolbar(AppCore& app) {
    modeAndScales(app.view(), app.frames());
    // The second row always exists (with frame height), so switching modes never resizes the image
    // and never re-renders everything.
    ViewState& v = app.view();
    if (v.mode == ViewMode::Grid) {
        ImGui::AlignTextToFramePadding();
        ImGui::TextDisabled("click a buffer to enlarge it; drag: orbit, right-drag: pan, wheel: zoom; "
                            "ranges are printed on each view");
    }
    if (v.mode == ViewMode::Single) {
        ImGui::SetNextItemWidth(170);
        if (ImGui::BeginCombo("buffer", v.enlarged.c_str())) {
            for (const Resource* r : app.renderer().buffers())
                if (ImGui::Selectable(r->desc.name.c_str(), r->desc.name == v.enlarged))
                    v.enlarged = r->desc.name, app.frames().keepAwake();
            ImGui::EndCombo();
        }
    }
    if (v.mode == ViewMode::Split) splitControls(app);
}

// A painted buffer is opaque (view.frag writes alpha 1), so it is drawn without the UI's blending:
// llvmpipe then writes its pixels instead of reading and mixing them, and drops what lay under
// a tile it covers (measured: Lantern's grid, five alternating runs each, medians: idle frame 8.1
// -> 6.7 ms, drag 20.4 -> 17.9, still 76.2 -> 66.5). The backend's state returns after it.
void image(ImDrawList* dl, const BufferViews::View* v, ImVec2 p, ImVec2 q, ImVec2 uv0 = {0, 1},
           ImVec2 uv1 = {1, 0}) {
    if (!v || !v->target.texture()) return;
    dl->AddCallback([](const ImDrawList*, const ImDrawCmd*) { glDisable(GL_BLEND); }, nullptr);
    dl->AddImage(texId(v->target.texture()), p, q, uv0, uv1);
    dl->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
}

} // namespace

void drawMainView(AppCore& app, ImVec2 pos, ImVec2 size) {
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4, 4));
    beginFixedWindow("view", pos, size,
                     ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar |
                         ImGuiWindowFlags_NoScrollWithMouse);
    toolbar(app);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    app.view().viewWidth = avail.x; // a drag across the whole view turns half a turn, in a grid cell too
    // Render at the size the enlarged view shows (1:1 pixels, framebuffer scale included).
    const ImVec2 fbScale = ImGui::GetIO().DisplayFramebufferScale;
    app.renderIfNeeded(int(avail.x * fbScale.x), int(avail.y * fbScale.y));
    app.view().cursorOnImage = false; // set again below by the image the cursor is over
    Renderer& r = app.renderer();
    const float aspect = float(r.width()) / float(r.height());
    ImDrawList* dl = ImGui::GetWindowDrawList();
    BufferViews& views = app.frames().views();

    if (app.view().mode == ViewMode::Grid) {
        const auto buffers = r.buffers();
        const int cols = gridColumns(int(buffers.size()), avail, aspect);
        const int rows = int((buffers.size() + size_t(cols) - 1) / size_t(cols));
        const ImVec2 cell(avail.x / float(cols), avail.y / float(std::max(rows, 1)));
        for (size_t i = 0; i < buffers.size(); ++i) {
            const std::string& name = buffers[i]->desc.name;
            ImVec2 off, sz;
            fit(ImVec2(cell.x - 4, cell.y - 4), aspect, off, sz);
            const ImVec2 p(origin.x + float(i % cols) * cell.x + off.x,
                           origin.y + float(i / cols) * cell.y + off.y);
            ImGui::PushID(int(i));
            const bool clicked = interact(app, "cell", p, sz);
            ImGui::PopID();
            const BufferViews::View* v = views.find(name);
            image(dl, v, p, ImVec2(p.x + sz.x, p.y + sz.y));
            cover(dl, p, ImVec2(p.x + sz.x, p.y + sz.y), referenceEmptyReason(app.frames(), name));
            label(dl, p, (v ? v->label : name) + tag(app, name), sz.x);
            app.view().widgetRects["view#" + name] = ImVec4(p.x, p.y, p.x + sz.x, p.y + sz.y);
            app.view().gridCellPx = std::max(1, int(std::ceil(sz.x * fbScale.x))); // painted at this size next frame
            if (clicked) {
                app.view().enlarged = name;
                app.view().mode = ViewMode::Single;
                app.frames().keepAwake();
            }
        }
    } else {
        ImVec2 off, sz;
        fit(avail, aspect, off, sz);
        const ImVec2 p(origin.x + off.x, origin.y + off.y), q(p.x + sz.x, p.y + sz.y);
        if (interact(app, "image", p, sz) && app.view().mode == ViewMode::Single) app.view().pinPixel = !app.view().pinPixel;
        app.view().widgetRects["view#main"] = ImVec4(p.x, p.y, q.x, q.y);
        if (app.view().mode == ViewMode::Single) {
            const BufferViews::View* v = views.find(app.view().enlarged);
            image(dl, v, p, q);
            cover(dl, p, q, referenceEmptyReason(app.frames(), app.view().enlarged));
            label(dl, p, (v ? v->label : app.view().enlarged) + tag(app, app.view().enlarged));
            drawSamples(app, dl, p, sz);
        } else if (app.view().splitDifference) {
            if (r.graph().find("b." + app.view().splitBuffer)) {
                const BufferViews::View& d =
                    views.difference(r, app.view().splitBuffer, "b." + app.view().splitBuffer, app.view().diffScale);
                image(dl, &d, p, q);
                label(dl, p, d.label);
            }
        } else {
            const float s = app.view().splitPosition, x = p.x + sz.x * s;
            image(dl, views.find(app.view().splitBuffer), p, ImVec2(x, q.y), ImVec2(0, 1), ImVec2(s, 0));
            image(dl, views.find("b." + app.view().splitBuffer), ImVec2(x, p.y), q, ImVec2(s, 1), ImVec2(1, 0));
            dl->AddLine(ImVec2(x, p.y), ImVec2(x, q.y), IM_COL32(255, 255, 0, 255), 3.0f);
            dl->AddCircleFilled(ImVec2(x, (p.y + q.y) * 0.5f), 6.0f, IM_COL32(255, 255, 0, 255));
            app.view().widgetRects["split#divider"] = ImVec4(x - 4, p.y, x + 4, q.y);
            label(dl, p, "A: current  " + app.view().splitBuffer);
            const std::string bl = app.view().splitKind == SplitKind::AoOnOff     ? "B: AO off"
                                   : app.view().splitKind == SplitKind::Candidate ? "B: " + app.view().splitCandidateB
                                                                                  : "B: " + app.view().splitPresetB;
            label(dl, ImVec2(q.x - ImGui::CalcTextSize(bl.c_str()).x - 10, p.y), bl);
            drawSamples(app, dl, p, sz);
        }
    }
    ImGui::End();
    ImGui::PopStyleVar();
}

} // namespace ssao
