// The left panel: status, then tabs for the parameters (generated from the table), the scene and
// camera, presets and the front. Timing and the inspector live in the info strip under the image.
#include "scene/load/builtin_scenes.h"
#include "view/panels/ui_panels.h"
#include "view/panels/ui_layout.h"

#include <algorithm>
#include <cstring>
#include <functional>
#include <vector>

namespace ssao {

void rememberRect(ViewState& view, const std::string& key) {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    view.widgetRects[key] = ImVec4(a.x, a.y, b.x, b.y);
}

void rememberRect(UiActions& out, const std::string& key) {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    out.rects[key] = ImVec4(a.x, a.y, b.x, b.y);
}

void wrappedText(const std::string& text, bool disabled) {
    const float width = std::max(ImGui::GetContentRegionAvail().x, 40.0f);
    const MeasureText measure = [](const std::string& t) { return ImGui::CalcTextSize(t.c_str()).x; };
    bool over = false;
    if (disabled) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::BeginGroup();
    for (const std::string& line : wrapWords(text, width, measure)) {
        ImGui::TextUnformatted(line.c_str());
        over |= measure(line) > width;
    }
    ImGui::EndGroup();
    if (disabled) ImGui::PopStyleColor();
    if (over && ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 36.0f);
        ImGui::TextUnformatted(text.c_str());
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
}

namespace {

// Returns true when the text changed, or, with `enter`, when Enter was pressed.
bool inputText(const char* label, std::string& s, bool enter = false) {
    char buf[512];
    std::snprintf(buf, sizeof buf, "%s", s.c_str());
    const bool hit =
        ImGui::InputText(label, buf, sizeof buf, enter ? ImGuiInputTextFlags_EnterReturnsTrue : 0);
    s = buf;
    return hit;
}

// The scene's name, size and materials, and the transparent surfaces' toggle.
void sceneFacts(const Scene& sc, UiActions& out) {
    ImGui::TextWrapped("%s", sc.name.c_str());
    ImGui::TextDisabled("%zu triangles, bounding-box diagonal %.4g units", sc.triangleCount(),
                        2.0f * sc.bounds.radius());
    const MaterialCounts& mc = sc.materials;
    if (mc.mask + mc.blend > 0) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("materials: %zu opaque, %zu mask, %zu blend triangles", mc.opaque, mc.mask, mc.blend);
        if (mc.mask > 0)
            ImGui::TextWrapped("mask: cut out where alpha < cutoff (%zu textures, %.1f M pixels decoded in %.0f ms)",
                               mc.maskTextures, double(mc.maskPixels) / double(1 << 20), mc.maskDecodeMs);
        ImGui::PopStyleColor();
    }
    if (mc.blend > 0) {
        bool opaque = !mc.blendSkipped;
        if (ImGui::Checkbox("draw BLEND surfaces as opaque", &opaque))
            out.push(act::SetTransparent{opaque ? Transparent::Opaque : Transparent::Skip});
        rememberRect(out, "scene#transparent");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("off (default): BLEND and transmissive surfaces are skipped, as engines draw them after the AO -\n"
                              "neither in the G-buffer nor an occluder of the reference. On: drawn and traced as solids\n"
                              "(ssaolab --transparent opaque).");
    }
}

// A path to open, and the built-in scenes.
void sceneOpen(UiActions& out) {
    static std::string path;
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.7f);
    const bool enter = inputText("##scenepath", path, true);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("a .gltf/.glb path; Enter or Open loads it");
    ImGui::SameLine();
    if (ImGui::Button("Open") || enter) out.push(act::OpenScene{path});
    rememberRect(out, "scene#open");
    for (const auto& name : builtinSceneNames()) {
        if (ImGui::SmallButton(name.c_str())) out.push(act::OpenScene{"builtin:" + name});
        ImGui::SameLine();
    }
    ImGui::NewLine();
}

// Orbit or fly, the reset, and the cameras the scene file brings.
void cameraButtons(const CameraController& cc, const Scene& sc, UiActions& out) {
    int mode = cc.mode() == CameraController::Mode::Orbit ? 0 : 1;
    if (ImGui::RadioButton("Orbit", &mode, 0)) out.push(act::SetCameraMode{CameraController::Mode::Orbit});
    ImGui::SameLine();
    if (ImGui::RadioButton("Fly (WASD/QE)", &mode, 1)) out.push(act::SetCameraMode{CameraController::Mode::Fly});
    ImGui::SameLine();
    if (ImGui::Button("Reset view")) out.push(act::ResetCamera{});
    for (size_t i = 0; i < sc.cameras.size(); ++i) {
        if (ImGui::SmallButton(("cam: " + sc.cameras[i].first).c_str())) out.push(act::SelectSceneCamera{int(i)});
        ImGui::SameLine();
    }
    ImGui::NewLine();
}

// Clip planes, projection and depth, and the camera as rendered.
void cameraChoices(const CameraController& cc, const Scene& sc, const Camera& e, UiActions& out) {
    // One row of two choices; returns the one clicked this frame (-1: none). The second button's
    // tooltip explains the non-default choice.
    auto choice = [&](const char* label, int current, const char* a, const char* keyA, const char* b,
                      const char* keyB, const char* tip) {
        int v = current, clicked = -1;
        ImGui::TextUnformatted(label);
        ImGui::SameLine();
        if (ImGui::RadioButton(a, &v, 0)) clicked = 0;
        rememberRect(out, keyA);
        ImGui::SameLine();
        if (ImGui::RadioButton(b, &v, 1)) clicked = 1;
        rememberRect(out, keyB);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
        if (clicked >= 0) out.push(act::KeepAwake{});
        return clicked;
    };
    const int clip = choice("Clip planes", cc.camera().clip == ClipMode::Fit ? 0 : 1, "fit to scene",
                            "camera#clip_fit", "camera's own", "camera#clip_fixed",
                            "The planes the camera came with (a glTF file's znear/zfar); with standard depth a\n"
                            "far/near ratio of 1e7 makes the depth test z-fight into false AO.");
    if (clip >= 0) out.push(act::SetClip{clip == 0 ? ClipMode::Fit : ClipMode::Fixed});
    const int proj = choice("Projection ", cc.camera().orthographic() ? 1 : 0, "perspective", "camera#perspective",
                            "orthographic", "camera#orthographic",
                            "Parallel rays; the view spans what the field of view sees at the target's distance.");
    if (proj >= 0) out.push(act::SetProjection{proj == 0 ? Projection::Perspective : Projection::Orthographic});
    const int depth = choice("Depth      ", cc.camera().depth == DepthMode::Reversed ? 1 : 0, "standard",
                             "camera#depth_standard", "reversed-Z", "camera#depth_reversed",
                             "Float depth stored as 1 at near, 0 at far: even precision over any far/near\n"
                             "ratio, so a file's own 0.05 .. 1e6 planes no longer z-fight.");
    if (depth >= 0) out.push(act::SetDepth{depth == 0 ? DepthMode::Standard : DepthMode::Reversed});
    const Camera c = cameraToFile(cc.camera(), sc); // what --camera and presets take
    ImGui::TextDisabled("eye %.4g %.4g %.4g  target %.4g %.4g %.4g", c.eye.x, c.eye.y, c.eye.z, c.target.x,
                        c.target.y, c.target.z);
    ImGui::TextDisabled("fov %.0f  near %.4g  far %.4g (as rendered)%s", e.fovYDeg, e.nearZ, e.farZ,
                        e.orthographic() ? "; view height = 2 |target - eye| tan(fov/2)" : "");
}

} // namespace

// What replaces the scene (opening one, the transparent toggle) is an action applied after the tab:
// `in.scene` and what points into it outlive every widget drawn from them.
void drawSceneTab(const SceneView& in, UiActions& out) {
    sceneFacts(in.scene, out);
    sceneOpen(out);
    ImGui::Separator();
    cameraButtons(in.camera, in.scene, out);
    cameraChoices(in.camera, in.scene, in.rendered, out);
}

namespace {

// One row of the preset list, two lines tall: the name, and under it the description cut at a word
// (the whole of it on hover). Double-click loads it.
void presetRow(const PresetsView& in, const PresetEntry& e, const std::string& description, std::string& selected,
               UiActions& out) {
    const float line = ImGui::GetTextLineHeightWithSpacing();
    std::string name = (e.builtin ? "[shipped] " : "") + e.name;
    if (e.name == in.loaded.name) name += in.unsaved ? "  (loaded, changed)" : "  (loaded)";
    ImGui::PushID(e.path.c_str());
    if (ImGui::Selectable("##preset", selected == e.name, ImGuiSelectableFlags_AllowDoubleClick,
                          ImVec2(0, 2.0f * line - ImGui::GetStyle().ItemSpacing.y)))
        selected = e.name;
    ImGui::PopID();
    rememberRect(out, "preset#" + e.name);
    const bool hovered = ImGui::IsItemHovered();
    if (hovered && ImGui::IsMouseDoubleClicked(0)) out.push(act::OpenPreset{e.name});
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    const MeasureText measure = [](const std::string& t) { return ImGui::CalcTextSize(t.c_str()).x; };
    bool cut = false;
    const std::string shown = fitLine(description.empty() ? "(no description)" : description, b.x - a.x, measure, &cut);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddText(a, ImGui::GetColorU32(ImGuiCol_Text), name.c_str());
    const ImVec2 d(a.x, a.y + line);
    dl->AddText(d, ImGui::GetColorU32(ImGuiCol_TextDisabled), shown.c_str());
    out.rects["preset#" + e.name + "#description"] =
        ImVec4(d.x, d.y, d.x + ImGui::CalcTextSize(shown.c_str()).x, d.y + ImGui::GetTextLineHeight());
    if (hovered && !description.empty()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 36.0f);
        ImGui::TextUnformatted(description.c_str());
        ImGui::PopTextWrapPos();
        ImGui::TextDisabled("double-click: load");
        ImGui::EndTooltip();
    }
}

} // namespace

void drawPresetsTab(const PresetsView& in, UiActions& out) {
    const PresetStore& store = in.store;
    const std::string current = in.loaded.name + (in.unsaved ? " (unsaved changes)" : "");
    ImGui::Text("current: %s", current.c_str());
    static std::string selected;
    const PresetEntry* sel = store.find(selected);
    ImGui::BeginDisabled(!sel);
    if (ImGui::Button("Load")) out.push(act::OpenPreset{selected});
    rememberRect(out, "preset#load");
    ImGui::SameLine();
    ImGui::BeginDisabled(!sel || sel->builtin);
    if (ImGui::Button("Rename to name")) out.push(act::RenamePreset{selected, in.newName});
    rememberRect(out, "preset#rename");
    ImGui::SameLine();
    if (ImGui::Button("Delete")) out.push(act::DeletePreset{selected});
    rememberRect(out, "preset#delete");
    ImGui::EndDisabled();
    ImGui::EndDisabled();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
    std::string newName = in.newName;
    inputText("name##newpreset", newName);
    if (newName != in.newName) out.push(act::SetNewPresetName{newName});
    rememberRect(out, "preset#name");
    ImGui::SameLine();
    if (ImGui::Button("Save")) out.push(act::SavePreset{newName});
    rememberRect(out, "preset#save");
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("A saved preset keeps the settings, the scene, the view size and the camera;\n"
                          "`ssaolab render --preset NAME` renders it headless.\nuser presets: %s",
                          store.userDir().c_str());
    // Every preset, the rest of the tab tall: the user's own first (what one reloads most), then
    // the shipped ones (the seeds' reproductions and the tuned technique-quality presets).
    const float height = std::max(ImGui::GetContentRegionAvail().y, 6.0f * ImGui::GetTextLineHeightWithSpacing());
    if (ImGui::BeginChild("##presets", ImVec2(0, height), true)) {
        for (bool builtin : {false, true})
            for (size_t i = 0; i < store.entries().size(); ++i)
                if (store.entries()[i].builtin == builtin)
                    presetRow(in, store.entries()[i], in.descriptions[i], selected, out);
    }
    ImGui::EndChild();
    rememberRect(out, "preset#list");
}

namespace {

// The panel's tabs as a row of buttons: ImGui's tab bar draws a tab only from the frame after it
// first appears, so the first frame had none; buttons are laid out on the frame they are submitted.
void tabStrip(int current, const std::vector<const char*>& names, UiActions& out) {
    const ImGuiStyle& st = ImGui::GetStyle();
    for (size_t i = 0; i < names.size(); ++i) {
        if (i > 0) ImGui::SameLine(0.0f, st.ItemInnerSpacing.x);
        const bool on = current == int(i);
        ImGui::PushStyleColor(ImGuiCol_Button, st.Colors[on ? ImGuiCol_TabActive : ImGuiCol_Tab]);
        ImGui::PushStyleColor(ImGuiCol_ButtonHovered, st.Colors[ImGuiCol_TabHovered]);
        ImGui::PushStyleColor(ImGuiCol_ButtonActive, st.Colors[ImGuiCol_TabActive]);
        if (ImGui::Button(names[i])) out.push(act::SelectTab{int(i)});
        ImGui::PopStyleColor(3);
        rememberRect(out, std::string("tab#") + names[i]);
    }
    ImGui::PushStyleColor(ImGuiCol_Separator, st.Colors[ImGuiCol_TabActive]);
    ImGui::Separator();
    ImGui::PopStyleColor();
}

} // namespace

void beginFixedWindow(const char* name, ImVec2 pos, ImVec2 size, ImGuiWindowFlags extra) {
    // The layout is computed from the window size each frame: nothing to move, resize or persist.
    // No background: each would be a blended quad over its whole window, the whole screen in all,
    // drawn under the views' images again, every frame; the clear paints it instead.
    ImGui::SetNextWindowPos(pos);
    ImGui::SetNextWindowSize(size);
    ImGui::Begin(name, nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBackground | extra);
}

void clearUiBackground() {
    const ImVec4 bg = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
    glClearColor(bg.x, bg.y, bg.z, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
}

void beginControlPanel(const PanelHeader& in, ImVec2 pos, ImVec2 size, UiActions& out) {
    // The scrollbar always: ImGui adds it on the frame after it learns the content is taller, and the
    // first frame's widgets were wider than every later frame's.
    beginFixedWindow("ssaolab", pos, size, ImGuiWindowFlags_AlwaysVerticalScrollbar);
    out.rects["panel"] = ImVec4(pos.x, pos.y, pos.x + size.x, pos.y + size.y);
    // The status has a fixed height (three lines, scrolled if longer): the widgets below never move.
    ImGui::BeginChild("status", ImVec2(0, ImGui::GetTextLineHeightWithSpacing() * 3.0f), false);
    ImGui::PushStyleColor(ImGuiCol_Text,
                          in.statusIsError ? ImVec4(1, 0.4f, 0.4f, 1) : ImVec4(0.6f, 0.9f, 0.6f, 1));
    wrappedText(in.status);
    rememberRect(out, "status");
    ImGui::PopStyleColor();
    ImGui::EndChild();
    if (ImGui::IsItemHovered()) { // the whole status, also when it runs past its three lines
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 36.0f);
        ImGui::TextUnformatted(in.status.c_str());
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
    if (!in.shaderError.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.4f, 0.4f, 1));
        ImGui::TextWrapped("shader error (last good shaders still running):\n%s", in.shaderError.c_str());
        ImGui::PopStyleColor();
    }
    tabStrip(in.tab, {"Parameters", "Scene & camera", "Presets", "Front"}, out);
}

} // namespace ssao
