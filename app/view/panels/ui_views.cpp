// The main view: a labelled grid of every buffer (click one to enlarge it), a single enlarged
// buffer with the sample inspector drawn over it, and a split A | B comparison (drag the divider)
// or their signed difference. Dragging orbits (left) or pans (right/middle); the wheel zooms;
// WASD/QE fly in fly mode.
#include "view/panels/ui_panels.h"
#include "view/panels/ui_layout.h"

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

// Where the cursor is and the divider, as the input phase leaves them (ViewState's fields).
struct Pointer {
    bool dragging;
    float position;
    bool onImage = false;
    glm::vec2 uv;
    int chain;
};

// Camera interaction and hover over an image rectangle; returns true on a click (no drag).
bool interact(const ViewState& v, CameraController::Mode cameraMode, Pointer& pt, const char* id, ImVec2 pos,
              ImVec2 size, UiActions& out) {
    ImGui::SetCursorScreenPos(pos);
    ImGui::InvisibleButton(id, size,
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    const ImGuiIO& io = ImGui::GetIO();
    const bool split = v.mode == ViewMode::Split && !v.splitDifference;
    const float divider = pos.x + size.x * pt.position;
    bool moved = false;
    if (ImGui::IsItemActivated()) // a press near the divider drags it until released
        pt.dragging = split && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && std::abs(io.MousePos.x - divider) <= 8.0f;
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) pt.dragging = false;
    if (ImGui::IsItemActive()) {
        if (pt.dragging) { // drag the divider, not the camera
            pt.position = std::clamp((io.MousePos.x - pos.x) / size.x, 0.0f, 1.0f);
            out.push(act::KeepAwake{});
        } else if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 2.0f) &&
                   (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
            out.push(act::Orbit{io.MouseDelta.x, io.MouseDelta.y, v.viewWidth});
            moved = true;
        }
        if ((ImGui::IsMouseDown(ImGuiMouseButton_Right) || ImGui::IsMouseDown(ImGuiMouseButton_Middle)) &&
            (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
            out.push(act::Pan{io.MouseDelta.x, io.MouseDelta.y, size.y});
            moved = true;
        }
    }
    if (ImGui::IsItemHovered()) {
        if (io.MouseWheel != 0) {
            out.push(act::Zoom{io.MouseWheel});
            moved = true;
        }
        if (cameraMode == CameraController::Mode::Fly) {
            glm::vec3 m(0.0f);
            m.z += float(ImGui::IsKeyDown('W') - ImGui::IsKeyDown('S'));
            m.x += float(ImGui::IsKeyDown('D') - ImGui::IsKeyDown('A'));
            m.y += float(ImGui::IsKeyDown('E') - ImGui::IsKeyDown('Q'));
            if (m != glm::vec3(0.0f)) {
                out.push(act::Fly{m, 0.6f * io.DeltaTime});
                moved = true;
            }
        }
        pt.onImage = true;
        if (!v.pinPixel) {
            const ImVec2 rel((io.MousePos.x - pos.x) / size.x, (io.MousePos.y - pos.y) / size.y);
            pt.uv = glm::vec2(std::clamp(rel.x, 0.0f, 0.99999f), std::clamp(rel.y, 0.0f, 0.99999f));
            pt.chain = split && io.MousePos.x > divider ? 1 : 0;
        }
    }
    if (moved) out.push(act::NoteInteraction{});
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
std::string tag(const FrameDriver& frames, const std::string& buffer) {
    return buffer.rfind("reference.", 0) == 0 ? referenceTag(frames) : std::string();
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

void drawSamples(const ViewImages& in, const Renderer& r, ImDrawList* dl, ImVec2 pos, ImVec2 size) {
    const glm::ivec2 px = in.hoverPixel;
    if (!in.inspection || px.x < 0) return;
    const auto& pi = *in.inspection;
    if (!pi || !pi->geometry) return;
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
        if (t.secondLayer) // the surface behind it hid sectors
            dl->AddRect(ImVec2(p.x - 4.5f, p.y - 4.5f), ImVec2(p.x + 4.5f, p.y + 4.5f), IM_COL32(255, 220, 80, 220));
    }
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
void drawImageSplit(const ViewState& v, const ViewImages& in, ImDrawList* dl, ImVec2 p, ImVec2 q, UiActions& out) {
    const float s = v.splitPosition, x = p.x + (q.x - p.x) * s;
    image(dl, in.frames.views().find(v.splitBuffer), p, ImVec2(x, q.y), ImVec2(0, 1), ImVec2(s, 0));
    if (const gl::Texture2D* t = in.imageB) {
        dl->AddCallback([](const ImDrawList*, const ImDrawCmd*) { glDisable(GL_BLEND); }, nullptr);
        dl->AddImage(texId(*t), ImVec2(x, p.y), q, ImVec2(s, 0), ImVec2(1, 1)); // its top row first
        dl->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
    } else {
        cover(dl, ImVec2(x, p.y), q, in.whyNoImageB);
    }
    out.rects["split#image_b"] = ImVec4(x, p.y, q.x, q.y);
    dl->AddLine(ImVec2(x, p.y), ImVec2(x, q.y), IM_COL32(255, 255, 0, 255), 3.0f);
    dl->AddCircleFilled(ImVec2(x, (p.y + q.y) * 0.5f), 6.0f, IM_COL32(255, 255, 0, 255));
    out.rects["split#divider"] = ImVec4(x - 4, p.y, x + 4, q.y);
    label(dl, p, "A: current  " + v.splitBuffer);
    const std::string bl = "B: " + v.splitCandidateB + "  AO 0..1 (Chromium)" +
                           (v.splitBuffer.rfind("ao.", 0) == 0 ? "" : ", whatever A shows");
    label(dl, ImVec2(q.x - ImGui::CalcTextSize(bl.c_str()).x - 10, p.y), bl);
}

// Split A | B of two chains: each half its chain's buffer, the divider between them.
void drawChainSplit(const ViewState& v, const ViewImages& in, ImDrawList* dl, ImVec2 p, ImVec2 sz, UiActions& out) {
    const ImVec2 q(p.x + sz.x, p.y + sz.y);
    const BufferViews& views = in.frames.views();
    const float s = v.splitPosition, x = p.x + sz.x * s;
    image(dl, views.find(v.splitBuffer), p, ImVec2(x, q.y), ImVec2(0, 1), ImVec2(s, 0));
    image(dl, views.find("b." + v.splitBuffer), ImVec2(x, p.y), q, ImVec2(s, 1), ImVec2(1, 0));
    dl->AddLine(ImVec2(x, p.y), ImVec2(x, q.y), IM_COL32(255, 255, 0, 255), 3.0f);
    dl->AddCircleFilled(ImVec2(x, (p.y + q.y) * 0.5f), 6.0f, IM_COL32(255, 255, 0, 255));
    out.rects["split#divider"] = ImVec4(x - 4, p.y, x + 4, q.y);
    label(dl, p, "A: current  " + v.splitBuffer);
    const std::string bl = v.splitKind == SplitKind::AoOnOff     ? "B: AO off"
                           : v.splitKind == SplitKind::Candidate ? "B: " + v.splitCandidateB
                                                                 : "B: " + v.splitPresetB;
    label(dl, ImVec2(q.x - ImGui::CalcTextSize(bl.c_str()).x - 10, p.y), bl);
    drawSamples(in, in.frames.renderer(), dl, p, sz);
}

// Every buffer, each under two lines of its own for its name and range (the label never covers
// it), laid out to fill the view (ui_layout.h).
GridLayout grid(const ViewArea& a, size_t buffers) {
    const float aspect = float(a.renderer.width()) / float(a.renderer.height());
    const float labelHeight = 2.0f * ImGui::GetTextLineHeight() + 4.0f;
    return gridLayout(int(buffers), a.avail.x, a.avail.y, aspect, labelHeight, 4.0f);
}

// The image's rectangle in Single and Split mode: the render's aspect, centred.
void imageRect(const ViewArea& a, ImVec2& p, ImVec2& sz) {
    ImVec2 off;
    fit(a.avail, float(a.renderer.width()) / float(a.renderer.height()), off, sz);
    p = ImVec2(a.origin.x + off.x, a.origin.y + off.y);
}

// Every buffer under its label; a click (drawViewInput) enlarges one.
void drawGrid(const ViewArea& a, const ViewImages& in, UiActions& out) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const auto buffers = a.renderer.buffers();
    const GridLayout g = grid(a, buffers.size());
    out.rects["view#grid"] = ImVec4(a.origin.x, a.origin.y, a.origin.x + a.avail.x, a.origin.y + a.avail.y);
    float widest = 1.0f;
    for (size_t i = 0; i < buffers.size() && i < g.slots.size(); ++i) {
        const std::string& name = buffers[i]->desc.name;
        const GridSlot& s = g.slots[i];
        const ImVec2 p(a.origin.x + s.x, a.origin.y + s.y), q(p.x + s.w, p.y + s.h);
        const BufferViews::View* v = in.frames.views().find(name);
        image(dl, v, p, q);
        cover(dl, p, q, referenceEmptyReason(in.frames, name));
        // The view's label is "name  range": the range goes on the second line.
        std::string range = (v ? v->label.substr(std::min(name.size(), v->label.size())) : "") + tag(in.frames, name);
        range.erase(0, std::min(range.find_first_not_of(' '), range.size()));
        out.rects["label#" + name] = labelLines(dl, ImVec2(p.x, a.origin.y + s.labelY), name, range, s.w);
        out.rects["view#" + name] = ImVec4(p.x, p.y, q.x, q.y);
        widest = std::max(widest, s.w);
    }
    // Painted at the largest cell's size next frame (rows of fewer images have larger ones).
    out.push(act::SetGridCellPx{std::max(1, int(std::ceil(widest * ImGui::GetIO().DisplayFramebufferScale.x)))});
}

} // namespace

void drawViewInput(const ViewArea& a, CameraController::Mode cameraMode, UiActions& out) {
    const ViewState& v = a.view;
    Pointer pt{v.draggingDivider, v.splitPosition, false, v.hoverUv, v.hoverChain};
    if (v.mode == ViewMode::Grid) {
        const auto buffers = a.renderer.buffers();
        const GridLayout g = grid(a, buffers.size());
        for (size_t i = 0; i < buffers.size() && i < g.slots.size(); ++i) {
            const GridSlot& s = g.slots[i];
            ImGui::PushID(int(i));
            const bool clicked =
                interact(v, cameraMode, pt, "cell", ImVec2(a.origin.x + s.x, a.origin.y + s.y), ImVec2(s.w, s.h), out);
            ImGui::PopID();
            if (clicked) out.push(act::SelectView{ViewMode::Single, buffers[i]->desc.name});
        }
    } else {
        ImVec2 p, sz;
        imageRect(a, p, sz);
        if (interact(v, cameraMode, pt, "image", p, sz, out) && v.mode == ViewMode::Single) out.push(act::TogglePin{});
    }
    if (pt.dragging != v.draggingDivider || pt.position != v.splitPosition)
        out.push(act::SetDivider{pt.dragging, pt.position});
    if (pt.onImage) out.push(act::CursorOnImage{});
    if (pt.uv != v.hoverUv || pt.chain != v.hoverChain) out.push(act::SetHover{pt.uv, pt.chain});
}

void drawViewImages(const ViewArea& a, const ViewImages& in, UiActions& out) {
    const ViewState& v = a.view;
    if (in.mode == ViewMode::Grid) {
        drawGrid(a, in, out);
        return;
    }
    ImDrawList* dl = ImGui::GetWindowDrawList();
    ImVec2 p, sz;
    imageRect(a, p, sz);
    const ImVec2 q(p.x + sz.x, p.y + sz.y);
    out.rects["view#main"] = ImVec4(p.x, p.y, q.x, q.y);
    if (v.mode == ViewMode::Single) {
        const BufferViews::View* b = in.frames.views().find(v.enlarged);
        image(dl, b, p, q);
        cover(dl, p, q, referenceEmptyReason(in.frames, v.enlarged));
        label(dl, p, (b ? b->label : v.enlarged) + tag(in.frames, v.enlarged));
        drawSamples(in, a.renderer, dl, p, sz);
    } else if (v.imageB()) {
        drawImageSplit(v, in, dl, p, q, out);
    } else if (v.splitDifference) {
        if (in.difference) {
            image(dl, in.difference, p, q);
            label(dl, p, in.difference->label);
        }
    } else {
        drawChainSplit(v, in, dl, p, sz, out);
    }
}

} // namespace ssao
