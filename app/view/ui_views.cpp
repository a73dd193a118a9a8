// The main view: a labelled grid of every buffer (click one to enlarge it), a single enlarged
// buffer with the sample inspector drawn over it, and a split A | B comparison (drag the divider)
// or their signed difference. Dragging orbits (left) or pans (right/middle); the wheel zooms;
// WASD/QE fly in fly mode.
#include "view/app_core.h"
#include "view/ui_layout.h"

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

// A one-line label over the top left of an enlarged image (as wide as the view: the ranges fit).
void label(ImDrawList* dl, ImVec2 pos, const std::string& text) {
    const ImVec2 ts = ImGui::CalcTextSize(text.c_str());
    dl->AddRectFilled(pos, ImVec2(pos.x + ts.x + 8, pos.y + ts.y + 4), IM_COL32(0, 0, 0, 170));
    dl->AddText(ImVec2(pos.x + 4, pos.y + 2), IM_COL32(255, 255, 255, 255), text.c_str());
}

// A grid cell's label on the two lines above its image: the buffer's name, and its range cut at a
// group or word to the image's width (never inside a number: "x -6.37..7.1" stays whole or goes,
// a triangle says something was left off); the whole text on hover. Returns its rectangle.
ImVec4 labelLines(ImDrawList* dl, ImVec2 pos, const std::string& name, const std::string& range, float width) {
    const MeasureText measure = [](const std::string& t) { return ImGui::CalcTextSize(t.c_str()).x; };
    const float room = std::max(width - 8.0f - 10.0f, 0.0f); // padding and the triangle
    bool cutName = false, cutRange = false;
    const std::string lines[2] = {fitLine(name, room, measure, &cutName, ""),
                                  fitLine(range, room, measure, &cutRange, "")};
    const bool cut[2] = {cutName, cutRange};
    const float lh = ImGui::GetTextLineHeight();
    float w = 0;
    for (int i = 0; i < 2; ++i)
        w = std::max(w, measure(lines[i]) + (cut[i] ? 10.0f : 0.0f));
    const ImVec2 q(pos.x + std::min(w + 8.0f, width), pos.y + (range.empty() ? 1.0f : 2.0f) * lh + 4.0f);
    dl->AddRectFilled(pos, q, IM_COL32(0, 0, 0, 170));
    for (int i = 0; i < 2; ++i) {
        const ImVec2 t(pos.x + 4, pos.y + 2 + float(i) * lh);
        dl->AddText(t, i == 0 ? IM_COL32(255, 255, 255, 255) : IM_COL32(210, 210, 210, 255), lines[i].c_str());
        if (!cut[i]) continue;
        const float x = t.x + measure(lines[i]) + 3.0f, y = t.y + lh * 0.5f;
        dl->AddTriangleFilled(ImVec2(x, y - 4), ImVec2(x, y + 4), ImVec2(x + 5, y), IM_COL32(255, 200, 60, 255));
    }
    if ((cutName || cutRange) && ImGui::IsMouseHoveringRect(pos, q))
        ImGui::SetTooltip("%s\n%s", name.c_str(), range.c_str());
    return ImVec4(pos.x, pos.y, q.x, q.y);
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
    if (ImGui::BeginCombo(v.imageB() ? "A shows" : "compare", v.splitBuffer.c_str())) {
        // Every buffer chain B has too (its own or shared with A), from the graph; against an
        // engine's frame (an image, no chain B) every buffer of A.
        for (const Resource* r : app.renderer().buffers()) {
            const std::string& b = r->desc.name;
            if ((v.imageB() || app.renderer().graph().find("b." + b)) && ImGui::Selectable(b.c_str(), v.splitBuffer == b))
                v.splitBuffer = b, f.keepAwake();
        }
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    ImGui::BeginDisabled(v.imageB()); // A - B is drawn from two chains of the renderer
    if (ImGui::Checkbox("A - B", &v.splitDifference)) f.keepAwake();
    ImGui::EndDisabled();
    rememberRect(v, "split#difference");
    if (v.imageB() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("B is the engine's AO frame from Chromium, an image: A - B needs two of ssaolab's chains");
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
// a tile it covers. The backend's state returns after it.
void image(ImDrawList* dl, const BufferViews::View* v, ImVec2 p, ImVec2 q, ImVec2 uv0 = {0, 1},
           ImVec2 uv1 = {1, 0}) {
    if (!v || !v->target.texture()) return;
    dl->AddCallback([](const ImDrawList*, const ImDrawCmd*) { glDisable(GL_BLEND); }, nullptr);
    dl->AddImage(texId(v->target.texture()), p, q, uv0, uv1);
    dl->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
}

// Split A | B where B is an engine's AO frame (an image of the view, ViewState::imageB): A is the
// buffer chosen, B the frame whatever A shows.
void drawImageSplit(AppCore& app, ImDrawList* dl, ImVec2 p, ImVec2 q) {
    ViewState& v = app.view();
    const float s = v.splitPosition, x = p.x + (q.x - p.x) * s;
    image(dl, app.frames().views().find(v.splitBuffer), p, ImVec2(x, q.y), ImVec2(0, 1), ImVec2(s, 0));
    std::string why;
    if (const gl::Texture2D* t = app.splitImageB(why)) {
        dl->AddCallback([](const ImDrawList*, const ImDrawCmd*) { glDisable(GL_BLEND); }, nullptr);
        dl->AddImage(texId(*t), ImVec2(x, p.y), q, ImVec2(s, 0), ImVec2(1, 1)); // its top row first
        dl->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
    } else {
        cover(dl, ImVec2(x, p.y), q, why);
    }
    v.widgetRects["split#image_b"] = ImVec4(x, p.y, q.x, q.y);
    dl->AddLine(ImVec2(x, p.y), ImVec2(x, q.y), IM_COL32(255, 255, 0, 255), 3.0f);
    dl->AddCircleFilled(ImVec2(x, (p.y + q.y) * 0.5f), 6.0f, IM_COL32(255, 255, 0, 255));
    v.widgetRects["split#divider"] = ImVec4(x - 4, p.y, x + 4, q.y);
    label(dl, p, "A: current  " + v.splitBuffer);
    const std::string bl = "B: " + v.splitCandidateB + "  AO 0..1 (Chromium)" +
                           (v.splitBuffer.rfind("ao.", 0) == 0 ? "" : ", whatever A shows");
    label(dl, ImVec2(q.x - ImGui::CalcTextSize(bl.c_str()).x - 10, p.y), bl);
}

// Every buffer, each under its label, laid out to fill `avail` (ui_layout.h); a click enlarges one.
void drawGrid(AppCore& app, ImVec2 origin, ImVec2 avail, float aspect) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    BufferViews& views = app.frames().views();
    const auto buffers = app.renderer().buffers();
    // Each image under two lines of its own for its name and range: the label never covers it.
    const float labelHeight = 2.0f * ImGui::GetTextLineHeight() + 4.0f;
    const GridLayout grid = gridLayout(int(buffers.size()), avail.x, avail.y, aspect, labelHeight, 4.0f);
    app.view().widgetRects["view#grid"] = ImVec4(origin.x, origin.y, origin.x + avail.x, origin.y + avail.y);
    float widest = 1.0f;
    for (size_t i = 0; i < buffers.size() && i < grid.slots.size(); ++i) {
        const std::string& name = buffers[i]->desc.name;
        const GridSlot& g = grid.slots[i];
        const ImVec2 p(origin.x + g.x, origin.y + g.y), q(p.x + g.w, p.y + g.h);
        ImGui::PushID(int(i));
        const bool clicked = interact(app, "cell", p, ImVec2(g.w, g.h));
        ImGui::PopID();
        const BufferViews::View* v = views.find(name);
        image(dl, v, p, q);
        cover(dl, p, q, referenceEmptyReason(app.frames(), name));
        // The view's label is "name  range": the range goes on the second line.
        std::string range = (v ? v->label.substr(std::min(name.size(), v->label.size())) : "") + tag(app, name);
        range.erase(0, std::min(range.find_first_not_of(' '), range.size()));
        app.view().widgetRects["label#" + name] = labelLines(dl, ImVec2(p.x, origin.y + g.labelY), name, range, g.w);
        app.view().widgetRects["view#" + name] = ImVec4(p.x, p.y, q.x, q.y);
        widest = std::max(widest, g.w);
        if (clicked) {
            app.view().enlarged = name;
            app.view().mode = ViewMode::Single;
            app.frames().keepAwake();
        }
    }
    // Painted at the largest cell's size next frame (rows of fewer images have larger ones).
    app.view().gridCellPx = std::max(1, int(std::ceil(widest * ImGui::GetIO().DisplayFramebufferScale.x)));
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
        drawGrid(app, origin, avail, aspect);
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
        } else if (app.view().imageB()) {
            drawImageSplit(app, dl, p, q);
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
