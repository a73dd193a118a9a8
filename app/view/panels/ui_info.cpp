// The strip under the image, always in view: per-pass GPU times (at full resolution and while
// moving, in graph order) with the frame-time plot, the error against the ray-traced reference
// (ui_reference.cpp), and the pixel / sample inspector.
#include "view/panels/ui_panels.h"

#include <algorithm>
#include <cfloat>
#include <cstdio>

namespace ssao {

namespace {

void timingSection(FrameDriver& frames, ViewState& view) {
    const FrameDriver::Timing& full = frames.timing(false);
    const FrameDriver::Timing& moving = frames.timing(true);
    const auto& order = frames.renderer().graph().passOrder();
    if (ImGui::BeginTable("timing", 3, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg)) {
        char h1[48], h2[48];
        std::snprintf(h1, sizeof h1, "full %dx%d", full.width, full.height);
        std::snprintf(h2, sizeof h2, "moving %dx%d", moving.width, moving.height);
        // Weights from the widest text each column holds: without them the first frame (no widths
        // measured yet) squeezed every column to one character.
        float names = ImGui::CalcTextSize("all passes").x;
        for (const auto& name : order)
            names = std::max(names, ImGui::CalcTextSize(name.c_str()).x);
        const float numbers = ImGui::CalcTextSize("moving 0000x0000").x;
        ImGui::TableSetupColumn("GPU ms", ImGuiTableColumnFlags_WidthStretch, names);
        ImGui::TableSetupColumn(h1, ImGuiTableColumnFlags_WidthStretch, numbers);
        ImGui::TableSetupColumn(h2, ImGuiTableColumnFlags_WidthStretch, numbers);
        ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
        for (int c = 0; c < 3; ++c) {
            ImGui::TableSetColumnIndex(c);
            ImGui::TableHeader(ImGui::TableGetColumnName(c));
            rememberRect(view, "timing#col" + std::to_string(c));
        }
        double totals[2] = {0, 0};
        for (const auto& name : order) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(name.c_str());
            const FrameDriver::Timing* t[2] = {&full, &moving};
            for (int i = 0; i < 2; ++i) {
                ImGui::TableNextColumn();
                const double ms = t[i]->average(name);
                if (ms >= 0) {
                    ImGui::Text("%.2f", ms);
                    totals[i] += ms;
                } else {
                    ImGui::TextDisabled("-");
                }
            }
        }
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("all passes");
        for (double t : totals) {
            ImGui::TableNextColumn();
            ImGui::Text("%.2f", t);
        }
        ImGui::EndTable();
    }
    rememberRect(view, "timing");
    std::vector<float> f(frames.frameMs().begin(), frames.frameMs().end());
    if (!f.empty()) {
        const float width =
            std::max(ImGui::GetContentRegionAvail().x, 50.0f); // an explicit width: -1 draws nothing
        ImGui::PlotLines("##frame", f.data(), int(f.size()), 0, nullptr, 0.0f, FLT_MAX, ImVec2(width, 40));
        rememberRect(view, "timing#plot");
        ImGui::TextDisabled("frame %.1f ms (CPU, UI included)%s", f.back(),
                            frames.renderedInteractive() ? ", reduced resolution while moving" : "");
    }
    std::string ran;
    for (auto& n : frames.lastReport().ran())
        ran += n + " ";
    wrappedText("last change re-ran: " + ran, true);
    rememberRect(view, "timing#ran");
}

void inspectorSection(FrameDriver& frames, Inspector& inspector, ViewState& view) {
    ImGui::Checkbox("samples at cursor", &view.showSamples);
    ImGui::SameLine();
    ImGui::Checkbox("pin pixel", &view.pinPixel);
    rememberRect(view, "inspector");
    const glm::ivec2 px = Inspector::hoverPixel(frames.renderer(), view);
    if (px.x < 0) {
        ImGui::TextDisabled("hover the image to inspect a pixel");
        return;
    }
    // B only while the split view shows B under the cursor (a stale tag once stayed in the grid).
    const bool onB = view.cursorOnB();
    ImGui::Text("pixel %d, %d%s", px.x, px.y, onB ? "  (B)" : "");
    const std::string prefix = onB ? "b." : "";
    for (const Resource* r : frames.renderer().buffers()) {
        std::string name = r->desc.name;
        if (!prefix.empty() && frames.renderer().graph().find(prefix + name)) name = prefix + name;
        const std::vector<float> v =
            referenceEmptyReason(frames, name).empty() ? inspector.valueAt(frames.renderer(), name, px) : std::vector<float>{};
        std::string text = v.empty() ? "         -" : ""; // no reference yet, or not computed in this view
        for (float x : v) {
            char buf[24];
            std::snprintf(buf, sizeof buf, "%10.4g", x);
            text += buf;
        }
        ImGui::Text("%-18s%s", name.c_str(), text.c_str()); // as many values as the buffer has channels
    }
    std::string error;
    const auto& pi = inspector.inspection(frames.renderer(), view, frames.interacting(), error);
    if (!error.empty()) frames.setShaderError(error);
    if (!pi) {
        ImGui::TextDisabled("the technique records no taps here");
        return;
    }
    if (!pi->geometry) {
        ImGui::TextDisabled("sky: no samples");
        return;
    }
    int counts[5] = {};
    for (const auto& t : pi->taps)
        ++counts[int(t.state)];
    char taps[200];
    std::snprintf(taps, sizeof taps, "%zu taps (GPU): %d open, %d occluded, %d off screen, %d behind eye, %d sky",
                  pi->taps.size(), counts[int(TapState::Open)], counts[int(TapState::Occluded)],
                  counts[int(TapState::Offscreen)], counts[int(TapState::BehindEye)], counts[int(TapState::Sky)]);
    wrappedText(taps);
    int band = 0;
    for (const auto& t : pi->taps)
        band += fromGuardBand(t);
    if (band > 0) ImGui::Text("%d of them off the frame, read from the guard band", band);
    int back = 0;
    for (const auto& t : pi->taps)
        back += t.backLayer;
    if (back > 0) ImGui::Text("%d of them took their solid's far side from the back-face layer (ringed)", back);
    int second = 0;
    for (const auto& t : pi->taps)
        second += t.secondLayer;
    if (second > 0) ImGui::Text("%d of them hid sectors with what the depth buffer hides, the second layer (squared)", second);
    ImGui::Text("occlusion %.3f / %.0f, radius %.4g units -> AO %.4f", pi->occlusion, pi->normaliser,
                pi->radius, pi->ao);
}

} // namespace

void drawInfoStrip(FrameDriver& frames, Inspector& inspector, ViewState& view, ImVec2 pos, ImVec2 size) {
    beginFixedWindow("info", pos, size, ImGuiWindowFlags_NoTitleBar);
    if (ImGui::BeginTable("info", 3, ImGuiTableFlags_BordersInnerV)) {
        ImGui::TableSetupColumn("timing", ImGuiTableColumnFlags_WidthStretch, 0.38f);
        ImGui::TableSetupColumn("reference", ImGuiTableColumnFlags_WidthStretch, 0.22f);
        ImGui::TableSetupColumn("inspector", ImGuiTableColumnFlags_WidthStretch, 0.40f);
        ImGui::TableNextColumn();
        timingSection(frames, view);
        ImGui::TableNextColumn();
        drawReferenceSection(frames, view);
        ImGui::TableNextColumn();
        inspectorSection(frames, inspector, view);
        ImGui::EndTable();
    }
    ImGui::End();
}

} // namespace ssao
