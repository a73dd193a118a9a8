#include "bench/bench_command.h"

#include "bench/bench_report.h"
#include "bench/bench_run.h"
#include "bench/viewpoints.h"
#include "headless_runner.h"
#include "progress_bar.h"
#include "reference/reference_cache.h"
#include "render_command.h"
#include "scene/scene.h"
#include "util/error.h"
#include "util/paths.h"

#include "cli_util.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <set>
#include <filesystem>

namespace ssao {

void addBenchOptions(CLI::App& cmd, BenchOptions& o) {
    cmd.add_option("--scene", o.scenes,
                   "scene to measure (repeatable): builtin:NAME or a .gltf file "
                   "(default builtin:showcase)");
    cmd.add_option("--sweep", o.sweep, "builtin, or a sweep JSON file (see assets/bench/sweep_builtin.json)")
        ->capture_default_str();
    cmd.add_option("--size", o.size, "render size WIDTHxHEIGHT")->capture_default_str();
    cmd.add_option("--views", o.views, "viewpoints per scene: its camera, then orbits around it")
        ->capture_default_str()
        ->check(cliRange(1, 32));
    cmd.add_option("--frames", o.frames, "timed frames per configuration and view (median, min, max)")
        ->capture_default_str()
        ->check(cliRange(1, 10000));
    cmd.add_option("--warmup", o.warmup, "untimed frames before timing")
        ->capture_default_str()
        ->check(cliRange(0, 1000));
    cmd.add_option("--reference-rays", o.referenceRays, "reference rays per pixel")
        ->capture_default_str()
        ->check(cliRange(1, 1 << 16));
    cmd.add_option("--reference-variant", o.referenceVariant, "visibility (XeGTAO's) or obscurance")
        ->capture_default_str()
        ->check(CLI::IsMember({"visibility", "obscurance"}));
    cmd.add_option(
           "--radius-scene", o.radiusScene,
           "the AO radius R of every configuration and of the reference, as a fraction of the scene's "
           "bounding-box diagonal")
        ->capture_default_str()
        ->check(cliRange(0.0001, 0.5));
    cmd.add_option("--out", o.out, "output folder")->capture_default_str();
    cmd.add_option("--preset-dir", o.presetDir, "folder of user presets (default: as the app)");
    cmd.add_flag(
        "--no-plot", [&o](int64_t) { o.plot = false; }, "skip the matplotlib plot");
    cmd.add_flag("--quiet", o.quiet, "no progress output");
}

namespace {

// One scene of the benchmark: for each viewpoint, the reference (cached) and every configuration.
void benchScene(const BenchOptions& o, HeadlessRunner& runner, Renderer& r, const Sweep& sweep,
                ReferenceVariant variant, const std::string& spec, Scene& scene, BenchRun& run) {
    const float radius = o.radiusScene * 2.0f * scene.bounds.radius();
    const int w = r.width(), h = r.height();
    r.setScene(scene);
    ReferenceProvider provider(scene);
    nlohmann::json facts = {{"name", scene.name},
                            {"spec", spec},
                            {"triangles", scene.triangleCount()},
                            {"diagonal", 2.0f * scene.bounds.radius()},
                            {"radius", radius}};
    for (const auto& [vname, cam] : viewpoints(defaultCamera(scene), o.views)) {
        r.setCamera(cam);
        r.setSettings(withRadius(sweep.configs[sweep.baseline].settings, radius));
        r.render(); // fits the clip planes: the reference traces the camera as rendered
        bool cached = false;
        ReferenceImage ref;
        {
            ProgressBar bar("  reference " + scene.name + " " + vname, !o.quiet);
            ref = provider.get(r.camera(), w, h, {radius, o.referenceRays, variant}, [&](double f) { bar.update(f); },
                               &cached);
        }
        facts["viewpoints"].push_back({{"name", vname},
                                       {"camera",
                                        {{"eye", {cam.eye.x, cam.eye.y, cam.eye.z}},
                                         {"target", {cam.target.x, cam.target.y, cam.target.z}}}},
                                       {"reference_cached", cached},
                                       {"reference_seconds", ref.seconds},
                                       {"reference_ambiguous_pixels", ref.ambiguousPixels()},
                                       {"reference_mrays_per_second", ref.raysPerSecond() * 1e-6}});
        ProgressBar bar("  " + scene.name + " " + vname + ": " + std::to_string(sweep.configs.size()) +
                            " configurations",
                        !o.quiet);
        for (size_t c = 0; c < sweep.configs.size(); ++c) {
            ViewResult v = measure(r, withRadius(sweep.configs[c].settings, radius), ref, o.warmup, o.frames);
            runner.checkGl("measuring " + sweep.configs[c].label + " on " + scene.name + " " + vname);
            v.scene = scene.name;
            v.viewpoint = vname;
            v.config = c;
            run.views.push_back(v);
            bar.update(double(c + 1) / double(sweep.configs.size()));
        }
    }
    run.facts["scenes"].push_back(facts);
}

void printBenchSummary(const BenchRun& run, const Sweep& sweep, const BenchOptions& o) {
    const ConfigSummary& b = run.summary[sweep.baseline];
    std::printf("baseline %s: %.3f ms, RMSE %.4f, PSNR %.2f dB (geometry) %.2f dB (full frame)\n",
                sweep.configs[sweep.baseline].label.c_str(), b.gpuMs, b.rmse, b.psnrGeometrySrgb, b.psnrFullSrgb);
    const size_t cheap = fastestAtMostBaselineError(run), best = mostAccurate(run);
    if (cheap != std::string::npos)
        std::printf("fastest at most the baseline's error: %s: %.3f ms (%.3fx), RMSE %.4f (%.3fx)\n",
                    sweep.configs[cheap].label.c_str(), run.summary[cheap].gpuMs, run.summary[cheap].timeRatio,
                    run.summary[cheap].rmse, run.summary[cheap].rmseRatio);
    if (best != std::string::npos)
        std::printf("lowest error: %s: RMSE %.4f (%.3fx) in %.3f ms (%.3fx)\n", sweep.configs[best].label.c_str(),
                    run.summary[best].rmse, run.summary[best].rmseRatio, run.summary[best].gpuMs,
                    run.summary[best].timeRatio);
    int front = 0;
    for (const auto& s : run.summary)
        front += s.pareto;
    std::printf("%d configurations on the Pareto front; wrote %s/{results.csv,summary.csv,results.json,report.md"
                "%s}\n",
                front, o.out.c_str(), o.plot ? ",pareto.png,pareto.svg" : "");
}

} // namespace

int runBench(const BenchOptions& o) {
    // Everything that needs no GL first: bad input fails in milliseconds with one line.
    int w = 0, h = 0;
    parseSizeOption(o.size, w, h);
    const Sweep sweep = loadSweep(o.sweep, o.presetDir);
    const ReferenceVariant variant = parseVariant(o.referenceVariant);
    const std::vector<std::string> specs =
        o.scenes.empty() ? std::vector<std::string>{"builtin:showcase"} : o.scenes;
    std::vector<Scene> scenes;
    for (const auto& s : specs)
        scenes.push_back(loadNamedScene(s));

    HeadlessRunner runner;
    BenchRun run;
    run.sweep = &sweep;
    run.facts = runFacts(runner.glRenderer());
    run.facts["size"] = o.size;
    run.facts["frames"] = o.frames;
    run.facts["warmup"] = o.warmup;
    run.facts["reference"] = {{"definition", kReferenceDefinition},
                              {"variant", o.referenceVariant},
                              {"rays", o.referenceRays},
                              {"radius_scene", o.radiusScene}};
    std::unique_ptr<Renderer> r = runner.makeRenderer(w, h);
    r->setWanted(std::set<std::string>{"ao.denoised"}); // what is judged: no composite, no albedo
    if (!o.quiet)
        std::printf("bench: %zu configurations x %zu scenes x %d views at %dx%d on %s\n", sweep.configs.size(),
                    scenes.size(), o.views, w, h, runner.glRenderer().c_str());
    for (size_t si = 0; si < scenes.size(); ++si)
        benchScene(o, runner, *r, sweep, variant, specs[si], scenes[si], run);
    run.summary = summarize(run.views, sweep.configs.size(), sweep.baseline);
    writeBenchFiles(run, o.out);
    std::string title;
    for (const auto& s : scenes)
        title += (title.empty() ? "" : ", ") + s.name;
    title += " | " + o.size + " | " + runner.glRenderer();
    if (o.plot) plotBench(o.out, title, o.quiet);
    if (!o.quiet) printBenchSummary(run, sweep, o);
    long bad = 0;
    for (const auto& s : run.summary)
        bad += s.nonFinite;
    if (bad > 0)
        throw Error(std::to_string(bad) + " non-finite AO pixels in the benchmark (see results.csv)");
    return 0;
}

} // namespace ssao
