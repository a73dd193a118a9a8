#include "results/place_report.h"

#include "metrics/error_places.h"
#include "output/escape.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <vector>

namespace ssao {

namespace {

// "share % (RMSE)" of one place of a row's sums; "–" for a place with no pixels.
std::string cell(const PlaceStats& s, const PlaceStats& all) {
    if (s.pixels == 0) return "–";
    char b[64];
    std::snprintf(b, sizeof b, "%.0f %% (%.3f)", all.sumSq > 0 ? 100.0 * s.sumSq / all.sumSq : 0.0,
                  std::sqrt(s.sumSq / double(s.pixels)));
    return b;
}

// The rows reported: the baseline, the front (the run's objective) and the lowest still RMSE.
std::vector<bool> reportedRows(const BenchRun& run) {
    std::vector<bool> on(run.sweep.configs.size(), false);
    size_t best = std::string::npos;
    for (const ConfigSummary& s : run.summary) {
        if (s.pareto || s.config == run.sweep.baseline) on[s.config] = true;
        if (std::isfinite(s.rmse) && (best == std::string::npos || s.rmse < run.summary[best].rmse)) best = s.config;
    }
    if (best != std::string::npos) on[best] = true;
    return on;
}

void sceneTable(std::ostringstream& md, const BenchRun& run, const std::map<size_t, ErrorByPlace>& rows) {
    md << "| configuration | RMSE | border | silhouette | crease | convex | open | R < 8 px | R 8-16 px | R > 16 px "
          "| crease < 80° | crease 80-120° | crease > 120° | pixels: border / silhouette / crease / convex / open |\n"
          "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
    for (const auto& [config, e] : rows) {
        const PlaceStats& all = e.all;
        char rmse[32] = "–";
        if (all.pixels) std::snprintf(rmse, sizeof rmse, "%.4f", std::sqrt(all.sumSq / double(all.pixels)));
        md << "| " << markdownCell(run.sweep.configs[config].label) << " | " << rmse;
        for (const PlaceStats& s : e.place) md << " | " << cell(s, all);
        for (const PlaceStats& s : e.radius) md << " | " << cell(s, all);
        for (const PlaceStats& s : e.opening) md << " | " << cell(s, all);
        md << " |";
        for (size_t i = 0; i < e.place.size(); ++i) {
            char b[16];
            std::snprintf(b, sizeof b, "%s%.0f %%", i ? " / " : " ", all.pixels ? 100.0 * double(e.place[i].pixels) / double(all.pixels) : 0.0);
            md << b;
        }
        md << " |\n";
    }
    md << "\n";
}

} // namespace

std::string placeMarkdown(const BenchRun& run) {
    const std::vector<bool> on = reportedRows(run);
    std::vector<std::string> scenes;
    std::map<std::string, std::map<size_t, ErrorByPlace>> sums; // scene -> config -> over its views
    for (const ViewResult& v : run.views) {
        if (!v.hasPlaces || v.config >= on.size() || !on[v.config]) continue;
        if (!sums.count(v.scene)) scenes.push_back(v.scene);
        accumulate(sums[v.scene][v.config], v.places);
    }
    if (scenes.empty()) return "";
    std::ostringstream md;
    md << "\n### Where the error lives\n\nEach row's squared error against the truth, summed over the scene's views, "
          "split by where its pixels are (`metrics/error_places.h`), each cell the place's **share of the squared "
          "error** (the five places add to 100 %) and its RMSE. Places by priority: *border*, nearer the frame's edge "
          "than R in pixels (taps fall off the screen); *silhouette*, within 2 px of a depth discontinuity; *crease*, "
          "within 2 px of a concave normal discontinuity (binned by its opening angle, 180° flat); *convex*, an outer "
          "edge; *open*, the rest. R in pixels at each pixel bins every pixel again. A place whose share is far "
          "above its share of the pixels (last column) is where a change pays. Rows: the baseline, the front and "
          "the lowest RMSE.\n\n";
    for (const std::string& sc : scenes) {
        md << "**" << markdownCell(sc) << "**\n\n";
        sceneTable(md, run, sums[sc]);
    }
    return md.str();
}

} // namespace ssao
