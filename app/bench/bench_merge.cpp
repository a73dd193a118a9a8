// `ssaolab bench merge DIR... --out DIR`: the shards of a split benchmark (bench --shard K/N) joined
// into the files one run would write. Each row keeps the ratio to its own shard's baseline, so
// shards measured on different machines rank together; the report names which machine measured
// which rows.
#include "bench/bench_command.h"

#include "bench/bench_report.h"
#include "bench/shard.h"
#include "cli_util.h"
#include "settings/params.h"
#include "util/error.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

namespace fs = std::filesystem;

namespace ssao {

void addBenchMergeOptions(CLI::App& cmd, BenchMergeOptions& o) {
    cmd.add_option("dirs", o.dirs, "output folders of `bench --shard K/N` runs")->required();
    cmd.add_option("--out", o.out, "output folder of the merged results")->capture_default_str();
    cmd.add_option("--budget-ms", o.budgetMs, "answer: the most accurate configuration within this time (ms)")
        ->check(cliRange(1e-6, 1e6));
    cmd.add_option("--max-error", o.maxError, "answer: the fastest configuration whose RMSE is at most this")
        ->check(cliRange(1e-9, 1.0));
    cmd.add_flag(
        "--no-plot", [&o](int64_t) { o.plot = false; }, "skip the matplotlib plot");
    cmd.add_flag("--quiet", o.quiet, "no progress output");
}

namespace {

// The facts every shard must share to be one benchmark.
void checkSameBenchmark(const BenchRun& a, const BenchRun& b, const std::string& where) {
    for (const char* k : {"size", "frames", "warmup", "views_per_scene", "reference"})
        if (a.facts.value(k, nlohmann::json()) != b.facts.value(k, nlohmann::json()))
            throw Error(where + ": its '" + k + "' (" + b.facts.value(k, nlohmann::json()).dump() +
                        ") differs from the first folder's (" + a.facts.value(k, nlohmann::json()).dump() + ")");
    std::vector<std::string> na, nb;
    for (const auto& s : a.facts["scenes"])
        na.push_back(s.value("name", ""));
    for (const auto& s : b.facts["scenes"])
        nb.push_back(s.value("name", ""));
    if (na != nb) throw Error(where + ": measured other scenes than the first folder");
    if (a.sweep.configs.size() != b.sweep.configs.size() || a.sweep.baseline != b.sweep.baseline)
        throw Error(where + ": its sweep has other configurations than the first folder's");
    for (size_t c = 0; c < a.sweep.configs.size(); ++c)
        if (a.sweep.configs[c].label != b.sweep.configs[c].label ||
            toJson(a.sweep.configs[c].settings) != toJson(b.sweep.configs[c].settings))
            throw Error(where + ": configuration " + std::to_string(c) + " ('" + b.sweep.configs[c].label +
                        "') differs from the first folder's ('" + a.sweep.configs[c].label + "')");
}

// Copies dir/thumbs/** into out/thumbs/ (the first copy of a file wins: identical across shards).
void copyThumbnails(const std::string& dir, const std::string& out) {
    const fs::path from = fs::path(dir) / "thumbs";
    std::error_code ec;
    if (!fs::is_directory(from, ec)) return;
    for (auto it = fs::recursive_directory_iterator(from, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec)) {
        if (!it->is_regular_file(ec) || it->is_symlink(ec)) continue;
        const fs::path to = fs::path(out) / "thumbs" / fs::relative(it->path(), from, ec);
        fs::create_directories(to.parent_path(), ec);
        if (!fs::exists(to, ec)) fs::copy_file(it->path(), to, ec);
        if (ec) throw Error("cannot copy " + it->path().string() + " to " + to.string() + ": " + ec.message());
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
        for (const BenchRun& p : parts)
            for (const auto& vp : p.facts["scenes"][si]["viewpoints"])
                vps.emplace(vp.value("index", 0L), vp);
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
    std::error_code ec;
    fs::create_directories(o.out, ec);
    if (ec) throw Error("cannot create " + o.out + ": " + ec.message());
    for (const auto& d : o.dirs)
        copyThumbnails(d, o.out);
    std::string title;
    for (const auto& s : run.facts["scenes"])
        title += (title.empty() ? "" : ", ") + s.value("name", "");
    title += " | " + run.facts.value("size", "") + " | " + std::to_string(run.shards.size()) + " shards";
    if (!o.quiet)
        std::printf("bench merge: %zu shards, %zu rows, %zu configurations\n", run.shards.size(), run.views.size(),
                    run.sweep.configs.size());
    return finishBench(run, o.out, title, o.plot, o.quiet, Question{o.budgetMs, o.maxError});
}

} // namespace ssao
