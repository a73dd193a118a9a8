// `ssaolab bench merge DIR... --out DIR`: the shards of a split benchmark (bench --shard K/N) joined
// into the files one run would write. Each row keeps the ratio to its own shard's baseline, so
// shards measured on different machines rank together; the report names which machine measured
// which rows.
#include "commands/merge/merge_command.h"
#include "results/bench_finish.h"

#include "results/bench_report.h"
#include "results/results_check.h"
#include "results/shard.h"
#include "cli/cli_util.h"
#include "cli/shared_options.h"
#include "settings/params.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/files.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>

namespace fs = std::filesystem;

namespace ssao {

void addBenchMergeOptions(CLI::App& cmd, BenchMergeOptions& o) {
    cmd.add_option("dirs", o.dirs, "output folders of `bench --shard K/N` runs")->type_name(kInDirs)->required();
    cmd.add_option("--out", o.out, "output folder of the merged results")->type_name(kOutDir)->capture_default_str();
    addBudgetMsOption(cmd, o.budgetMs, {"answer: the most accurate configuration within ", "its AO + denoise time"});
    addBudgetRatioOption(cmd, o.budgetRatio, {"answer: the most accurate configuration within ", ""});
    addMaxErrorOption(cmd, o.maxError);
    addObjectiveOption(cmd, o.objective, {"what the front and the answers rank by: ", "default: what the shards ran with"});
    addNoPlotFlag(cmd, o.plot);
    addQuietFlag(cmd, o.quiet);
}

namespace {

// The facts every shard must share to be one benchmark.
void checkSameBenchmark(const BenchRun& a, const BenchRun& b, const std::string& where) {
    for (const char* k : {"size", "frames", "warmup", "views_per_scene", "reference", "oracle", "motion"})
        if (a.facts.value(k, nlohmann::json()) != b.facts.value(k, nlohmann::json()))
            throw Error(where + ": its '" + k + "' (" + b.facts.value(k, nlohmann::json()).dump() +
                        ") differs from the first folder's (" + a.facts.value(k, nlohmann::json()).dump() + ")");
    // The same scenes, each of the same size and radius (the rows' error depends on both).
    auto scenes = [](const BenchRun& r) {
        std::vector<nlohmann::json> out;
        for (const auto& s : r.facts["scenes"])
            out.push_back({s.value("name", nlohmann::json()), s.value("triangles", nlohmann::json()),
                           s.value("radius", nlohmann::json())});
        return out;
    };
    if (scenes(a) != scenes(b)) throw Error(where + ": measured other scenes than the first folder");
    if (a.sweep.name != b.sweep.name || a.sweep.configs.size() != b.sweep.configs.size() ||
        a.sweep.baseline != b.sweep.baseline)
        throw Error(where + ": its sweep has other configurations than the first folder's");
    for (size_t c = 0; c < a.sweep.configs.size(); ++c)
        if (a.sweep.configs[c].label != b.sweep.configs[c].label || a.sweep.configs[c].engine != b.sweep.configs[c].engine ||
            toJson(a.sweep.configs[c].settings) != toJson(b.sweep.configs[c].settings))
            throw Error(where + ": configuration " + std::to_string(c) + " ('" + b.sweep.configs[c].label +
                        "') differs from the first folder's ('" + a.sweep.configs[c].label + "')");
}

// Copies dir/thumbs/** into out/thumbs/ (the first copy of a file wins: identical across shards).
// Only regular files inside the shard folder travel: a link (to a private file, or out of the
// folder) or a FIFO planted in a shard is skipped, and the copy goes through the atomic writer.
void copyThumbnails(const std::string& dir, const std::string& out) {
    constexpr size_t kMaxThumbnails = 100000, kMaxThumbnailBytes = size_t(4) << 20;
    for (const std::string& rel : listFilesInside(dir, "thumbs", "shard folder", kMaxThumbnails)) {
        if (fs::path(rel).extension() != ".png") continue; // the report embeds PNG files alone
        const fs::path to = fs::path(out) / rel;
        std::error_code ec;
        if (fs::exists(fs::symlink_status(to, ec))) continue;
        makeOutputFolder(to.parent_path().string());
        writeFileAtomically(to.string(), readFileInside(dir, rel, "shard thumbnail", kMaxThumbnailBytes));
    }
}

} // namespace

int runBenchMerge(const BenchMergeOptions& o) {
    std::vector<BenchRun> parts;
    for (const auto& d : o.dirs)
        parts.push_back(readResults(d));
    BenchRun run = parts[0];
    run.views.clear();
    run.shards = nlohmann::json::array();
    std::map<int, std::string> seen; // shard index -> folder
    std::map<std::tuple<std::string, std::string, size_t>, std::string> measured; // row -> folder
    int count = 0;
    for (size_t i = 0; i < parts.size(); ++i) {
        const BenchRun& p = parts[i];
        if (i) checkSameBenchmark(parts[0], p, o.dirs[i]);
        const int offset = int(run.shards.size());
        for (const auto& sh : p.shards) {
            const ShardSpec spec = parseShard(sh.value("shard", ""));
            if (count && spec.count != count)
                throw Error(o.dirs[i] + ": shard " + spec.text() + " is of another split than " + std::to_string(count) +
                            " parts");
            count = spec.count;
            if (seen.count(spec.index))
                throw Error(o.dirs[i] + ": shard " + spec.text() + " is also in " + seen[spec.index]);
            seen[spec.index] = o.dirs[i];
            run.shards.push_back(sh);
        }
        for (ViewResult v : p.views) {
            const auto [at, fresh] = measured.emplace(std::make_tuple(v.scene, v.viewpoint, v.config), o.dirs[i]);
            if (!fresh)
                throw Error(o.dirs[i] + ": its row of " + v.scene + " " + v.viewpoint + " '" +
                            run.sweep.configs[v.config].label + "' is also in " + at->second);
            if (run.views.size() == kMaxResultRows)
                throw Error("bench merge: the shards hold more than " + std::to_string(kMaxResultRows) + " rows");
            v.shard += offset;
            run.views.push_back(v);
        }
    }
    std::string missing;
    for (int k = 1; k <= count; ++k)
        if (!seen.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k) + "/" + std::to_string(count);
    if (!missing.empty()) throw Error("bench merge: shard(s) " + missing + " missing (each folder holds one shard)");

    // Viewpoints: every shard's, once, in the order one run measures them.
    for (size_t si = 0; si < run.facts["scenes"].size(); ++si) {
        std::map<long, nlohmann::json> vps;
        for (size_t pi = 0; pi < parts.size(); ++pi)
            for (const auto& vp : parts[pi].facts["scenes"][si]["viewpoints"]) {
                // One view: the same name and camera (how long its reference took, or whether it came
                // from a cache, is the shard's own).
                const auto [at, fresh] = vps.emplace(vp["index"].get<long>(), vp);
                if (!fresh && (at->second["name"] != vp["name"] || at->second["camera"] != vp["camera"]))
                    throw Error(o.dirs[pi] + ": viewpoint " + vp["name"].get<std::string>() + " of " +
                                run.facts["scenes"][si]["name"].get<std::string>() + " differs from another folder's");
            }
        nlohmann::json list = nlohmann::json::array();
        for (auto& [index, vp] : vps)
            list.push_back(vp);
        run.facts["scenes"][si]["viewpoints"] = list;
    }
    // Rows in one run's order: scene, viewpoint, configuration.
    std::map<std::pair<std::string, std::string>, long> order;
    for (size_t si = 0; si < run.facts["scenes"].size(); ++si)
        for (const auto& vp : run.facts["scenes"][si]["viewpoints"])
            order[{run.facts["scenes"][si].value("name", ""), vp.value("name", "")}] = long(si) * 1000 + vp.value("index", 0L);
    std::stable_sort(run.views.begin(), run.views.end(), [&](const ViewResult& a, const ViewResult& b) {
        const long ka = order[{a.scene, a.viewpoint}], kb = order[{b.scene, b.viewpoint}];
        return ka != kb ? ka < kb : a.config < b.config;
    });
    run.facts["merged_from"] = o.dirs;
    makeOutputFolder(o.out);
    for (const auto& d : o.dirs)
        copyThumbnails(d, o.out);
    std::string title;
    for (const auto& s : run.facts["scenes"])
        title += (title.empty() ? "" : ", ") + s.value("name", "");
    title += " | " + run.facts.value("size", "") + " | " + std::to_string(run.shards.size()) + " shards";
    if (!o.quiet)
        std::printf("bench merge: %zu shards, %zu rows, %zu configurations\n", run.shards.size(), run.views.size(),
                    run.sweep.configs.size());
    const Objective objective = o.objective.empty() ? runObjective(run) : parseObjective(o.objective);
    return finishBench(run, o.out, title, o.plot, o.quiet, Question{o.budgetMs, o.maxError, o.budgetRatio, objective});
}

} // namespace ssao
