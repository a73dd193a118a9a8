// The "Front" tab: the time-against-error front of the view on screen (view/frame/front_panel.h).
// A plot drawn with ImGui's draw list - GPU time on a log axis, RMSE against the finished live
// reference or the motion score along the camera path through the view ("still | motion"; the axis
// clipped above the bulk, outliers as triangles on its top edge), the front as
// a step line, the current setting ringed, the baseline black, the reference's noise floor as a
// grey band - where hovering names a point, a click applies it and a shift+click compares it with
// the current setting in Split A|B. Under it the two one-click answers and the budget box.
#include "techniques/technique.h"
#include "view/panels/ui_panels.h"
#include "view/panels/ui_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ssao {

namespace {

std::string pointText(const FrontPoint& p, const FrontPoint* base) {
    char b[480];
    if (p.candidate.isEngine()) {
        std::snprintf(b, sizeof b,
                      "%s (a web engine in Chromium)\n%.3f ms AO: frame with the pass - frame without%s\nRMSE "
                      "%.4f%s, bias %+.4f, edge RMSE %.4f\nclick: its AO frame in Split B",
                      p.candidate.label.c_str(), p.result.gpuMs,
                      base ? (", " + std::to_string(p.timeRatio).substr(0, 5) + "x the baseline's").c_str() : "",
                      p.result.error.rmse, base ? (", " + std::to_string(p.scoreRatio).substr(0, 5) + "x").c_str() : "",
                      p.result.error.bias, p.result.error.rmseEdge);
        return b;
    }
    const std::string tr = base ? ", " + std::to_string(p.timeRatio).substr(0, 5) + "x the baseline's" : "";
    const std::string er = base ? ", " + std::to_string(p.scoreRatio).substr(0, 5) + "x" : "";
    if (p.motion)
        std::snprintf(b, sizeof b,
                      "%s\n%.3f ms GPU (AO + denoise)%s\nmotion score %.4f%s: per-frame RMSE %.4f, instability "
                      "%.4f, ghosting %s\nstill RMSE %.4f",
                      p.candidate.label.c_str(), p.result.gpuMs, tr.c_str(), p.score, er.c_str(), p.motion->rmseMean,
                      p.motion->instability, ghostingText(*p.motion).c_str(), p.result.error.rmse);
    else
        std::snprintf(b, sizeof b, "%s\n%.3f ms GPU (AO + denoise)%s\nRMSE %.4f%s, bias %+.4f, edge RMSE %.4f",
                      p.candidate.label.c_str(), p.result.gpuMs, tr.c_str(), p.result.error.rmse, er.c_str(),
                      p.result.error.bias, p.result.error.rmseEdge);
    return b;
}

// A point of the plot: a disc (a web engine's: a diamond), or above the error axis a triangle
// pointing up on its top edge; the baseline black and large, the front red, an engine orange.
void dot(ImDrawList* dl, ImVec2 c, const FrontPoint& p, bool baseline, bool offTop) {
    const bool engine = p.candidate.isEngine();
    const float r = baseline ? 5.5f : p.front || engine ? 4.0f : 3.0f;
    const ImU32 col = baseline ? IM_COL32(0, 0, 0, 255)
                      : p.front ? IM_COL32(214, 39, 40, 255)
                      : engine  ? IM_COL32(230, 130, 20, 255)
                                : IM_COL32(150, 150, 150, 255);
    if (engine && !offTop)
        dl->AddQuadFilled(ImVec2(c.x, c.y - r - 1.5f), ImVec2(c.x + r + 1.5f, c.y), ImVec2(c.x, c.y + r + 1.5f),
                          ImVec2(c.x - r - 1.5f, c.y), col);
    else if (offTop)
        dl->AddTriangleFilled(ImVec2(c.x, c.y - r - 1), ImVec2(c.x - r - 1, c.y + r), ImVec2(c.x + r + 1, c.y + r), col);
    else
        dl->AddCircleFilled(c, r, col);
}

// The plot; returns the index of the point under the cursor (npos when none).
size_t plot(UiActions& out, const std::vector<FrontPoint>& pts, size_t current, size_t baseline, double noise,
            const std::string& axisName) {
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float w = std::max(ImGui::GetContentRegionAvail().x, 200.0f), h = 260.0f;
    ImGui::InvisibleButton("front#plot", ImVec2(w, h));
    rememberRect(out, "front#plot");
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const float L = 44, R = 8, T = 8, B = 30;
    dl->AddRectFilled(origin, ImVec2(origin.x + w, origin.y + h), IM_COL32(250, 250, 250, 255));
    double tlo = 1e300, thi = 0;
    std::vector<double> errors;
    for (const auto& p : pts)
        if (p.result.gpuMs > 0 && std::isfinite(p.score))
            tlo = std::min(tlo, p.result.gpuMs), thi = std::max(thi, p.result.gpuMs), errors.push_back(p.score);
    // The error axis stops above the bulk (ui_layout.h): one outlier would squeeze the points people
    // compare into the bottom strip. Points above it sit on the top edge as triangles.
    const double ehi = std::max(clippedAxisTop(errors, noise * 1.2) * 1.1, 1e-3);
    const long above = std::count_if(errors.begin(), errors.end(), [&](double e) { return e > ehi; });
    if (!(thi > 0)) tlo = 0.1, thi = 10;
    tlo /= 1.2, thi *= 1.2;
    if (!(thi > tlo * 1.01)) thi = tlo * 2;
    auto X = [&](double t) { return origin.x + L + float((std::log(t) - std::log(tlo)) / (std::log(thi) - std::log(tlo))) * (w - L - R); };
    auto Y = [&](double e) { return origin.y + h - B - float(std::min(e, ehi) / ehi) * (h - T - B); };
    const ImU32 grid = IM_COL32(225, 225, 225, 255), ink = IM_COL32(70, 70, 70, 255);
    if (noise > 0)
        dl->AddRectFilled(ImVec2(origin.x + L, Y(noise)), ImVec2(origin.x + w - R, Y(0)), IM_COL32(228, 228, 228, 255));
    for (int d = int(std::floor(std::log10(tlo))); d <= int(std::ceil(std::log10(thi))); ++d)
        for (double m : {1.0, 2.0, 5.0}) {
            const double v = m * std::pow(10.0, d);
            if (v < tlo || v > thi) continue;
            dl->AddLine(ImVec2(X(v), origin.y + T), ImVec2(X(v), Y(0)), grid);
            char b[16];
            std::snprintf(b, sizeof b, "%g", v);
            dl->AddText(ImVec2(X(v) - 8, Y(0) + 2), ink, b);
        }
    for (int k = 0; k <= 4; ++k) {
        const double v = ehi * k / 4;
        dl->AddLine(ImVec2(origin.x + L, Y(v)), ImVec2(origin.x + w - R, Y(v)), grid);
        char b[16];
        std::snprintf(b, sizeof b, "%.3f", v);
        dl->AddText(ImVec2(origin.x + 2, Y(v) - 7), ink, b);
    }
    // Axis names where they cannot run out of the plot, whatever the panel's width: time under the
    // right end of the x axis, the error's above the y axis's labels.
    const char* xName = "GPU ms (log) ->";
    dl->AddText(ImVec2(origin.x + w - R - ImGui::CalcTextSize(xName).x, origin.y + h - 14), ink, xName);
    const std::string yName =
        axisName + (above > 0 ? " (" + std::to_string(above) + " above the axis: triangles)" : "");
    dl->AddText(ImVec2(origin.x + L + 4, origin.y + T), ink, yName.c_str());
    out.rects["front#y:" + axisName] = ImVec4(origin.x + L, origin.y + T, origin.x + w - R, origin.y + T + 14);
    // The front as a step line, fastest first.
    std::vector<const FrontPoint*> front;
    for (const auto& p : pts)
        if (p.front) front.push_back(&p);
    std::sort(front.begin(), front.end(), [](auto* a, auto* b) { return a->result.gpuMs < b->result.gpuMs; });
    for (size_t i = 1; i < front.size(); ++i) {
        const ImVec2 a(X(front[i - 1]->result.gpuMs), Y(front[i - 1]->score));
        const ImVec2 c(X(front[i]->result.gpuMs), Y(front[i]->score));
        dl->AddLine(a, ImVec2(c.x, a.y), IM_COL32(214, 39, 40, 200), 1.5f);
        dl->AddLine(ImVec2(c.x, a.y), c, IM_COL32(214, 39, 40, 200), 1.5f);
    }
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    size_t hover = std::string::npos;
    float best = 8.0f * 8.0f;
    for (size_t i = 0; i < pts.size(); ++i) {
        const FrontPoint& p = pts[i];
        if (!(p.result.gpuMs > 0) || !std::isfinite(p.score)) continue;
        const ImVec2 c(X(p.result.gpuMs), Y(p.score));
        dot(dl, c, p, i == baseline, p.score > ehi);
        if (i == current) dl->AddCircle(c, 8.0f, IM_COL32(30, 110, 255, 255), 16, 2.0f);
        out.rects["front#point:" + p.candidate.label] = ImVec4(c.x - 2, c.y - 2, c.x + 2, c.y + 2);
        const float d2 = (c.x - mouse.x) * (c.x - mouse.x) + (c.y - mouse.y) * (c.y - mouse.y);
        if (ImGui::IsItemHovered() && d2 < best) best = d2, hover = i;
    }
    if (hover != std::string::npos) {
        const ImVec2 c(X(pts[hover].result.gpuMs), Y(pts[hover].score));
        dl->AddCircle(c, 6.0f, IM_COL32(0, 0, 0, 255), 12, 1.5f);
    }
    return hover;
}

// "label: t ms (x), RMSE e (x)" (or the motion score) relative to the current point, and a button that applies it.
void answer(const FrontPanel& f, const char* question, size_t i, const std::string& key, UiActions& out) {
    ImGui::TextWrapped("%s", question);
    if (i == std::string::npos) {
        ImGui::TextDisabled("  none measured so far");
        return;
    }
    const FrontPoint& p = f.points()[i];
    const FrontPoint& c = f.points()[f.currentIndex()];
    ImGui::TextWrapped("  %s: %.3f ms (%.2fx current), %s %.4f (%.2fx current)", p.candidate.label.c_str(),
                       p.result.gpuMs, p.result.gpuMs / c.result.gpuMs, p.motion ? "motion score" : "RMSE", p.score,
                       p.score / c.score);
    if (ImGui::SmallButton(("apply##" + key).c_str())) out.push(act::ApplyCandidate{p.candidate});
    rememberRect(out, "front#apply_" + key);
    ImGui::SameLine();
    if (ImGui::SmallButton(("compare in A|B##" + key).c_str())) out.push(act::CompareCandidate{p.candidate});
}

// Why the current point may look grainy: denoise.kind=auto leaves the marching techniques
// unfiltered because a blur raises their error on the bench scenes (docs/bench/report.md).
void grainNote(const Settings& s, UiActions& out) {
    if (s.denoise.kind != DenoiseKind::Auto || effectiveDenoise(s).kind != DenoiseKind::None || s.temporal.enabled)
        return;
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("Grain: denoise 'auto' leaves %s unfiltered - its noise is finer than the detail a blur "
                       "erases, and every blur raised its error against the reference on the bench scenes. For a "
                       "still camera, temporal accumulation (temporal.enabled) averages it away; the points here "
                       "are scored on a still frame unless the axis is 'motion'.",
                       s.ao.technique.c_str());
    ImGui::PopStyleColor();
    rememberRect(out, "front#grain");
}

// The y axis's choice (`axis`, asked for as SetFrontAxis), and on the motion axis what its numbers
// are of and how far they are.
void motionAxis(const FrontPanel& f, FrontPanel::Axis& axis, UiActions& out) {
    ImGui::TextUnformatted("y axis:");
    ImGui::SameLine();
    const FrontPanel::Axis before = axis;
    if (ImGui::RadioButton("still", axis == FrontPanel::Axis::Still)) axis = FrontPanel::Axis::Still;
    rememberRect(out, "front#axis_still");
    ImGui::SameLine();
    if (ImGui::RadioButton("motion", axis == FrontPanel::Axis::Motion)) axis = FrontPanel::Axis::Motion;
    rememberRect(out, "front#axis_motion");
    if (axis != before) out.push(act::SetFrontAxis{axis == FrontPanel::Axis::Motion});
    if (axis != FrontPanel::Axis::Motion || !f.waiting().empty()) return;
    const FrontMotion& m = f.motion();
    if (!m.hasView()) return;
    const MotionView& v = m.view();
    char what[160];
    std::snprintf(what, sizeof what, "%d frames at %dx%d (orbit %.3g deg, dolly %.3g), %d-ray references",
                  v.spec.frames, v.width, v.height, v.spec.orbitDeg, v.spec.dolly, v.settings.samples);
    const FrontMotion::Progress pr = m.progress();
    char b[256];
    if (!pr.error.empty()) {
        ImGui::TextWrapped("the motion path's references failed: %s", pr.error.c_str());
    } else if (m.tracing()) {
        std::snprintf(b, sizeof b, "tracing the motion path's references: %s", what);
        ImGui::ProgressBar(float(pr.traceFraction), ImVec2(-1, 0), b);
    } else if (m.measuring()) {
        std::snprintf(b, sizeof b, "scoring %zu / %zu candidates in motion", pr.done, pr.total);
        ImGui::ProgressBar(float(pr.fraction), ImVec2(-1, 0), b);
    } else {
        ImGui::TextDisabled("motion: %s", what);
    }
    rememberRect(out, "front#motion_progress");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Each candidate along the camera path through this view, as `ssaolab bench --motion`\n"
                          "scores it, at a reduced size (the path needs a reference per frame): every\n"
                          "frame against its own reference. Motion score = sqrt(mean per-frame RMSE^2 +\n"
                          "instability^2), bench's motion rank; points appear once scored.");
}

} // namespace

void drawFrontTab(const FrontTabView& in, UiActions& out) {
    const FrontPanel& f = in.front;
    const FrontMeasurer& m = f.measurer();
    const FrontMeasurer::Progress pr = m.progress();
    if (!f.waiting().empty()) {
        ImGui::TextWrapped("%s", f.waiting().c_str());
    } else if (m.busy()) {
        char b[128];
        std::snprintf(b, sizeof b, "measuring %zu / %zu candidates, ETA %.0f s", pr.done, pr.total, pr.etaSeconds);
        ImGui::ProgressBar(float(pr.fraction), ImVec2(-1, 0), b);
    } else if (m.hasView()) {
        ImGui::Text("%zu candidates measured on this view (%.1f s)", pr.total, pr.seconds);
    }
    rememberRect(out, "front#progress");
    FrontPanel::Axis axis = f.axis;
    motionAxis(f, axis, out);
    bool paused = f.paused;
    if (ImGui::Checkbox("pause", &paused)) out.push(act::SetFrontPaused{paused});
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Every shipped preset, the current setting and its neighbours (AO resolution,\n"
                          "denoisers, quality ladder), each with the reference's radius R: GPU time at\n"
                          "this view's size (median of 5 frames after 2) and RMSE against the finished\n"
                          "reference - the numbers `ssaolab bench` gives for the same view.\n"
                          "Click a point: apply it. Shift+click: compare it with the current one in A|B.\n"
                          "Diamonds: web engines run in Chromium (Engines, below); a click shows\n"
                          "one's AO frame in Split B. The answers pick among ssaolab's settings.");
    const auto& pts = f.points();
    const size_t base = f.baselineIndex(), cur = f.currentIndex();
    const size_t hover = plot(out, pts, cur, base, f.referenceNoise(), f.axisName());
    if (hover != std::string::npos) {
        ImGui::SetTooltip("%s", pointText(pts[hover], base == std::string::npos ? nullptr : &pts[base]).c_str());
        if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
            if (ImGui::GetIO().KeyShift || pts[hover].candidate.isEngine()) // an engine's: B is its frame
                out.push(act::CompareCandidate{pts[hover].candidate});
            else
                out.push(act::ApplyCandidate{pts[hover].candidate});
        }
    }
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("blue ring: current   black: baseline (learnopengl)   red: the front   diamonds: web "
                       "engines   grey band: the reference's own noise");
    ImGui::PopStyleColor();
    grainNote(in.settings, out);
    if (cur != std::string::npos) {
        answer(f, "Cheapest at <= the current error:", f.cheapestAtMostCurrentError(), "cheapest", out);
        answer(f, "Most accurate at <= the current time:", f.mostAccurateWithinCurrentTime(), "accurate", out);
    }
    ImGui::Separator();
    ImGui::SetNextItemWidth(110);
    double budgetMs = f.budgetMs, maxError = f.maxError;
    bool edited = ImGui::InputDouble("budget ms", &budgetMs, 0, 0, "%.3f");
    rememberRect(out, "front#budget_ms");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(110);
    edited |= ImGui::InputDouble(axis == FrontPanel::Axis::Motion ? "max score###max" : "max RMSE###max", &maxError,
                                 0, 0, "%.4f");
    rememberRect(out, "front#max_error");
    if (edited) out.push(act::SetFrontBudget{budgetMs, maxError});
    if (f.budgetMs > 0 || f.maxError > 0) {
        const size_t b = f.bestForBudget();
        if (b == std::string::npos) {
            ImGui::TextDisabled("no candidate meets it (so far)");
        } else if (cur != std::string::npos) {
            answer(f, f.budgetMs > 0 ? "Most accurate within the budget:" : "Fastest at most that error:", b, "budget",
                   out);
        }
    }
    drawEngineSection(in, axis, out);
}

} // namespace ssao
