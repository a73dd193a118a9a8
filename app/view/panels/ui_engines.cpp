// The Front tab's web engines (front/engine_front.h): a switch, one line of state (how far they
// are, or why they are off), a row per engine point - its AO time and error against the current
// setting's, "A|B" (its AO frame in Split B) and "copy snippet" (its settings for this view as
// JavaScript for the engine's API) - and where tuned settings come from.
#include "view/panels/ui_panels.h"
#include "view/panels/ui_layout.h"

#include <cstdio>
#include <cstring>

namespace ssao {

namespace {

const char* const kEnginesHelp =
    "three.js SSAOPass, SAOPass and GTAOPass, N8AO, postprocessing's SSAOEffect, Babylon.js's\n"
    "SSAO2RenderingPipeline and SSAORenderingPipeline, PlayCanvas's CameraFrame SSAO and\n"
    "Filament's AO (web build), run for real in Chromium (Node.js\n"
    "and the npm packages `make engine-modules` pins) on this glTF file at this view's camera,\n"
    "size and R, once ssaolab's candidates are measured. Each engine as its package ships it,\n"
    "at its defaults with every length from R (as `make peers` runs it), and each\n"
    "`ssaolab tune --engine NAME --out FILE.json`\n"
    "result in the tuned folder below or added by path: its fit applied to this view (a knob\n"
    "tuned relative to R scales with this view's R), as tune scores its held-out views.\n"
    "The AO is scored against the same reference as every point. Time: the browser's frame\n"
    "with the pass minus the frame without (median of 5 frames), not a GPU timer query.\n"
    "copy snippet: the settings it ran with here, as JavaScript for the engine's API.";

// The engine point labelled so, as the front's answers pass candidates on.
Candidate engineCandidate(const std::string& label) {
    Candidate c;
    c.label = label;
    c.origin = "engine";
    return c;
}

// One engine point: its numbers against the current setting's, and its two actions.
void engineRow(const EngineSample& s, const FrontPoint* cur, UiActions& out) {
    const std::string& label = s.candidate.label;
    char ms[32] = "time under the browser's timer";
    if (s.aoMs > 0) std::snprintf(ms, sizeof ms, "%.2f ms", s.aoMs);
    char b[320];
    std::snprintf(b, sizeof b, "%s: %s, RMSE %.4f", label.c_str(), ms, s.error.rmse);
    std::string text = b;
    if (cur && cur->result.gpuMs > 0 && cur->result.error.rmse > 0 && s.aoMs > 0) {
        std::snprintf(b, sizeof b, " (%.2fx, %.2fx current)", s.aoMs / cur->result.gpuMs, s.error.rmse / cur->result.error.rmse);
        text += b;
    }
    ImGui::PushID(label.c_str());
    wrappedText(text);
    if (ImGui::SmallButton("A|B")) out.push(act::CompareCandidate{engineCandidate(label)});
    rememberRect(out, "front#engine_compare:" + label);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Split A|B: the current setting's AO against this engine's AO frame");
    ImGui::SameLine();
    if (ImGui::SmallButton("copy snippet")) {
        ImGui::SetClipboardText(s.snippet.c_str());
        out.push(act::SetStatus{"copied the settings of " + label + " for this view as JavaScript (" + s.title + ")", false});
    }
    rememberRect(out, "front#engine_snippet:" + label);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", s.snippet.c_str());
    ImGui::PopID();
}

// Tuned settings by path: a `tune --engine --out` file joins the engines' candidates.
// The field is ViewState::engineFile (`file`); "add" asks for AddEngineFile.
void addTunedFile(const std::string& file, UiActions& out) {
    char buf[512];
    std::snprintf(buf, sizeof buf, "%s", file.c_str());
    ImGui::SetNextItemWidth(std::max(ImGui::GetContentRegionAvail().x - 60.0f, 80.0f));
    const bool enter = ImGui::InputText("##engine_file", buf, sizeof buf, ImGuiInputTextFlags_EnterReturnsTrue);
    const std::string typed = buf;
    if (typed != file) out.push(act::SetEngineFile{typed});
    rememberRect(out, "front#engine_file");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("a tuned settings file (ssaolab tune --engine NAME --out FILE.json)");
    ImGui::SameLine();
    if ((ImGui::SmallButton("add") || enter) && !typed.empty()) out.push(act::AddEngineFile{typed});
    rememberRect(out, "front#engine_add");
}

} // namespace

void drawEngineSection(const FrontTabView& in, FrontPanel::Axis axis, UiActions& out) {
    const FrontPanel& f = in.front;
    const EngineFront& e = f.engines();
    ImGui::Separator();
    bool enabled = e.enabled;
    if (ImGui::Checkbox("engines", &enabled)) out.push(act::SetEnginesOn{enabled}), out.push(act::KeepAwake{});
    rememberRect(out, "front#engines_on");
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", kEnginesHelp);
    std::string line = e.status();
    if (line.empty() && enabled && f.waiting().empty() && f.measurer().busy())
        line = "engines: after ssaolab's candidates";
    if (line.empty() && enabled && axis == FrontPanel::Axis::Motion)
        line = "engines: on the still axis (a frame each, no motion score)";
    if (!line.empty()) {
        wrappedText(line, !e.off());
        rememberRect(out, "front#engines");
    }
    if (e.off() || !enabled) return;
    const size_t ci = f.currentIndex();
    const FrontPoint* cur = ci == std::string::npos ? nullptr : &f.points()[ci];
    for (const auto& s : e.samples())
        engineRow(*s, cur, out);
    for (const std::string& err : e.errors())
        wrappedText(err);
    for (const std::string& err : e.tunedErrors())
        wrappedText(err, true);
    wrappedText("tuned settings: the tune --engine --out files in " + FrontPanel::tunedDir(in.store) +
                    ", and files added here:",
                true);
    if (ImGui::SmallButton("rescan")) out.push(act::RescanEngines{}), out.push(act::KeepAwake{});
    rememberRect(out, "front#engine_rescan");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("read the tuned settings folder again (a tune run since the view was measured)");
    addTunedFile(in.engineFile, out);
}

} // namespace ssao
