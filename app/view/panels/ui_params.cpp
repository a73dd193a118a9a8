// The parameter panel, generated from the parameter table: one widget per row, greyed out when the
// row does not apply (e.g. sigma unless the gaussian denoiser is chosen) and hidden when it belongs
// to a technique other than the chosen one, with the radius shown in world units and pixels under
// the AO group.
#include "settings/params.h"
#include "techniques/technique.h"
#include "view/panels/ui_panels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace ssao {

namespace {

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

// What '*' and R compare with: the preset loaded last (its values, not the table's defaults, are
// where a user starts from), or the table's defaults when none was.
std::string baselineName(const Preset& loaded) {
    const std::string& n = loaded.name;
    return n == "defaults" ? "the table's defaults" : "preset " + n;
}

void tooltip(const Param& p, bool applies, const Preset& loaded, bool changed) {
    if (!ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) return;
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
    ImGui::TextUnformatted(p.help.c_str());
    ImGui::TextDisabled("%s   range %s   default %s", p.key.c_str(), rangeText(p).c_str(),
                        p.format(p.def).c_str());
    if (!p.when.empty())
        ImGui::TextColored(applies ? ImVec4(0.6f, 0.6f, 0.6f, 1) : ImVec4(1, 0.75f, 0.3f, 1),
                           "applies when %s", p.whenText().c_str());
    if (loaded.name == "defaults" || loaded.keys.count(p.key))
        ImGui::TextDisabled("%s %s, where it is %s (R resets to it)", changed ? "* : changed from" : "as in",
                            baselineName(loaded).c_str(), p.format(p.get(loaded.settings)).c_str());
    else // the preset does not set it: its value is the default
        ImGui::TextDisabled("%s the default %s (R resets to it; %s does not set it)", changed ? "* : changed from" : "as",
                            p.format(p.get(loaded.settings)).c_str(), baselineName(loaded).c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

// One widget for one parameter, on the panel's copy `s` of the settings (the rows after it see the
// change this frame); a change is asked for as SetParam.
void paramWidget(const Preset& loaded, const Param& p, Settings& s, UiActions& out) {
    ImGui::PushID(p.key.c_str());
    const double before = p.get(s);
    const double base = p.get(loaded.settings);
    const bool changed = before != base;
    const bool applies = p.applies(s);
    const float resetWidth = ImGui::GetFrameHeight() * 1.6f;
    ImGui::BeginDisabled(!applies);
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.62f - resetWidth);
    // * marks a value changed against the loaded preset; "###key" keeps the widget's ID stable when
    // the * appears, or the first change of a drag would end the drag.
    const std::string label = p.label + (changed ? " *" : "") + "###" + p.key;
    bool slider = false;
    std::optional<double> to; // the value set this frame
    switch (p.type) {
    case Param::Type::Float: {
        float v = float(before);
        // Ranges spanning decades (radius, bias) get a logarithmic slider.
        ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp;
        if (p.max > 100.0 * std::max(p.min, 1e-3)) flags |= ImGuiSliderFlags_Logarithmic;
        std::string fmt = "%.4g" + (p.unit.empty() ? std::string() : " " + p.unit);
        if (ImGui::SliderFloat(label.c_str(), &v, float(p.min), float(p.max), fmt.c_str(), flags))
            to = v;
        slider = true;
        break;
    }
    case Param::Type::Int: {
        int v = int(before);
        ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp;
        if (p.max > 1000) flags |= ImGuiSliderFlags_Logarithmic;
        if (ImGui::SliderInt(label.c_str(), &v, int(p.min), int(p.max), "%d", flags)) to = v;
        slider = true;
        break;
    }
    case Param::Type::Bool: {
        bool v = before != 0.0;
        if (ImGui::Checkbox(label.c_str(), &v)) to = v ? 1 : 0;
        break;
    }
    case Param::Type::Enum: {
        if (ImGui::BeginCombo(label.c_str(), p.choices[size_t(before)].c_str())) {
            for (size_t i = 0; i < p.choices.size(); ++i) {
                if (ImGui::Selectable(p.choices[i].c_str(), size_t(before) == i)) to = double(i);
                rememberRect(out, p.key + "#" + p.choices[i]);
            }
            ImGui::EndCombo();
        }
        break;
    }
    }
    // Dragging a slider renders at the interactive scale until it is released (N8AO does this).
    if (slider && ImGui::IsItemActive()) out.push(act::NoteInteraction{});
    rememberRect(out, p.key);
    if (changed) rememberRect(out, "changed#" + p.key);
    ImGui::EndDisabled();
    tooltip(p, applies, loaded, changed);
    ImGui::SameLine();
    ImGui::BeginDisabled(!changed || !applies);
    if (ImGui::Button("R", ImVec2(resetWidth, 0))) to = base;
    ImGui::EndDisabled();
    rememberRect(out, p.key + "#reset");
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("reset to %s, the value of %s (what * compares with)", p.format(base).c_str(),
                          baselineName(loaded).c_str());
    ImGui::PopID();
    if (!to) return;
    p.set(s, *to);
    out.push(act::SetParam{p.key, *to});
    if (p.get(s) != before) out.push(act::KeepAwake{});
}

// One line that never wraps, so the rows below keep their place whatever it says.
void radiusLine(const ParamsView& in, UiActions& out) {
    if (!in.radius || !in.viewRadius) {
        ImGui::TextDisabled("radius: shown after the first frame");
    } else {
        const RadiusInfo& ri = *in.radius;
        const ViewRadiusCheck& vr = *in.viewRadius;
        const bool tiny = ri.pixels<2.0f, huge = ri.world> 0.25f * ri.sceneDiagonal;
        const ImVec4 colour = tiny || huge || vr.tooLarge ? ImVec4(1, 0.7f, 0.3f, 1)
                                                          : ImGui::GetStyle().Colors[ImGuiCol_TextDisabled];
        ImGui::TextColored(colour, "= %.4g units, %.*f px at centre (diag %.4g)%s", ri.world, ri.pixels < 100 ? 1 : 0,
                           ri.pixels, ri.sceneDiagonal,
                           tiny          ? " SUB-PIXEL: flat AO"
                           : huge        ? " >25%% OF SCENE"
                           : vr.tooLarge ? " TOO WIDE"
                                         : "");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "The AO radius in scene units and in pixels at the centre of the view; the scene's\n"
                "bounding-box diagonal. Under 2 pixels the kernel sees nothing: AO goes flat grey.");
        rememberRect(out, "radius#info");
        if (vr.tooLarge) { // a line of its own only then: the hint of the status, applied in one click
            char label[96];
            std::snprintf(label, sizeof label, "use the view's radius: %.3g world units", vr.suggested);
            if (ImGui::SmallButton(label)) {
                out.push(act::UseViewRadius{});
                out.push(act::KeepAwake{});
            }
            rememberRect(out, "radius#use_view");
            if (ImGui::IsItemHovered()) {
                ImGui::BeginTooltip();
                ImGui::PushTextWrapPos(ImGui::GetFontSize() * 36.0f);
                ImGui::TextUnformatted(vr.message().c_str());
                ImGui::PopTextWrapPos();
                ImGui::EndTooltip();
            }
        }
        return;
    }
    rememberRect(out, "radius#info");
}

} // namespace

// A row of a technique that is not the chosen one: hidden, not greyed (four techniques' rows
// would bury the ones that matter).
static bool otherTechnique(const Param& p, const Settings& s) {
    if (p.when.empty() || p.when.front().key != "ao.technique") return false;
    const auto& ids = p.when.front().values;
    return std::find(ids.begin(), ids.end(), s.ao.technique) == ids.end();
}

// A group's heading: a technique's rows under its id and label, its summary on hover (a user
// technique's from its file's header).
static void groupHeading(const std::string& group) {
    for (const TechniqueInfo& t : techniques())
        if (t.id == group && t.label != t.id) {
            ImGui::TextDisabled("%s - %s", group.c_str(), t.label.c_str());
            if (ImGui::IsItemHovered() && !t.summary.empty()) ImGui::SetTooltip("%s", t.summary.c_str());
            return;
        }
    ImGui::TextDisabled("%s", group.c_str());
}

void drawParameters(const ParamsView& in, UiActions& out) {
    std::string group;
    Settings s = in.settings; // the rows' working copy: what the app's settings become once applied
    for (const Param& p : paramTable()) {
        if (otherTechnique(p, s)) continue;
        if (p.group() != group) {
            if (group == "ao") radiusLine(in, out);
            group = p.group();
            ImGui::Spacing();
            groupHeading(group);
            ImGui::Separator();
        }
        paramWidget(in.loaded, p, s, out);
    }
}

} // namespace ssao
