#include "commands/stress/stress_command.h"
#include "scene/load/load_scene.h"
#include "gl/readback.h"

#include "base/image.h"
#include "cli/headless_runner.h"
#include "cli/scene_options.h"
#include "renderer.h"
#include "scene/view_fit.h"
#include "settings/params.h"
#include "commands/stress/stress_cases.h"
#include "commands/stress/stress_report.h"
#include "techniques/technique.h"
#include "util/error.h"
#include "util/files.h"
#include "util/paths.h"

#include "cli/cli_util.h"
#include "cli/shared_options.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <set>
#include <filesystem>

namespace ssao {

void addStressOptions(CLI::App& cmd, StressOptions& o) {
    addSceneOption(cmd, o.scenes, {"", "default builtin:showcase"});
    cmd.add_option("--technique", o.techniques, "technique (repeatable; default every one)")->type_name("TECHNIQUE");
    addSizeOption(cmd, o.size);
    cmd.add_option("--tolerance", o.tolerance,
                   "largest RMSE against the benign render allowed where AO must not change (scale, translation)")
        ->capture_default_str()
        ->check(cliRange(0.0, 1.0));
    cmd.add_option("--out", o.out, "output folder (stress.json, stability.md)")->type_name(kOutDir)->capture_default_str();
    addQuietFlag(cmd, o.quiet);
}

namespace {

struct Frame {
    Image raw, ao, mask;
};

Frame renderFrame(Renderer& r) {
    do
        r.render();
    while (r.accumulating());
    return {readBack(r.texture("ao.raw"), 1), readBack(r.texture("ao.denoised"), 1),
            readBack(r.texture("gbuffer.depth"), 1)};
}

// Non-finite values, and finite values outside [0,1], over every pixel.
void countBad(const Image& img, long& nonFinite, long& outside) {
    for (float v : img.data) {
        if (!std::isfinite(v)) ++nonFinite;
        else if (v < 0.0f || v > 1.0f) ++outside;
    }
}

// RMSE over pixels with geometry in both, and the share of pixels whose coverage differs.
void compare(const Frame& a, const Frame& b, double& rmse, double& coverage) {
    double se = 0;
    long n = 0, differ = 0;
    const size_t count = std::min(a.ao.data.size(), b.ao.data.size());
    for (size_t i = 0; i < count; ++i) {
        const bool ga = a.mask.data[i] > 0.0f, gb = b.mask.data[i] > 0.0f;
        if (ga != gb) ++differ;
        if (!ga || !gb) continue;
        const double d = double(a.ao.data[i]) - double(b.ao.data[i]);
        se += d * d, ++n;
    }
    rmse = n ? std::sqrt(se / double(n)) : 0.0;
    coverage = count ? double(differ) / double(count) : 0.0;
}

} // namespace

namespace {

// The renderers and the benign frame one technique's cases are compared with.
struct StressBench {
    HeadlessRunner& runner;
    Renderer& r;
    Renderer& plane; // builtin:plane in its own view: AO 1 by definition
};

// Renders one case into its row (a guard's refusal is a row too, not a failure of the run).
StressRow runCase(StressBench& b, const StressCase& sc, const Scene& base, const Camera& cam0, const Settings& s,
                  const Frame& benign, bool& transformed) {
    StressRow row;
    row.axis = sc.axis, row.variant = sc.variant, row.invariant = sc.invariant, row.compared = sc.compared;
    try {
        const bool moves = sc.scale != 1.0 || sc.offset != glm::dvec3(0.0) || sc.geometry;
        Scene moved;
        if (moves) moved = transformScene(base, sc.scale, sc.offset, sc.sceneOrigin);
        if (sc.geometry) sc.geometry(moved);
        const Scene& scene = moves ? moved : base;
        if (moves || transformed) b.r.setScene(scene);
        transformed = moves;
        Camera c = transformCamera(cam0, base, scene, sc.scale, sc.offset);
        c.clip = ClipMode::Fit;
        if (sc.camera) sc.camera(c, scene);
        if (sc.nearZ > 0.0f) {
            c.clip = ClipMode::Fixed;
            const double diag = 2.0 * double(scene.bounds.radius());
            c.nearZ = float(double(sc.nearZ) * diag);
            c.farZ = float(double(sc.farZ) * diag); // inf stays inf
        }
        if (sc.depth) c.depth = *sc.depth;
        if (sc.projection) c.projectionKind = *sc.projection;
        validateCamera(c); // a refused camera is a row, not a GL error
        Settings cs = s;
        if (sc.settings) sc.settings(cs);
        b.r.setCamera(c);
        b.r.setSettings(cs);
        const Frame f = renderFrame(b.r);
        countBad(f.raw, row.nonFinite, row.outside);
        countBad(f.ao, row.nonFinite, row.outside);
        const Stats st = stats(f.ao, &f.mask);
        row.mean = st.count ? st.mean : 1.0;
        row.geometry = st.count;
        if (sc.invariant || sc.compared) compare(f, benign, row.rmse, row.coverage);
        if (sc.settings) { // settings cases: an open plane must stay open
            b.plane.setSettings(cs);
            const Frame pf = renderFrame(b.plane);
            countBad(pf.raw, row.nonFinite, row.outside);
            countBad(pf.ao, row.nonFinite, row.outside);
            row.planeMean = stats(pf.ao, &pf.mask).mean;
            row.unphysical = unphysicalReason(cs);
        }
        row.status = "ok";
    } catch (const Error& e) {
        row.status = "refused";
        row.message = e.what();
    }
    b.runner.checkGl("in stress case " + sc.axis + " " + sc.variant);
    return row;
}

} // namespace

int runStress(const StressOptions& o) {
    int w = 0, h = 0;
    parseSizeOption(o.size, w, h);
    if (!(o.tolerance >= 0.0 && o.tolerance <= 1.0)) throw Error("--tolerance must be a number in [0, 1]");
    makeOutputFolder(o.out); // before the cases run, not after
    std::vector<std::string> techs = o.techniques;
    if (techs.empty())
        for (const auto& t : techniques())
            techs.push_back(t.id);
    for (const auto& t : techs)
        findTechnique(t); // names the known ones
    const std::vector<std::string> specs =
        o.scenes.empty() ? std::vector<std::string>{"builtin:showcase"} : o.scenes;

    HeadlessRunner runner;
    std::unique_ptr<Renderer> r = runner.makeRenderer(w, h), plane = runner.makeRenderer(w, h);
    const std::set<std::string> judged{"ao.raw", "ao.denoised"}; // no composite, no albedo
    r->setWanted(judged);
    plane->setWanted(judged);
    const Scene planeScene = loadScene("builtin:plane");
    plane->setScene(planeScene);
    plane->setCamera(*planeScene.camera);
    StressBench bench{runner, *r, *plane};
    StressRun run;
    run.size = o.size;
    run.tolerance = o.tolerance;
    for (const auto& spec : specs) {
        const Scene base = loadNamedScene(spec);
        const Camera cam0 = defaultCamera(base);
        for (const auto& tech : techs) {
            Settings s = defaultSettings();
            s.ao.technique = tech;
            r->setScene(base);
            Camera c0 = cam0;
            c0.clip = ClipMode::Fit;
            r->setCamera(c0);
            r->setSettings(s);
            const Frame benign = renderFrame(*r);
            const std::vector<StressCase> cases = stressCases(tech);
            if (!o.quiet) std::fprintf(stderr, "stress: %s %s: %zu cases\n", base.name.c_str(), tech.c_str(), cases.size());
            bool transformed = false;
            for (const StressCase& sc : cases) {
                StressRow row = runCase(bench, sc, base, cam0, s, benign, transformed);
                row.scene = base.name, row.technique = tech;
                run.rows.push_back(std::move(row));
            }
            if (transformed) r->setScene(base);
        }
    }
    writeStressFiles(run, o.out);
    const StressVerdict v = verdict(run);
    std::printf("stress: %zu cases, %ld non-finite and %ld out-of-range values, %d invariance cases over RMSE %g, "
                "%d settings that darken an open plane, %d refused by a guard; wrote %s/{stress.json,stability.md}\n",
                run.rows.size(), v.nonFinite, v.outside, v.invarianceFailures, o.tolerance, v.planeFailures,
                v.refused, o.out.c_str());
    if (!v.ok()) throw Error("stress found failing cases (see " + o.out + "/stability.md)");
    return 0;
}

} // namespace ssao
