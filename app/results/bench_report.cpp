#include "results/bench_report.h"

#include "measure/motion_measure.h"
#include "results/report_html.h"
#include "results/place_report.h"
#include "results/split_report.h"
#include "metrics/error_split.h"
#include "output/escape.h"
#include "util/number_text.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/files.h"
#include "util/json_file.h"
#include "util/paths.h"
#include "util/process.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace ssao {

namespace {

// A CSV cell (missing: empty) and a Markdown number (missing: a dash).
std::string cell(double v, int digits = 6) {
    return numberText(v, "%.*g", digits, Missing::EmptyCell);
}

std::string num(double v, int digits = 6) {
    return numberText(v, "%.*g", digits, Missing::Dash);
}

const char* kMetricHeader =
    "gpu_ms,gpu_ms_min,gpu_ms_max,rmse,mae,bias,p99_abs,max_abs,psnr_geometry_srgb,"
    "psnr_full_srgb,rmse_edge,rmse_interior,ssim,nonfinite,reference_noise,frames,rmse_first_frame,"
    "gbuffer_ms,layers_ms,ao_ms,denoise_ms,composite_ms";

std::string passCells(const PassTimes& t) {
    std::string out;
    for (int k = 0; k < PassTimes::kParts; ++k)
        out += (k ? "," : "") + cell(t.ms[k], 6);
    return out;
}

std::string metricCells(const ViewResult& v) {
    const ErrorMetrics& e = v.error;
    return cell(v.gpuMs) + "," + cell(v.gpuMsMin) + "," + cell(v.gpuMsMax) + "," + cell(e.rmse) + "," +
           cell(e.mae) + "," + cell(e.bias) + "," + cell(e.p99Abs) + "," + cell(e.maxAbs) + "," +
           cell(e.psnrGeometrySrgb) + "," + cell(e.psnrFullSrgb) + "," + cell(e.rmseEdge) + "," +
           cell(e.rmseInterior) + "," + cell(e.ssim) + "," + std::to_string(e.nonFinite) + "," +
           cell(e.referenceNoise) + "," + std::to_string(v.frames) + "," + cell(v.rmseFirstFrame) + "," +
           passCells(v.passMs);
}

} // namespace

size_t fastestAtMostBaselineError(const BenchRun& run) {
    const Objective o = runObjective(run);
    const double base = objectiveError(run.summary[run.sweep.baseline], o);
    size_t best = std::string::npos;
    for (const auto& s : run.summary)
        if (s.config != run.sweep.baseline && std::isfinite(objectiveError(s, o)) && objectiveError(s, o) <= base &&
            (best == std::string::npos || s.timeRatio < run.summary[best].timeRatio))
            best = s.config;
    return best;
}

std::string timeFlag(const ConfigSummary& s) {
    return s.unsureTimeViews > 0 ? " (!)" : "";
}

size_t mostAccurate(const BenchRun& run) {
    size_t best = std::string::npos;
    for (const auto& s : run.summary)
        if (std::isfinite(s.rmse) && (best == std::string::npos || s.rmse < run.summary[best].rmse))
            best = s.config;
    return best;
}

size_t mostAccurateInMotion(const BenchRun& run) {
    size_t best = std::string::npos;
    for (const auto& s : run.summary)
        if (std::isfinite(s.motionScore) && (best == std::string::npos || s.motionScore < run.summary[best].motionScore))
            best = s.config;
    return best;
}

std::string winnersDifferLine(const BenchRun& run, const std::function<std::string(const std::string&)>& name) {
    const size_t still = mostAccurate(run), moving = mostAccurateInMotion(run);
    if (still == std::string::npos || moving == std::string::npos || still == moving) return "";
    const auto& cfgs = run.sweep.configs;
    const ConfigSummary &a = run.summary[still], &b = run.summary[moving];
    return "The still camera's lowest error, " + name(cfgs[still].label) + " (motion score " + num(a.motionScore, 4) +
           "), is not the lowest in motion: " + name(cfgs[moving].label) + " (motion score " + num(b.motionScore, 4) +
           ", " + num(b.timeRatio, 3) + "x the baseline's time).";
}

namespace {

// The split's shares of the squared error (technique, screen, interaction: they sum to 1), from the
// three RMSEs of the same pixels; empty cells without a split.
std::string shareCells(bool split, double total, double technique, double screen) {
    if (!split) return ",,";
    const ErrorShares s = sharesOfMse(total * total, technique * technique, screen * screen);
    return cell(s.technique) + "," + cell(s.screen) + "," + cell(s.interaction);
}

// results.csv: one row per scene, viewpoint and configuration.
std::string resultsCsv(const BenchRun& run) {
    const auto& cfgs = run.sweep.configs;
    std::ostringstream f;
    f << "scene,viewpoint,label,technique,baseline,pareto," << kMetricHeader
      << ",baseline_ms,time_ratio,shard,rmse_vs_oracle,rmse_screen,share_technique,share_screen,share_interaction,"
         "motion_rmse_mean,motion_rmse_max,"
         "motion_instability,motion_ghosting,motion_score,settings\n";
    for (const auto& v : run.views) {
        const BenchConfig& c = cfgs[v.config];
        const std::string shard = run.shards.size() > size_t(v.shard) ? run.shards[v.shard].value("shard", "1/1") : "1/1";
        f << csvField(v.scene) << "," << csvField(v.viewpoint) << "," << csvField(c.label) << ","
          << csvField(c.technique()) << "," << c.baseline << "," << run.summary[v.config].pareto << ","
          << metricCells(v) << "," << cell(v.baselineMs) << "," << cell(v.timeRatio) << "," << csvField(shard) << ","
          << (v.hasSplit ? cell(v.vsOracle.rmse) : "") << "," << (v.hasSplit ? cell(v.screen.rmse) : "") << ","
          << shareCells(v.hasSplit, v.error.rmse, v.vsOracle.rmse, v.screen.rmse) << ","
          << cell(v.motion.rmseMean) << "," << cell(v.motion.rmseMax) << "," << cell(v.motion.instability) << ","
          << cell(v.motion.ghosting) << "," << (v.hasMotion ? cell(motionScore(v.motion.rmseMean, v.motion.instability)) : "")
          << "," << csvField(c.keys.dump()) << "\n";
    }
    return f.str();
}

// summary.csv: one row per configuration, over every view.
std::string summaryCsv(const BenchRun& run) {
    const auto& cfgs = run.sweep.configs;
    std::ostringstream f;
    f << "label,technique,baseline,pareto,views,gpu_ms,gpu_ms_min,gpu_ms_max,rmse,mae,bias,"
         "psnr_geometry_srgb,psnr_full_srgb,rmse_edge,rmse_interior,ssim,nonfinite,time_ratio,rmse_ratio,"
         "rmse_first_frame,rmse_vs_oracle,rmse_edge_vs_oracle,rmse_interior_vs_oracle,rmse_screen,"
         "rmse_edge_screen,rmse_interior_screen,share_technique,share_screen,share_interaction,gbuffer_ms,layers_ms,ao_ms,denoise_ms,composite_ms,motion_rmse_mean,"
         "motion_instability,motion_ghosting,motion_score,motion_score_ratio,settings\n";
    for (const auto& s : run.summary) {
        const BenchConfig& c = cfgs[s.config];
        f << csvField(c.label) << "," << csvField(c.technique()) << "," << c.baseline << "," << s.pareto
          << "," << s.views << "," << cell(s.gpuMs) << "," << cell(s.gpuMsMin) << "," << cell(s.gpuMsMax)
          << "," << cell(s.rmse) << "," << cell(s.mae) << "," << cell(s.bias) << ","
          << cell(s.psnrGeometrySrgb) << "," << cell(s.psnrFullSrgb) << "," << cell(s.rmseEdge) << ","
          << cell(s.rmseInterior) << "," << cell(s.ssim) << "," << s.nonFinite << "," << cell(s.timeRatio)
          << "," << cell(s.rmseRatio) << "," << cell(s.rmseFirstFrame) << "," << cell(s.technique.rmse) << ","
          << cell(s.technique.rmseEdge) << "," << cell(s.technique.rmseInterior) << "," << cell(s.screen.rmse) << ","
          << cell(s.screen.rmseEdge) << "," << cell(s.screen.rmseInterior) << ","
          << shareCells(std::isfinite(s.technique.rmse), s.rmse, s.technique.rmse, s.screen.rmse) << ","
          << passCells(s.passMs) << ","
          << cell(s.motion.rmseMean) << "," << cell(s.motion.instability) << "," << cell(s.motion.ghosting) << ","
          << cell(s.motionScore) << "," << cell(s.motionRatio) << "," << csvField(c.keys.dump())
          << "\n";
    }
    return f.str();
}

} // namespace

void writeBenchFiles(const BenchRun& run, const std::string& dir, const Answer* answer) {
    makeOutputFolder(dir);
    writeFileAtomically((fs::path(dir) / "results.csv").string(), resultsCsv(run));
    writeFileAtomically((fs::path(dir) / "summary.csv").string(), summaryCsv(run));
    // One line: the full run (every view of every configuration, with its settings) runs to megabytes
    // indented; results.csv and summary.csv are the readable views of it.
    writeFileAtomically((fs::path(dir) / "results.json").string(), dumpJson(resultsJson(run), -1) + "\n");
    writeFileAtomically((fs::path(dir) / "report.md").string(), benchMarkdown(run, "pareto.png", answer));
    writeFileAtomically((fs::path(dir) / "report.html").string(), benchHtml(run, dir, answer));
}

// What was run, where, on what; the reference's noise; the shards of a merged run.
static std::string runFacts(const BenchRun& run) {
    const nlohmann::json& f = run.facts;
    std::ostringstream md;
    auto text = [&](const nlohmann::json& j, const char* k) { return markdownCell(j.value(k, "")); };
    md << "Run: " << text(f, "date") << ", git " << text(f, "git_revision") << ", " << text(f, "build_type")
       << " build; GL renderer **" << text(f, "gl_renderer") << "** on " << text(f, "cpu") << " ("
       << f.value("hardware_threads", 0) << " threads); " << text(f, "size") << "; " << f.value("frames", 0)
       << " timed frames per configuration and view (median) after " << f.value("warmup", 0)
       << " warm-up; reference " << text(f["reference"], "variant") << ", "
       << f["reference"].value("rays", 0)
       << " rays per pixel, R = " << f["reference"].value("radius_scene", 0.0)
       << " x the scene diagonal.\n\nScenes and viewpoints: ";
    for (size_t i = 0; i < f["scenes"].size(); ++i) {
        const auto& s = f["scenes"][i];
        md << (i ? ", " : "") << text(s, "name") << " (" << s["viewpoints"].size() << " views, R "
           << num(s.value("radius", 0.0), 4) << ")";
    }
    md << ".";
    double noise = 0;
    for (const auto& v : run.views)
        noise += v.error.referenceNoise * v.error.referenceNoise;
    if (!run.views.empty())
        md << "\n\nThe reference's own noise (RMS over geometry pixels of its per-pixel standard error, over "
              "all views): "
           << num(std::sqrt(noise / double(run.views.size())), 3)
           << " — errors well above it are the techniques', not the reference's.";
    if (run.shards.size() > 1) {
        md << "\n\nMerged from " << run.shards.size()
           << " shards. Times are only comparable on one machine: every row is divided by the baseline its own "
              "shard measured on the same view, and configurations are ranked by those ratios (the ms columns "
              "mix machines).\n\n| shard | host | CPU | GL renderer | date | git | rows |\n|---|---|---|---|---|---|---:|\n";
        for (const auto& sh : run.shards)
            md << "| " << text(sh, "shard") << " | " << text(sh, "hostname") << " | " << text(sh, "cpu") << " | "
               << text(sh, "gl_renderer") << " | " << text(sh, "date") << " | " << text(sh, "git_revision") << " | "
               << sh.value("rows", 0) << " |\n";
    }
    return md.str();
}

// Where the time goes: each pass of a frame for the front and the baseline (the G-buffer and the
// composite are the same fixed cost for every row; AO + denoise is what the rows compare).
std::string passMarkdown(const BenchRun& run) {
    std::ostringstream md;
    std::vector<const ConfigSummary*> rows;
    for (const auto& s : run.summary)
        if ((s.pareto || s.config == run.sweep.baseline) && std::isfinite(s.passMs.ms[2])) rows.push_back(&s);
    if (rows.empty()) return "";
    std::sort(rows.begin(), rows.end(), [](auto* a, auto* b) { return a->timeRatio < b->timeRatio; });
    md << "\n### Where the time goes (front and baseline)\n\nGPU ms per part of the frame, mean over views of each "
          "view's median: the G-buffer, its extra layers (guard band, back faces), the AO (with the position "
          "pyramid), the denoise stage (upsample and temporal blend included). The composite does not run "
          "in `bench`, which judges the AO.\n\n| configuration | G-buffer | layers | AO | denoise |\n"
          "|---|---:|---:|---:|---:|\n";
    for (const ConfigSummary* s : rows) {
        const PassTimes& t = s->passMs;
        md << "| " << markdownCell(run.sweep.configs[s->config].label);
        for (int k = 0; k < 4; ++k)
            md << " | " << num(t.ms[k], 3);
        md << " |\n";
    }
    return md.str();
}

// bench --motion: every configuration ranked on a still frame and in motion ("" without).
static std::string motionMarkdown(const BenchRun& run) {
    if (!run.facts.contains("motion")) return "";
    const nlohmann::json& p = run.facts["motion"];
    auto score = [](const ConfigSummary& s) { return s.motionScore; };
    std::vector<const ConfigSummary*> still, moving;
    for (const auto& s : run.summary)
        if (std::isfinite(s.rmse) && std::isfinite(s.motion.rmseMean)) still.push_back(&s), moving.push_back(&s);
    if (moving.empty()) return "";
    std::stable_sort(still.begin(), still.end(), [](auto* a, auto* b) { return a->rmse < b->rmse; });
    std::stable_sort(moving.begin(), moving.end(), [&](auto* a, auto* b) { return score(*a) < score(*b); });
    std::vector<size_t> stillRank(run.summary.size(), 0);
    for (size_t i = 0; i < still.size(); ++i) stillRank[still[i]->config] = i + 1;
    std::ostringstream md;
    md << "\n### In motion\n\nEach view's camera path: " << p.value("frames", 0) << " frames orbiting "
       << num(p.value("orbit_deg", 0.0), 3) << " degrees about the view's target and moving "
       << num(p.value("dolly", 0.0), 3) << " of the way toward it, each frame against its own reference; temporal "
          "accumulation carries its history along the path. Motion RMSE: RMS over views of the mean per-frame "
          "RMSE. Instability: RMS of the AO's frame-to-frame change minus the reference's at the same surface "
          "point (flicker, crawling grain). Ghosting: mean |error| in the first 2 frames after a disocclusion minus "
          "the mean at stable pixels. Motion score: sqrt(motion RMSE^2 + instability^2), best first.\n\n"
          "| configuration | x baseline time | still RMSE | motion RMSE | instability | ghosting | motion score | still rank | motion rank |\n"
          "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (size_t i = 0; i < moving.size(); ++i) {
        const ConfigSummary& s = *moving[i];
        md << "| " << markdownCell(run.sweep.configs[s.config].label) << " | " << num(s.timeRatio, 3) << timeFlag(s) << " | " << num(s.rmse, 4) << " | "
           << num(s.motion.rmseMean, 4) << " | " << num(s.motion.instability, 4) << " | " << (std::isfinite(s.motion.ghosting) ? num(s.motion.ghosting, 3) : std::string("n/a"))
           << " | " << num(score(s), 4) << " | " << stillRank[s.config] << " | " << i + 1 << " |\n";
    }
    return md.str();
}

// bench --engines: what the engines' rows are and how their time differs from the others' ("" without).
static std::string engineMarkdown(const BenchRun& run) {
    std::string names;
    for (const BenchConfig& c : run.sweep.configs)
        if (c.isEngine())
            names += (names.empty() ? "" : ", ") + markdownCell(c.label) + " (" + markdownCell(c.engine.value("package", "")) +
                     " " + markdownCell(c.engine.value("version", "")) + ")";
    if (names.empty()) return "";
    return "\n### Web engines\n\n" + names + ": each engine run in Chromium on the same views, camera, size and R, "
           "its AO read back and scored against the same reference (defaults: the engine's own with every length set "
           "from R; as shipped: the package's defaults verbatim). Their time is not a GPU timer query: it is the frame with the pass minus the frame without, each "
           "ended by a 1-pixel read, median over the timed frames after 3 warm-up frames, on Chromium's WebGL; their "
           "ratio to the baseline compares that with the baseline's GL timer query on the same view.\n";
}

std::string benchMarkdown(const BenchRun& run, const std::string& plotFile, const Answer* answer) {
    const auto& cfgs = run.sweep.configs;
    const ConfigSummary& base = run.summary[run.sweep.baseline];
    std::ostringstream md;
    if (answer) md << answerMarkdown(run, *answer);
    md << runFacts(run);
    md << "\n\n![time against error](" << plotFile << ")\n\n";
    md << "Baseline: **" << markdownCell(cfgs[run.sweep.baseline].label) << "**: " << num(base.gpuMs, 4)
       << " ms AO + denoise, geometry RMSE " << num(base.rmse, 4) << ", PSNR "
       << num(base.psnrGeometrySrgb, 4) << " dB (geometry, sRGB), " << num(base.psnrFullSrgb, 4)
       << " dB full frame.\n\n";
    const Objective o = runObjective(run);
    if (run.facts.contains("motion"))
        md << "Objective: **" << objectiveTitle(o)
           << "** (`--objective " << objectiveKey(o) << "`): the front, the answers and the fastest at most the "
              "baseline's error rank by it.\n\n";
    const size_t cheap = fastestAtMostBaselineError(run), best = mostAccurate(run);
    if (cheap != std::string::npos)
        md << "Fastest configuration at most as wrong as the baseline " << objectiveWhere(o) << ": **"
           << markdownCell(cfgs[cheap].label) << "**: " << num(run.summary[cheap].gpuMs, 4) << " ms"
           << timeFlag(run.summary[cheap]) << " (" << num(run.summary[cheap].timeRatio, 3) << "x the baseline's time), "
           << objectiveErrorName(o) << " " << num(objectiveError(run.summary[cheap], o), 4) << " ("
           << num(objectiveRatio(run.summary[cheap], o), 3) << "x).\n\n";
    if (best != std::string::npos)
        md << "Lowest error" << (run.facts.contains("motion") ? " on a still camera" : "") << ": **"
           << markdownCell(cfgs[best].label) << "**: RMSE " << num(run.summary[best].rmse, 4) << " ("
           << num(run.summary[best].rmseRatio, 3) << "x the baseline's) in "
           << num(run.summary[best].gpuMs, 4) << " ms" << timeFlag(run.summary[best]) << " (" << num(run.summary[best].timeRatio, 3) << "x).\n\n";
    if (const size_t m = mostAccurateInMotion(run); m != std::string::npos) {
        const ConfigSummary& s = run.summary[m];
        md << "Lowest error in motion (motion score): **" << markdownCell(cfgs[m].label) << "**: "
           << num(s.motionScore, 4) << " in " << num(s.gpuMs, 4) << " ms" << timeFlag(s) << " ("
           << num(s.timeRatio, 3) << "x).\n\n";
        if (const std::string d = winnersDifferLine(run, markdownCell); !d.empty()) md << d << "\n\n";
    }
    const bool moving = run.facts.contains("motion");
    auto table = [&](bool frontOnly) {
        md << "| configuration | AO+denoise ms | x baseline | RMSE | x baseline | bias | PSNR geo dB | PSNR "
              "full dB "
              "| SSIM | edge RMSE | interior RMSE | 1st-frame RMSE | "
           << (moving ? "motion score | x baseline | " : "") << "front "
           << "|\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|" << (moving ? "---:|---:|" : "") << ":-:|\n";
        std::vector<const ConfigSummary*> rows;
        for (const auto& s : run.summary)
            if (!frontOnly || s.pareto || s.config == run.sweep.baseline) rows.push_back(&s);
        std::sort(rows.begin(), rows.end(), [](auto* a, auto* b) { return a->timeRatio < b->timeRatio; });
        for (const ConfigSummary* s : rows)
            md << "| " << markdownCell(cfgs[s->config].label) << " | " << num(s->gpuMs, 4) << timeFlag(*s) << " | " << num(s->timeRatio, 3)
               << " | " << num(s->rmse, 4) << " | " << num(s->rmseRatio, 3) << " | " << num(s->bias, 3)
               << " | " << num(s->psnrGeometrySrgb, 4) << " | " << num(s->psnrFullSrgb, 4) << " | "
               << num(s->ssim, 4) << " | " << num(s->rmseEdge, 4) << " | " << num(s->rmseInterior, 4) << " | "
               << num(s->rmseFirstFrame, 4) << " | "
               << (moving ? num(s->motionScore, 4) + " | " + num(s->motionRatio, 3) + " | " : std::string())
               << (s->pareto ? "yes" : "") << " |\n";
    };
    md << "### Pareto front" << (moving ? std::string(" ") + objectiveWhere(o) + " (" + objectiveErrorName(o) + ")" : "")
       << " and the baseline, fastest first\n\n";
    table(true);
    md << passMarkdown(run);
    md << splitMarkdown(run);
    md << placeMarkdown(run);
    md << motionMarkdown(run);
    md << engineMarkdown(run);
    md << "\n### Every configuration\n\n";
    table(false);
    md << "\nTime: a time marked (!) is unsure: on at least one view its slowest timed frame took more than "
       << num(kUnsureTimeSpread, 2) << "x its median (measure again with more --frames). "
       << "GPU timer queries (GL_TIME_ELAPSED) of every pass but the G-buffer and the composite, "
          "mean over views of each view's median; x baseline: the geometric mean over views of each view's "
          "median divided by the baseline's median on that view (the front and the ranking use it). RMSE: linear AO over the reference's geometry pixels, "
          "sqrt of the mean MSE over views; PSNR of the mean sRGB MSE over views (XeGTAO's averaging); bias "
          "= "
          "mean(SSAO - reference), + = too bright. With temporal accumulation the RMSE is of the image after "
          "its "
          "frames are blended; 1st-frame RMSE is of its first frame alone.\n";
    return md.str();
}

bool plotBench(const std::string& dir, const std::string& title, bool quiet, Objective objective) {
    const std::string script = dataRoot() + "/tools/plot_pareto.py"; // the source tree and an installation alike
    // Debian's python3 (python3-matplotlib) first: a pyenv/venv python3 on PATH may lack matplotlib.
    const std::string py = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    // matplotlib follows links: it draws into a folder made for it alone (mkdtemp: new, 0700), and
    // its files reach `dir` through the reads and the atomic writer every output uses.
    std::string staging = (fs::path(dir) / ".plot-XXXXXX").string();
    if (!::mkdtemp(staging.data())) throw Error("cannot write to " + dir + ": cannot make a folder for the plot");
    struct Cleanup {
        std::string path;
        ~Cleanup() {
            std::error_code ec;
            fs::remove_all(path, ec);
        }
    } cleanup{staging};
    // Every value as one argv element in --key=value form: a title starting with '-' stays a title.
    const ProgramRun r = runProgram({py, script, "--summary=" + dir + "/summary.csv", "--results=" + dir + "/results.csv",
                                     "--out=" + staging + "/pareto", "--title=" + title,
                                     std::string("--error=") + (objective == Objective::Motion ? "motion_score" : "rmse")},
                                    quiet ? ChildStream::Discard : ChildStream::Inherit,
                                    quiet ? ChildStream::Discard : ChildStream::Inherit);
    if (!r.started || r.exitCode != 0) {
        std::fprintf(stderr,
                     "note: the plot was not drawn (%s %s; install python3-matplotlib); the CSV, "
                     "JSON and report.md are complete\n",
                     script.c_str(), r.started ? "failed" : "could not be started");
        return false;
    }
    try {
        for (const std::string& name : listFilesInside(staging, "", "plot folder", 16))
            writeFileAtomically((fs::path(dir) / name).string(), readFileInside(staging, name, "plot"));
    } catch (const Error& e) { // the staging folder is ours, not the user's: errors name the output folder
        std::string msg = e.what();
        for (size_t at = msg.find(staging); at != std::string::npos; at = msg.find(staging, at + dir.size()))
            msg.replace(at, staging.size(), dir);
        throw Error(msg);
    }
    return true;
}

} // namespace ssao
