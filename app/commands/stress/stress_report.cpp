#include "commands/stress/stress_report.h"

#include "output/escape.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/files.h"
#include "util/json_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

namespace ssao {

StressVerdict verdict(const StressRun& run) {
    StressVerdict v;
    for (const auto& r : run.rows) {
        v.nonFinite += r.nonFinite;
        v.outside += r.outside;
        if (r.status == "refused") ++v.refused;
        if (r.status == "ok" && r.invariant && r.rmse > run.tolerance) ++v.invarianceFailures;
        if (r.status == "ok" && r.planeFails()) ++v.planeFailures;
    }
    return v;
}

namespace {
std::string cell(const StressRow& r, double tolerance) {
    char buf[96];
    if (r.status == "refused") return "refused";
    std::string s;
    if (r.nonFinite) s += std::to_string(r.nonFinite) + " NaN/inf ";
    if (r.outside) s += std::to_string(r.outside) + " outside [0,1] ";
    if (r.compared && !r.invariant && s.empty()) { // the mean, and how far it is from the benign render
        std::snprintf(buf, sizeof buf, r.geometry ? "%.3f, RMSE %.4f" : "%.3f (empty)", r.mean, r.rmse);
        s = buf;
    } else if (r.invariant) {
        std::snprintf(buf, sizeof buf, "%s%.4f", r.rmse > tolerance ? "**" : "", r.rmse);
        s += buf;
        if (r.rmse > tolerance) s += "**";
        if (r.coverage > 0.0) {
            std::snprintf(buf, sizeof buf, " (%.1f%% px moved)", 100.0 * r.coverage);
            s += buf;
        }
    } else if (s.empty()) {
        std::snprintf(buf, sizeof buf, r.geometry ? "%.3f" : "%.3f (empty)", r.mean);
        s = buf;
    }
    if (r.planeMean >= 0.0 && r.planeMean < 0.99) { // an open plane darkened: flagged unless by design
        std::snprintf(buf, sizeof buf, r.unphysical.empty() ? "; **plane %.3f**" : "; plane %.3f (by design)",
                      r.planeMean);
        s += buf;
    }
    return s;
}
} // namespace

std::string stabilityMarkdown(const StressRun& run) {
    std::ostringstream md;
    const StressVerdict v = verdict(run);
    md << "Every technique under every case at " << markdownCell(run.size) << ": " << run.rows.size() << " renders, "
       << v.nonFinite << " non-finite and " << v.outside << " out-of-range values, " << v.invarianceFailures
       << " invariance cases above RMSE " << run.tolerance << ", " << v.planeFailures
       << " settings that darken an open plane below 0.99, " << v.refused
       << " cases refused by a guard with a clear error.\n\n"
       << "Cells: the mean denoised AO over geometry (\"(empty)\": no geometry in view), with the RMSE "
          "against the benign render (fitted planes) for standard-depth planes; for the cases that must "
          "not change AO (scale, translate, reversed-depth planes) the RMSE alone, in bold above the "
          "tolerance, with the share of pixels whose coverage moved; NaN/inf or out-of-range counts when "
          "there are any; \"refused\" where a guard stops the case (messages below). Every case that "
          "changes settings is also rendered on an open plane (builtin:plane, AO 1): a mean below 0.99 is "
          "shown as \"plane\" and fails the run, unless the technique declares the setting unphysical by "
          "design (a seed's artefact, reasons below).\n";
    std::vector<std::string> scenes, techs, axes;
    auto addUnique = [](std::vector<std::string>& v, const std::string& s) {
        if (std::find(v.begin(), v.end(), s) == v.end()) v.push_back(s);
    };
    for (const auto& r : run.rows)
        addUnique(scenes, r.scene), addUnique(techs, r.technique), addUnique(axes, r.axis);
    std::map<std::string, std::string> refusals;
    for (const auto& scene : scenes)
        for (const auto& axis : axes) {
            std::vector<std::string> variants;
            std::map<std::pair<std::string, std::string>, const StressRow*> at;
            for (const auto& r : run.rows)
                if (r.scene == scene && r.axis == axis) {
                    addUnique(variants, r.variant);
                    at[{r.variant, r.technique}] = &r;
                    if (r.status == "refused") refusals[r.message] += (refusals[r.message].empty() ? "" : ", ") +
                                                                      r.technique + " " + r.variant;
                }
            if (variants.empty()) continue;
            md << "\n### " << markdownCell(scene) << ": " << markdownCell(axis) << "\n\n| case |";
            for (const auto& t : techs)
                md << " " << markdownCell(t) << " |";
            md << "\n|---|";
            for (size_t i = 0; i < techs.size(); ++i)
                md << "---:|";
            md << "\n";
            for (const auto& var : variants) {
                md << "| " << markdownCell(var) << " |";
                for (const auto& t : techs) {
                    auto it = at.find({var, t});
                    md << " " << (it == at.end() ? std::string("–") : cell(*it->second, run.tolerance)) << " |";
                }
                md << "\n";
            }
        }
    std::map<std::string, std::string> byDesign;
    for (const auto& r : run.rows)
        if (!r.unphysical.empty() && r.planeMean >= 0.0 && r.planeMean < 0.99)
            byDesign[r.unphysical] += (byDesign[r.unphysical].find(r.technique + " " + r.variant) == std::string::npos
                                           ? (byDesign[r.unphysical].empty() ? "" : ", ") + r.technique + " " + r.variant
                                           : "");
    if (!byDesign.empty()) {
        md << "\n### Unphysical by design\n\n";
        for (const auto& [why, where] : byDesign)
            md << "- " << markdownCell(why) << " (" << markdownCell(where) << ")\n";
    }
    if (!refusals.empty()) {
        md << "\n### Refused cases\n\n";
        for (const auto& [msg, where] : refusals)
            md << "- " << markdownCell(msg) << " (" << markdownCell(where.substr(0, 300)) << (where.size() > 300 ? "..." : "")
               << ")\n";
    }
    return md.str();
}

void writeStressFiles(const StressRun& run, const std::string& dir) {
    makeOutputFolder(dir);
    nlohmann::json j = {{"size", run.size}, {"tolerance", run.tolerance}, {"rows", nlohmann::json::array()}};
    for (const auto& r : run.rows)
        j["rows"].push_back({{"scene", r.scene}, {"technique", r.technique}, {"axis", r.axis},
                             {"variant", r.variant}, {"status", r.status}, {"message", r.message},
                             {"invariant", r.invariant}, {"compared", r.compared}, {"nonfinite", r.nonFinite}, {"outside", r.outside},
                             {"geometry_pixels", r.geometry}, {"mean", r.mean}, {"rmse", r.rmse},
                             {"coverage_moved", r.coverage}, {"plane_mean", r.planeMean},
                             {"unphysical", r.unphysical}});
    writeFileAtomically(dir + "/stress.json", dumpJson(j) + "\n");
    writeFileAtomically(dir + "/stability.md", stabilityMarkdown(run));
}

} // namespace ssao
