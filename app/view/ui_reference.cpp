// The "vs reference" block of the info strip: the ray-traced reference's progress (rays per pixel
// so far, or why it waits) and the error of ao.denoised against it, next to the timings.
#include "view/app_core.h"

#include <cmath>
#include <cstdio>

namespace ssao {

namespace {

using State = LiveReference::State;

void row(const char* name, const char* tip, const char* fmt, double v) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(name);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
    ImGui::TableNextColumn();
    if (std::isfinite(v))
        ImGui::Text(fmt, v);
    else
        ImGui::TextDisabled("-"); // e.g. no edge pixels in view: no value, not 0
}

void progressLine(const LiveReference::Status& s) {
    char text[96];
    switch (s.state) {
    case State::Off:
        break;
    case State::Waiting:
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
        ImGui::TextWrapped("view changed: waiting for the camera to settle");
        ImGui::PopStyleColor();
        break;
    case State::Starting:
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
        ImGui::TextWrapped("(re)starting: BVH and primary rays...");
        ImGui::PopStyleColor();
        break;
    case State::Tracing:
        std::snprintf(text, sizeof text, "%d / %d rays per pixel", s.rays, s.target);
        ImGui::ProgressBar(float(s.fraction), ImVec2(-1, 0), text);
        break;
    case State::Done:
        ImGui::Text("%d rays per pixel (done)", s.rays);
        break;
    case State::Failed:
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.4f, 0.4f, 1));
        ImGui::TextWrapped("failed: %s", s.error.c_str());
        ImGui::PopStyleColor();
        break;
    }
}

// The error split (live_reference.h): what settings can still fix against what the depth buffer
// does not hold. The two need not add up: RMSEs of two differences, not a sum of squares.
void splitSection(const LiveReference& ref) {
    const auto& sp = ref.split();
    if (!sp) {
        const double f = ref.oracleFraction();
        if (f > 0 && f < 1) {
            char text[96];
            std::snprintf(text, sizeof text, "screen-space oracle %.0f%%", 100 * f);
            ImGui::ProgressBar(float(f), ImVec2(-1, 0), text);
        }
        return;
    }
    // One line, so the strip's height holds it; the rest on hover.
    ImGui::Text("split: technique %.4f  screen %.4f", sp->technique.rmse, sp->screen.rmse);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("RMSE of ao.denoised against the screen-space oracle (technique: what settings can\n"
                          "still fix) and of the oracle against the reference (screen: what the depth buffer\n"
                          "does not hold - back faces, hidden and off-screen occluders, true thickness).\n"
                          "The oracle: the same integral and R, visibility decided by the depth buffer alone\n"
                          "(surfaces 1 R thick).\n\n"
                          "            technique   screen\n"
                          "RMSE        %.4f      %.4f\n"
                          "bias        %+.4f     %+.4f\n"
                          "edge        %.4f      %.4f\n"
                          "interior    %.4f      %.4f",
                          sp->technique.rmse, sp->screen.rmse, sp->technique.bias, sp->screen.bias,
                          sp->technique.rmseEdge, sp->screen.rmseEdge, sp->technique.rmseInterior,
                          sp->screen.rmseInterior);
}

} // namespace

std::string referenceTag(const FrameDriver& frames) {
    const LiveReference::Status s = frames.reference().status();
    char buf[64] = "";
    if (s.rays > 0) std::snprintf(buf, sizeof buf, "  %d/%d rays", s.rays, s.target);
    return buf;
}

std::string referenceEmptyReason(const FrameDriver& frames, const std::string& buffer) {
    if (buffer.rfind("reference.", 0) != 0) return "";
    const LiveReference::Status s = frames.reference().status();
    if (s.rays > 0) return "";
    switch (s.state) {
    case State::Waiting:
        return "view changed: the reference waits for the camera to settle";
    case State::Failed:
        return "reference failed: " + s.error;
    default:
        return "tracing the first rays of the reference...";
    }
}

void drawReferenceSection(FrameDriver& frames, ViewState& view) {
    if (ImGui::Checkbox("vs reference", &frames.referenceOn)) frames.keepAwake();
    rememberRect(view, "reference#on");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Ray-traced reference AO of this view (Embree, on the CPU in the background, one core left\n"
            "to the renderer): cosine-weighted visibility within the AO's world radius at the centre\n"
            "of the view, refined up to %d rays per pixel; restarted when the camera, the radius, the\n"
            "size or the scene changes. Shown as reference.ao and reference.error.",
            frames.referenceRays);
    if (!frames.referenceOn) {
        ImGui::TextDisabled("off");
        return;
    }
    const LiveReference::Status s = frames.reference().status();
    progressLine(s);
    rememberRect(view, "reference#progress");
    const auto& m = frames.reference().metrics();
    if (!m || s.state == State::Waiting) return;
    if (ImGui::BeginTable("reference", 2, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg)) {
        row("RMSE", "root mean square of ao.denoised - reference over geometry pixels (linear AO)", "%.4f",
            m->rmse);
        row("bias", "mean of ao.denoised - reference: + too bright (under-occluded), - too dark", "%+.4f",
            m->bias);
        row("PSNR", "of the sRGB-encoded AO over geometry pixels (peak 1), dB", "%.2f dB",
            m->psnrGeometrySrgb);
        row("SSIM", "structural similarity of the sRGB-encoded AO, whole frame (Wang et al. 2004)", "%.4f",
            m->ssim);
        row("RMSE edge", "RMSE within 3 px of a depth discontinuity", "%.4f", m->rmseEdge);
        row("RMSE interior", "RMSE away from depth discontinuities", "%.4f", m->rmseInterior);
        row("ref. noise", "RMS standard error of the reference itself: errors below it are noise", "%.4f",
            m->referenceNoise);
        ImGui::EndTable();
    }
    rememberRect(view, "reference#metrics");
    ImGui::TextDisabled("R %.4g units, %.1f s, %.1f Mrays/s", s.radius, s.seconds, s.mraysPerSecond);
    splitSection(frames.reference());
    rememberRect(view, "reference#split");
}

} // namespace ssao
