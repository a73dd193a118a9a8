#include "results/split_report.h"

#include "metrics/error_split.h"
#include "output/escape.h"
#include "techniques/technique.h"
#include "util/number_text.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace ssao {

namespace {

std::string num(double v, int digits = 3) {
    return numberText(v, "%.*f", digits);
}

std::string signedNum(double v) {
    if (!std::isfinite(v)) return "–";
    char b[32];
    std::snprintf(b, sizeof b, "%+.2f", v);
    return b;
}

// RMS of a per-view value over the rows of one scene and configuration.
struct Rms {
    double sum = 0;
    int n = 0;
    void add(double v) {
        if (std::isfinite(v)) sum += v * v, ++n;
    }
    double mean() const { return n ? sum / n : NAN; } // of the squares
    double value() const { return n ? std::sqrt(sum / n) : NAN; }
};

struct Cell {
    Rms total, technique, screen, techniqueEdge, screenEdge, techniqueInterior, screenInterior;
    Rms screenOneLayer; // two-layer rows: the one-layer oracle's screen on the same views
};

// The fraction of the one-layer screen's squared error that a two-layer row's own screen (its deep
// oracle against the truth) no longer has: what the second layer closed; blank for one-layer rows.
std::string closedCell(const Cell& c) {
    if (c.screenOneLayer.n == 0 || !(c.screenOneLayer.mean() > 0)) return "";
    return num(100.0 * (1.0 - c.screen.mean() / c.screenOneLayer.mean()), 0) + " %";
}

// The rows the section reads: the baseline, each technique at its defaults (also when an earlier
// label of the same settings took its row), the tuned presets.
bool reported(const BenchConfig& c) {
    for (const std::string& a : c.aliases)
        for (const TechniqueInfo& t : techniques())
            if (a == t.id + " defaults") return true;
    return c.baseline || c.group == "technique defaults" || c.group.rfind("tuned", 0) == 0 ||
           (!c.isEngine() && c.settings.gbuffer.secondLayer);
}

} // namespace

std::string splitMarkdown(const BenchRun& run) {
    bool any = false;
    for (const ViewResult& v : run.views)
        any = any || v.hasSplit;
    if (!any) return "";
    std::vector<std::string> scenes;
    std::map<std::string, std::map<size_t, Cell>> cells;
    std::map<std::pair<std::string, std::string>, double> oneLayerScreen; // (scene, view): the baseline's
    for (const ViewResult& v : run.views)
        if (v.hasSplit && v.config == run.sweep.baseline) oneLayerScreen[{v.scene, v.viewpoint}] = v.screen.rmse;
    const nlohmann::json o = run.facts.is_object() ? run.facts.value("oracle", nlohmann::json::object())
                                                   : nlohmann::json::object();
    const bool deep = o.value("layers", 1) == 1 && o.value("layers_two_layer_rows", 1) == 2;
    for (const ViewResult& v : run.views) {
        if (!v.hasSplit || !reported(run.sweep.configs[v.config])) continue;
        if (!cells.count(v.scene)) scenes.push_back(v.scene);
        Cell& c = cells[v.scene][v.config];
        c.total.add(v.error.rmse);
        c.technique.add(v.vsOracle.rmse);
        c.screen.add(v.screen.rmse);
        c.techniqueEdge.add(v.vsOracle.rmseEdge);
        c.screenEdge.add(v.screen.rmseEdge);
        c.techniqueInterior.add(v.vsOracle.rmseInterior);
        c.screenInterior.add(v.screen.rmseInterior);
        const BenchConfig& cfg = run.sweep.configs[v.config];
        if (deep && !cfg.isEngine() && cfg.settings.gbuffer.secondLayer && oneLayerScreen.count({v.scene, v.viewpoint}))
            c.screenOneLayer.add(oneLayerScreen[{v.scene, v.viewpoint}]);
    }
    std::ostringstream md;
    md << "\n### What the screen cannot see\n\nEach error split in two against the **screen-space oracle**: the "
          "same integral, R and rays as the reference, with visibility decided only by what the G-buffer holds ("
       << o.value("layers", 1) << " depth layer(s), surfaces "
       << markdownCell(o.contains("thickness_r") ? o["thickness_r"].dump() : std::string("inf"))
       << " x R thick, " << o.value("guard_band_px", 0)
       << " px guard band; `reference_ao.h`, `screen_layers.h`). *screen* = the oracle against the truth: what no "
          "screen-space technique with this G-buffer can recover (the same for every configuration of a view with as many layers). "
          "*technique* = the AO against the oracle: what the technique's settings can still fix. RMSE over "
          "geometry pixels, RMS over views; edge/interior as in the tables above (within 3 px of a depth "
          "discontinuity or not). The two RMSEs do not add up to the total; the share columns do: "
       << kSharesHowToRead << " (from the views' mean squared errors)."
       << (deep ? " Rows with `gbuffer.second_layer` are split against the oracle of a two-layer G-buffer: their "
                  "*screen* is what even two layers miss, and *screen closed* is the part of the one-layer "
                  "screen's squared error (the baseline's, on the same views) that the second layer closed."
                : "")
       << "\n\n";
    for (const std::string& sc : scenes) {
        md << "**" << markdownCell(sc) << "**\n\n| configuration | total | technique | screen | technique share | "
              "screen share | interaction | screen closed | technique edge | screen edge | technique interior | "
              "screen interior |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        for (const auto& [config, c] : cells[sc]) {
            const ErrorShares sh = sharesOfMse(c.total.mean(), c.technique.mean(), c.screen.mean());
            md << "| " << markdownCell(run.sweep.configs[config].label) << " | " << num(c.total.value()) << " | "
               << num(c.technique.value()) << " | " << num(c.screen.value()) << " | " << num(sh.technique, 2) << " | "
               << num(sh.screen, 2) << " | " << signedNum(sh.interaction) << " | " << closedCell(c) << " | "
               << num(c.techniqueEdge.value())
               << " | " << num(c.screenEdge.value()) << " | " << num(c.techniqueInterior.value()) << " | "
               << num(c.screenInterior.value()) << " |\n";
        }
        md << "\n";
    }
    return md.str();
}

} // namespace ssao
