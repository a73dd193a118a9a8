#include "commands/skips/skips_report.h"

#include "output/escape.h"
#include "util/number_text.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/files.h"
#include "util/json_file.h"

#include <cstdio>
#include <filesystem>
#include <sstream>

namespace ssao {

namespace {
std::string num(double v, const char* fmt = "%.2f") {
    return numberText(v, fmt);
}
// "left of total" for a counter pair of the G-buffer: `left` (culled, occluded) out of what was
// drawn plus it, e.g. draws / draws_culled.
std::string leftOf(const SkipRow& r, const char* drawn, const char* left) {
    const double d = r.extra.value(drawn, 0.0), l = r.extra.value(left, 0.0);
    return num(l, "%.0f") + " of " + num(d + l, "%.0f");
}

std::string ratio(const SkipRow& r) {
    return r.without > 0 ? num(r.ratio(), "%.2fx") : "-";
}
// "0" for bit-exact, else the largest difference.
std::string change(double d) {
    return d == 0.0 ? "0 (exact)" : num(d, "%.2g");
}
std::string joined(const nlohmann::json& list) {
    std::string s;
    for (const auto& v : list)
        s += (s.empty() ? "" : ", ") + markdownCell(v.get<std::string>());
    return s.empty() ? "none" : s;
}
// A table's title, header and alignment row.
void table(std::ostringstream& md, const std::string& title, const std::string& header, const std::string& align) {
    md << "\n#### " << title << "\n\n" << header << "\n" << align << "\n";
}
template <class F> void rows(std::ostringstream& md, const SkipsRun& run, const std::string& skip, F line) {
    for (const auto& r : run.rows)
        if (r.skip == skip) md << line(r) << "\n";
}

// The skips inside the AO and its denoiser: what a change re-runs, sky pixels, adaptive samples,
// deinterleaved sampling.
void aoTables(std::ostringstream& md, const SkipsRun& run) {
    table(md, "Dirty passes: what each change re-runs",
          "| scene | change | passes run | GPU ms with | every pass forced | ratio | wall ms with / forced | output change |",
          "|---|---|---|---:|---:|---:|---:|---|");
    rows(md, run, "dirty", [](const SkipRow& r) {
        return "| " + markdownCell(r.scene) + " | " + markdownCell(r.variant) + " | " + joined(r.extra["passes_run"]) + " | " + num(r.with) +
               " | " + num(r.without) + " | " + ratio(r) + " | " + num(r.wallWith, "%.1f") + " / " +
               num(r.wallWithout, "%.1f") + " | " + change(r.errorChange) + " |";
    });

    table(md, "Sky pixels: AO and the denoiser's last pass return at once",
          "| scene | sky share | technique | AO + denoise ms with | without | ratio | geometry share | output change |",
          "|---|---:|---|---:|---:|---:|---:|---|");
    rows(md, run, "sky", [](const SkipRow& r) {
        const double sky = r.extra.value("sky_share", 0.0);
        return "| " + markdownCell(r.scene) + " | " + num(100.0 * sky, "%.0f %%") + " | " + markdownCell(r.variant) + " | " + num(r.with) +
               " | " + num(r.without) + " | " + ratio(r) + " | " + num(1.0 - sky, "%.2f") + " | " +
               change(r.errorChange) + " |";
    });

    table(md, "Adaptive sample count (ao.adaptive): fewer samples where the radius spans few pixels",
          "| scene | view | technique | samples taken | AO ms adaptive | full | ratio | RMSE adaptive | full | change |",
          "|---|---|---|---:|---:|---:|---:|---:|---:|---:|");
    rows(md, run, "adaptive", [](const SkipRow& r) {
        return "| " + markdownCell(r.scene) + " | " + markdownCell(r.view) + " | " + markdownCell(r.variant) + " | " +
               num(100.0 * r.extra.value("sample_share", 1.0), "%.0f %%") + " | " + num(r.with) + " | " +
               num(r.without) + " | " + ratio(r) + " | " + num(r.extra.value("rmse_with", 0.0), "%.4f") + " | " +
               num(r.extra.value("rmse_without", 0.0), "%.4f") + " | " + num(r.errorChange, "%+.4f") + " |";
    });

    table(md, "Deinterleaved sampling (ao.deinterleave): 16 quarter-size layers, one jitter each (not exact: taps on a 4-pixel grid)",
          "| scene | view | preset | AO ms deinterleaved | interleaved | ratio | frame wall ms deinterleaved / interleaved | RMSE deinterleaved | interleaved | change |",
          "|---|---|---|---:|---:|---:|---:|---:|---:|---:|");
    rows(md, run, "deinterleave", [](const SkipRow& r) {
        return "| " + markdownCell(r.scene) + " | " + markdownCell(r.view) + " | " + markdownCell(r.variant) + " | " + num(r.with) + " | " + num(r.without) +
               " | " + ratio(r) + " | " + num(r.wallWith, "%.1f") + " / " + num(r.wallWithout, "%.1f") + " | " +
               num(r.extra.value("rmse_with", 0.0), "%.4f") + " | " + num(r.extra.value("rmse_without", 0.0), "%.4f") +
               " | " + num(r.errorChange, "%+.4f") + " |";
    });
}

// The skips in the G-buffer and the composite: culling, hidden faces and draws, unread targets,
// the fused upsample.
void gbufferTables(std::ostringstream& md, const SkipsRun& run) {
    table(md, "Frustum culling in the G-buffer pass",
          "| scene | view | draws culled | triangles culled | G-buffer ms with | without | ratio | wall ms with / without | output change |",
          "|---|---|---:|---:|---:|---:|---:|---:|---|");
    rows(md, run, "cull", [](const SkipRow& r) {
        return "| " + markdownCell(r.scene) + " | " + markdownCell(r.view) + " | " + leftOf(r, "draws", "draws_culled") + " | " +
               leftOf(r, "triangles", "triangles_culled") + " | " + num(r.with) + " | " + num(r.without) +
               " | " + ratio(r) + " | " + num(r.wallWith, "%.1f") + " / " + num(r.wallWithout, "%.1f") + " | " +
               change(r.errorChange) + " |";
    });

    table(md, "Hidden faces of closed solids culled in the G-buffer (skip.hidden_faces)",
          "| scene | view | triangles drawn with culling | G-buffer ms with | without | ratio | wall ms with / without | output change |",
          "|---|---|---:|---:|---:|---:|---:|---|");
    rows(md, run, "faces", [](const SkipRow& r) {
        const double t = r.extra.value("triangles", 0.0), tf = r.extra.value("triangles_face_culled", 0.0);
        return "| " + markdownCell(r.scene) + " | " + markdownCell(r.view) + " | " + num(tf, "%.0f") + " of " + num(t, "%.0f") + " | " +
               num(r.with) + " | " + num(r.without) + " | " + ratio(r) + " | " + num(r.wallWith, "%.1f") + " / " +
               num(r.wallWithout, "%.1f") + " | " + change(r.errorChange) + " |";
    });

    table(md, "Draws the scene hides left out of the G-buffer (skip.occluded: occlusion queries)",
          "| scene | view | draws occluded | triangles occluded | boxes tested | frame wall ms with | without | ratio | output change |",
          "|---|---|---:|---:|---:|---:|---:|---:|---|");
    rows(md, run, "occluded", [](const SkipRow& r) {
        return "| " + markdownCell(r.scene) + " | " + markdownCell(r.view) + " | " + leftOf(r, "draws", "draws_occluded") + " | " +
               leftOf(r, "triangles", "triangles_occluded") + " | " + num(r.extra.value("boxes_tested", 0.0), "%.0f") +
               " | " + num(r.with, "%.1f") + " | " + num(r.without, "%.1f") + " | " + ratio(r) + " | " +
               change(r.errorChange) + " |";
    });

    table(md, "G-buffer targets nothing reads",
          "| scene | view | case | colour targets written | G-buffer ms with | all 4 written | ratio | output change |",
          "|---|---|---|---:|---:|---:|---:|---|");
    rows(md, run, "targets", [](const SkipRow& r) {
        return "| " + markdownCell(r.scene) + " | " + markdownCell(r.view) + " | " + markdownCell(r.variant) + " | " +
               num(r.extra.value("targets_written", 4.0), "%.0f") + " | " + num(r.with) + " | " + num(r.without) +
               " | " + ratio(r) + " | " + change(r.errorChange) + " |";
    });

    table(md, "The joint upsample inside the composite (half-resolution AO, a composite view nothing else reads)",
          "| scene | view | frame GPU ms fused | own upsample pass | ratio | wall ms fused / own pass | composite change |",
          "|---|---|---:|---:|---:|---:|---|");
    rows(md, run, "fused", [](const SkipRow& r) {
        return "| " + markdownCell(r.scene) + " | " + markdownCell(r.view) + " | " + num(r.with) + " | " + num(r.without) + " | " + ratio(r) +
               " | " + num(r.wallWith, "%.1f") + " / " + num(r.wallWithout, "%.1f") + " | " + change(r.errorChange) +
               " |";
    });

    table(md, "The second depth layer in the G-buffer's own pass (gbuffer.second_layer_build=previous) instead of a "
              "second geometry pass (peel); each build's frames in a row",
          "| scene | view | G-buffer + layer ms, one pass | two passes | ratio | wall ms one / two | AO change |",
          "|---|---|---:|---:|---:|---:|---|");
    rows(md, run, "layer", [](const SkipRow& r) {
        return "| " + markdownCell(r.scene) + " | " + markdownCell(r.view) + " | " + num(r.with) + " | " + num(r.without) + " | " + ratio(r) +
               " | " + num(r.wallWith, "%.1f") + " / " + num(r.wallWithout, "%.1f") + " | " + change(r.errorChange) +
               " |";
    });
}
} // namespace

std::string skipsMarkdown(const SkipsRun& run) {
    std::ostringstream md;
    md << "Measured by `ssaolab skips` at " << markdownCell(run.facts.value("size", std::string("?"))) << ", median of "
       << run.facts.value("frames", 0) << " frames per variant, the variants alternating frame by frame on "
       << markdownCell(run.facts.value("gl_renderer", std::string("?")))
       << ". \"with\" is the frame with the skip, \"without\" the same frame with it switched off (skip.* "
          "settings) or, for dirty passes, with every pass forced; ratio = with / without. The output "
          "change is the largest difference of the judged buffer over geometry pixels (0: bit-exact), "
          "or for adaptive sampling the change in RMSE against the ray-traced reference.\n";

    aoTables(md, run);
    gbufferTables(md, run);
    return md.str();
}

void writeSkipsFiles(const SkipsRun& run, const std::string& dir) {
    makeOutputFolder(dir);
    nlohmann::json j = {{"facts", run.facts}, {"rows", nlohmann::json::array()}};
    for (const auto& r : run.rows)
        j["rows"].push_back({{"skip", r.skip},
                             {"scene", r.scene},
                             {"view", r.view},
                             {"variant", r.variant},
                             {"measured", r.measured},
                             {"with_ms", r.with},
                             {"without_ms", r.without},
                             {"ratio", r.ratio()},
                             {"wall_with_ms", r.wallWith},
                             {"wall_without_ms", r.wallWithout},
                             {"error_change", r.errorChange},
                             {"extra", r.extra}});
    writeFileAtomically(dir + "/skips.json", dumpJson(j) + "\n");
    writeFileAtomically(dir + "/skips.md", skipsMarkdown(run));
}

} // namespace ssao
