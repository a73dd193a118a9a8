// The "vs reference" block of the info strip: the ray-traced reference's progress (rays per pixel
// so far, or why it waits) and the error of ao.denoised against it, next to the timings.
#include "view/panels/ui_panels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace ssao {

namespace {

using State = LiveReference::State;

// The rows of the error table: the name (a short one while B's column is beside A's, in the
// strip's narrow column), what it means, its format and field.
struct MetricRow {
    const char *name, *shortName, *tip, *fmt;
    double ErrorMetrics::*field;
    const char* key; // the cells' rectangles: reference#KEY_a, reference#KEY_b
};
const MetricRow kRows[] = {
    {"RMSE", "RMSE", "root mean square of ao.denoised - reference over geometry pixels (linear AO)", "%.4f",
     &ErrorMetrics::rmse, "rmse"},
    {"bias", "bias", "mean of ao.denoised - reference: + too bright (under-occluded), - too dark", "%+.4f",
     &ErrorMetrics::bias, "bias"},
    {"PSNR dB", "PSNR dB", "of the sRGB-encoded AO over geometry pixels (peak 1)", "%.2f",
     &ErrorMetrics::psnrGeometrySrgb, "psnr"},
    {"SSIM", "SSIM", "structural similarity of the sRGB-encoded AO, whole frame (Wang et al. 2004)", "%.4f",
     &ErrorMetrics::ssim, "ssim"},
    {"RMSE edge", "edge", "RMSE within 3 px of a depth discontinuity", "%.4f", &ErrorMetrics::rmseEdge, "rmse_edge"},
    {"RMSE interior", "interior", "RMSE away from depth discontinuities", "%.4f", &ErrorMetrics::rmseInterior,
     "rmse_interior"},
    {"ref. noise", "noise", "RMS standard error of the reference itself: errors below it are noise", "%.4f",
     &ErrorMetrics::referenceNoise, "noise"},
};

// The error of A's ao.denoised against the reference, and of B's beside it (`b`: the split view,
// when B has an AO of its own).
void metricsTable(const ErrorMetrics& a, const ErrorMetrics* b, ViewState& view) {
    if (!ImGui::BeginTable("reference", b ? 3 : 2, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg)) return;
    // Explicit weights: the columns are sane from the first frame, before ImGui measured them.
    const float number = ImGui::CalcTextSize("+0.0000").x;
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthStretch, ImGui::CalcTextSize(b ? "interior" : "RMSE interior").x);
    ImGui::TableSetupColumn("A", ImGuiTableColumnFlags_WidthStretch, number);
    if (b) {
        ImGui::TableSetupColumn("B", ImGuiTableColumnFlags_WidthStretch, number);
        ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
        const char* tips[3] = {"", "A: the current settings", "B: the split view's other side (b.ao.denoised), same reference"};
        for (int c = 0; c < 3; ++c) {
            ImGui::TableSetColumnIndex(c);
            ImGui::TableHeader(ImGui::TableGetColumnName(c));
            if (c > 0 && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tips[c]);
        }
    }
    const ErrorMetrics* m[2] = {&a, b};
    for (const MetricRow& r : kRows) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(b ? r.shortName : r.name);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", r.tip);
        for (int i = 0; i < (b ? 2 : 1); ++i) {
            ImGui::TableNextColumn();
            const double v = m[i]->*r.field;
            if (std::isfinite(v))
                ImGui::Text(r.fmt, v);
            else
                ImGui::TextDisabled("-"); // e.g. no edge pixels in view: no value, not 0
            rememberRect(view, std::string("reference#") + r.key + (i ? "_b" : "_a"));
        }
    }
    ImGui::EndTable();
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
// does not hold. The two RMSEs need not add up; their shares of the squared error do.
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
    // Short, wrapped at spaces in a narrow strip; the rest on hover.
    char line[96];
    std::snprintf(line, sizeof line, "split: technique %.4f  screen %.4f", sp->technique.rmse, sp->screen.rmse);
    wrappedText(line);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("RMSE of ao.denoised against the screen-space oracle (technique: what settings can\n"
                          "still fix) and of the oracle against the reference (screen: what the depth buffer\n"
                          "does not hold - back faces, hidden and off-screen occluders, true thickness).\n"
                          "The oracle: the same integral and R, visibility decided by the depth buffer alone\n"
                          "(surfaces 1 R thick, cut-out MASK surfaces sheets).\n\n"
                          "            technique   screen\n"
                          "RMSE        %.4f      %.4f\n"
                          "bias        %+.4f     %+.4f\n"
                          "edge        %.4f      %.4f\n"
                          "interior    %.4f      %.4f",
                          sp->technique.rmse, sp->screen.rmse, sp->technique.bias, sp->screen.bias,
                          sp->technique.rmseEdge, sp->screen.rmseEdge, sp->technique.rmseInterior,
                          sp->screen.rmseInterior);
    const ErrorShares& sh = sp->shares;
    if (std::isfinite(sh.technique))
        ImGui::Text("shares: technique %.2f  screen %.2f  interaction %+.2f", sh.technique, sh.screen,
                    sh.interaction);
    else
        ImGui::TextDisabled("shares: - (no error to share)");
    if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 36.0f);
        ImGui::TextUnformatted(kSharesHowToRead);
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
}

// Where the error lives (metrics/error_places.h): the two places with the largest share of the
// squared error on one line, every place and R-in-pixels bin on hover.
void placesSection(const LiveReference& ref) {
    const auto& e = ref.places();
    if (!e || e->all.sumSq <= 0) return;
    int order[kPlaces] = {0, 1, 2, 3, 4};
    std::sort(order, order + kPlaces, [&](int a, int b) { return e->place[size_t(a)].sumSq > e->place[size_t(b)].sumSq; });
    char line[128];
    std::snprintf(line, sizeof line, "where: %s %.0f%%, %s %.0f%%", placeName(Place(order[0])),
                  100 * e->place[size_t(order[0])].sumSq / e->all.sumSq, placeName(Place(order[1])),
                  100 * e->place[size_t(order[1])].sumSq / e->all.sumSq);
    wrappedText(line);
    if (!ImGui::IsItemHovered()) return;
    std::string tip = "Where ao.denoised's squared error lives (share of it, RMSE, share of the pixels):\n";
    char b[128];
    for (int i = 0; i < kPlaces; ++i) {
        const PlaceStats& s = e->place[size_t(i)];
        std::snprintf(b, sizeof b, "  %-10s %3.0f%%  %.4f  (%3.0f%% of the pixels)\n", placeName(Place(i)),
                      100 * s.sumSq / e->all.sumSq, s.pixels ? std::sqrt(s.sumSq / double(s.pixels)) : 0.0,
                      100.0 * double(s.pixels) / double(std::max(1L, e->all.pixels)));
        tip += b;
    }
    const char* bins[kRadiusBins] = {"R < 8 px", "R 8-16 px", "R > 16 px"};
    for (int i = 0; i < kRadiusBins; ++i) {
        std::snprintf(b, sizeof b, "  %-10s %3.0f%%\n", bins[i], 100 * e->radius[size_t(i)].sumSq / e->all.sumSq);
        tip += b;
    }
    tip += "Places by priority: border (nearer the frame's edge than R in pixels), silhouette (2 px of a\n"
           "depth discontinuity), crease (2 px of a concave normal discontinuity), convex edge, open.";
    ImGui::SetTooltip("%s", tip.c_str());
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
    // B's numbers beside A's when the split view's B has its own AO (not A's, shared).
    const auto& mb = frames.reference().metricsB();
    metricsTable(*m, view.mode == ViewMode::Split && mb ? &*mb : nullptr, view);
    rememberRect(view, "reference#metrics");
    char about[96];
    std::snprintf(about, sizeof about, "R %.4g units, %.1f s, %.1f Mrays/s", s.radius, s.seconds, s.mraysPerSecond);
    wrappedText(about, true);
    splitSection(frames.reference());
    placesSection(frames.reference());
    rememberRect(view, "reference#split"); // the shares' line, the last of the section
}

} // namespace ssao
