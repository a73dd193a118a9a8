// The left panel: scene & camera, presets, every parameter (generated from the table), timing,
// and the pixel / sample inspector.
#include "scene/builtin_scenes.h"
#include "settings/params.h"
#include "view/app_core.h"

#include <cmath>
#include <cstring>

namespace ssao {

namespace {

void remember(AppCore& app, const std::string& key) {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    app.widgetRects[key] = ImVec4(a.x, a.y, b.x, b.y);
}

bool inputText(const char* label, std::string& s) {
    char buf[512];
    std::snprintf(buf, sizeof buf, "%s", s.c_str());
    bool changed = ImGui::InputText(label, buf, sizeof buf);
    if (changed) s = buf;
    return changed;
}

std::string rangeText(const Param& p) {
    if (p.type == Param::Type::Enum) {
        std::string r;
        for (auto& c : p.choices)
            r += (r.empty() ? "" : " | ") + c;
        return r;
    }
    if (p.type == Param::Type::Bool) return "on | off";
    return "[" + p.format(p.min) + ", " + p.format(p.max) + "]" + (p.unit.empty() ? "" : " " + p.unit);
}

void tooltip(const Param& p) {
    if (!ImGui::IsItemHovered()) return;
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
    ImGui::TextUnformatted(p.help.c_str());
    ImGui::TextDisabled("%s   range %s   default %s", p.key.c_str(), rangeText(p).c_str(),
                        p.format(p.def).c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

// One widget for one parameter; returns true when the value changed.
bool paramWidget(AppCore& app, const Param& p, Settings& s) {
    ImGui::PushID(p.key.c_str());
    const double before = p.get(s);
    const float resetWidth = ImGui::GetFrameHeight() * 1.6f;
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.62f - resetWidth);
    const std::string label = p.label + (p.isDefault(s) ? "" : " *"); // * marks a changed value
    switch (p.type) {
    case Param::Type::Float: {
        float v = float(before);
        // Ranges spanning decades (radius, bias) get a logarithmic slider.
        ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp;
        if (p.max > 100.0 * std::max(p.min, 1e-3)) flags |= ImGuiSliderFlags_Logarithmic;
        std::string fmt = "%.4g" + (p.unit.empty() ? std::string() : " " + p.unit);
        if (ImGui::SliderFloat(label.c_str(), &v, float(p.min), float(p.max), fmt.c_str(), flags))
            p.set(s, v);
        break;
    }
    case Param::Type::Int: {
        int v = int(before);
        ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp;
        if (p.max > 1000) flags |= ImGuiSliderFlags_Logarithmic;
        if (ImGui::SliderInt(label.c_str(), &v, int(p.min), int(p.max), "%d", flags)) p.set(s, v);
        break;
    }
    case Param::Type::Bool: {
        bool v = before != 0.0;
        if (ImGui::Checkbox(label.c_str(), &v)) p.set(s, v ? 1 : 0);
        break;
    }
    case Param::Type::Enum: {
        if (ImGui::BeginCombo(label.c_str(), p.choices[size_t(before)].c_str())) {
            for (size_t i = 0; i < p.choices.size(); ++i) {
                if (ImGui::Selectable(p.choices[i].c_str(), size_t(before) == i)) p.set(s, double(i));
                remember(app, p.key + "#" + p.choices[i]);
            }
            ImGui::EndCombo();
        }
        break;
    }
    }
    remember(app, p.key);
    tooltip(p);
    ImGui::SameLine();
    ImGui::BeginDisabled(p.isDefault(s));
    if (ImGui::Button("R", ImVec2(resetWidth, 0))) p.set(s, p.def);
    ImGui::EndDisabled();
    remember(app, p.key + "#reset");
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("reset to %s", p.format(p.def).c_str());
    ImGui::PopID();
    return p.get(s) != before;
}

void sceneSection(AppCore& app) {
    const Scene& sc = app.scene();
    ImGui::TextWrapped("%s  (%zu triangles)", sc.name.c_str(), sc.triangleCount());
    static std::string path;
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.7f);
    inputText("##scenepath", path);
    ImGui::SameLine();
    if (ImGui::Button("Open")) app.openScene(path);
    remember(app, "scene#open");
    for (const auto& name : builtinSceneNames()) {
        if (ImGui::SmallButton(name.c_str())) app.openScene("builtin:" + name);
        ImGui::SameLine();
    }
    ImGui::NewLine();
    CameraController& cc = app.cameraController();
    int mode = cc.mode() == CameraController::Mode::Orbit ? 0 : 1;
    if (ImGui::RadioButton("Orbit", &mode, 0)) cc.setMode(CameraController::Mode::Orbit);
    ImGui::SameLine();
    if (ImGui::RadioButton("Fly (WASD/QE)", &mode, 1)) cc.setMode(CameraController::Mode::Fly);
    ImGui::SameLine();
    if (ImGui::Button("Reset view")) app.resetCamera();
    for (size_t i = 0; i < sc.cameras.size(); ++i) {
        if (ImGui::SmallButton(("cam: " + sc.cameras[i].first).c_str())) app.selectSceneCamera(int(i));
        ImGui::SameLine();
    }
    ImGui::NewLine();
    const Camera& c = cc.camera();
    ImGui::TextDisabled("eye %.3g %.3g %.3g  fov %.0f  near %.3g far %.3g", c.eye.x, c.eye.y, c.eye.z,
                        c.fovYDeg, c.nearZ, c.farZ);
}

void presetSection(AppCore& app) {
    PresetStore& store = app.presets();
    const std::string current = app.loadedPreset().name + (app.unsavedChanges() ? " (unsaved changes)" : "");
    ImGui::Text("current: %s", current.c_str());
    static std::string selected;
    if (ImGui::BeginListBox("##presets", ImVec2(-1, ImGui::GetTextLineHeightWithSpacing() * 7))) {
        for (const auto& e : store.entries()) {
            std::string label = (e.builtin ? "[seed] " : "") + e.name;
            if (e.name == app.loadedPreset().name && app.unsavedChanges()) label += " *";
            if (ImGui::Selectable(label.c_str(), selected == e.name)) selected = e.name;
            if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(0)) app.openPreset(e.name);
            remember(app, "preset#" + e.name);
        }
        ImGui::EndListBox();
    }
    const PresetEntry* sel = store.find(selected);
    ImGui::BeginDisabled(!sel);
    if (ImGui::Button("Load")) app.openPreset(selected);
    remember(app, "preset#load");
    ImGui::SameLine();
    ImGui::BeginDisabled(!sel || sel->builtin);
    if (ImGui::Button("Rename to name")) app.renamePreset(selected, app.newPresetName);
    remember(app, "preset#rename");
    ImGui::SameLine();
    if (ImGui::Button("Delete")) app.deletePreset(selected);
    remember(app, "preset#delete");
    ImGui::EndDisabled();
    ImGui::EndDisabled();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
    inputText("name##newpreset", app.newPresetName);
    remember(app, "preset#name");
    ImGui::SameLine();
    if (ImGui::Button("Save")) app.savePreset(app.newPresetName);
    remember(app, "preset#save");
    ImGui::TextDisabled("user presets: %s", store.userDir().c_str());
}

void timingSection(AppCore& app) {
    double total = 0;
    if (ImGui::BeginTable("timing", 2, ImGuiTableFlags_SizingStretchProp)) {
        for (const auto& [name, t] : app.timings()) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(name.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%.3f ms (avg of %zu runs)", t.average(), t.ms.size());
            total += t.average();
        }
        ImGui::EndTable();
    }
    ImGui::Text("all passes: %.3f ms GPU", total);
    std::vector<float> f(app.frameMs().begin(), app.frameMs().end());
    if (!f.empty()) {
        ImGui::PlotLines("frame ms", f.data(), int(f.size()), 0, nullptr, 0.0f, FLT_MAX, ImVec2(-1, 50));
        ImGui::TextDisabled("last frame %.2f ms (CPU, UI included); idle frames are not drawn", f.back());
    }
    std::string ran;
    for (auto& n : app.lastReport().ran())
        ran += n + " ";
    ImGui::TextDisabled("last change re-ran: %s", ran.c_str());
}

void inspectorSection(AppCore& app) {
    ImGui::Checkbox("Show samples at cursor", &app.showSamples);
    ImGui::SameLine();
    ImGui::Checkbox("Pin pixel", &app.pinPixel);
    const glm::ivec2 px = app.hoverPixel;
    if (px.x < 0) {
        ImGui::TextDisabled("hover the image to inspect a pixel");
        return;
    }
    ImGui::Text("pixel %d, %d", px.x, px.y);
    for (int i = 0; i < kBufferCount; ++i) {
        const glm::vec4 v = app.texelOf(BufferId(i), px.x, px.y);
        ImGui::Text("%-9s %9.4g %9.4g %9.4g %9.4g", bufferName(BufferId(i)), v.x, v.y, v.z, v.w);
    }
    const PixelInspection& pi = app.inspection();
    if (!pi.geometry) {
        ImGui::TextDisabled("sky: no samples");
        return;
    }
    int counts[5] = {};
    for (const auto& t : pi.taps)
        ++counts[int(t.state)];
    ImGui::Text("%zu taps: %d open, %d occluded, %d off screen, %d behind eye, %d sky", pi.taps.size(),
                counts[0], counts[1], counts[3], counts[2], counts[4]);
    ImGui::Text("AO replayed on CPU %.4f (ao_raw %.4f)", pi.ao, app.texelOf(BufferId::AoRaw, px.x, px.y).x);
}

} // namespace

void drawControlPanel(AppCore& app, ImVec2 pos, ImVec2 size) {
    ImGui::SetNextWindowPos(pos);
    ImGui::SetNextWindowSize(size);
    ImGui::Begin("ssaolab", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings);
    if (!app.status().empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text,
                              app.statusIsError() ? ImVec4(1, 0.4f, 0.4f, 1) : ImVec4(0.6f, 0.9f, 0.6f, 1));
        ImGui::TextWrapped("%s", app.status().c_str());
        ImGui::PopStyleColor();
    }
    if (!app.shaderError().empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.4f, 0.4f, 1));
        ImGui::TextWrapped("shader error (last good shaders still running):\n%s", app.shaderError().c_str());
        ImGui::PopStyleColor();
    }
    if (ImGui::CollapsingHeader("Scene & camera", ImGuiTreeNodeFlags_DefaultOpen)) sceneSection(app);
    if (ImGui::CollapsingHeader("Presets", ImGuiTreeNodeFlags_DefaultOpen)) presetSection(app);
    if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) {
        std::string group;
        for (const Param& p : paramTable()) {
            if (p.group() != group) {
                group = p.group();
                ImGui::Spacing();
                ImGui::TextDisabled("%s", group.c_str());
                ImGui::Separator();
            }
            if (paramWidget(app, p, app.settings())) app.poke();
        }
    }
    if (ImGui::CollapsingHeader("GPU timing", ImGuiTreeNodeFlags_DefaultOpen)) timingSection(app);
    if (ImGui::CollapsingHeader("Inspector", ImGuiTreeNodeFlags_DefaultOpen)) inspectorSection(app);
    ImGui::End();
}

} // namespace ssao
