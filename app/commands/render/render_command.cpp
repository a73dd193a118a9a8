#include "commands/render/render_command.h"
#include "scene/load/load_scene.h"

#include "base/image.h"
#include "measure/motion_measure.h"
#include "display/capture.h"
#include "cli/headless_runner.h"
#include "metrics/evaluate.h"
#include "metrics/radius_check.h"
#include "output/reference_report.h"
#include "output/report.h"
#include "cli/progress_bar.h"
#include "reference/reference_cache.h"
#include "reference/screen_layers.h"
#include "scene/scene.h"
#include "scene/view_fit.h"
#include "settings/applicability.h"
#include "settings/params.h"
#include "settings/preset.h"
#include "settings/preset_store.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/files.h"
#include "util/json_file.h"
#include "util/paths.h"

#include "cli/cli_util.h"
#include "cli/shared_options.h"
#include "cli/scene_options.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

namespace ssao {

void addRenderOptions(CLI::App& cmd, RenderOptions& o) {
    addSceneOption(cmd, o.scene, {"", "default: the preset's scene, else builtin:showcase"});
    o.preset = kStartPreset; // one default everywhere: the window's first frame (settings/preset.h)
    cmd.add_option(
        "--preset", o.preset,
        "preset JSON file, or a name: the seed presets (e.g. learnopengl), then the ones saved in the app")
        ->type_name(kInFile)
        ->capture_default_str();
    addSetOption(cmd, o.sets);
    addSizeOption(cmd, o.size, {"", "default: the preset's size, else 1280x720"});
    cmd.add_option("--camera", o.camera, "eye,target[,up[,fov_deg[,near,far]]] as comma-separated numbers")->type_name("EYE,TARGET...");
    cmd.add_option("--clip", o.clip,
                   "clip planes: fit (to the scene, default) or fixed (the camera's own near/far)")
        ->check(CLI::IsMember({"fit", "fixed"}));
    addLensOptions(cmd, o.projection, o.depth);
    cmd.add_option("--out", o.out, "output folder (EXR, PNG, metrics.json)")->type_name(kOutDir)->capture_default_str();
    addTimingFramesOption(cmd, o.timingFrames, {"", "extra frames, every pass forced, averaged into gpu_ms"});
    cmd.add_flag("--fit-range", o.fitRange,
                 "PNG previews: fit every buffer's range (as the app's 'fit range')");
    cmd.add_flag("--false-colour", o.falseColor, "PNG previews: scalar buffers in false colour");
    cmd.add_flag("--reference", o.reference,
                 "also ray trace the reference AO (Embree, cached) and write ao_reference, error.exr/png and "
                 "the error metrics");
    addReferenceRaysOption(cmd, o.referenceRays);
    addReferenceVariantOption(cmd, o.referenceVariant);
    cmd.add_flag("--no-cache", o.noCache, "trace the reference even if the cache holds it");
    addOracleOptions(cmd, o.oracleLayers, o.oracleThickness, o.oracleGuard, {"with --reference: ", ""});
    cmd.add_option("--score", o.score,
                   "with --reference: also judge this AO image of the same view and size (PNG, PGM or EXR; "
                   "channel 0, 1 = open), e.g. another renderer's; repeatable")->type_name(kInFiles);
    cmd.add_flag("--motion", o.motion,
                 "also score the AO in motion: frames along a camera path from the view (an orbit about its target "
                 "and a dolly toward it), each against its own reference (--reference-rays): per-frame RMSE, "
                 "instability, ghosting (metrics.json \"motion\")");
    addMotionPathOptions(cmd, o.motionPath);
    addShadersOption(cmd, o.shaderDir);
    addPresetDirOption(cmd, o.presetDir);
    cmd.add_flag("--verbose-gl", o.verboseGl, "log every KHR_debug message");
    addQuietFlag(cmd, o.quiet, {"", "nothing printed on success"});
}

namespace {

// Everything a render needs that takes no GL: bad input fails here, in milliseconds, with one line.
struct RenderJob {
    int w = 1280, h = 720;
    Settings settings;
    Scene scene;
    Camera camera;
    RunInfo info;
    ViewStyle style; // PNG previews: the same mapping as the app's views
    std::optional<float> referenceRadius; // world units: the preset's reference_radius_scene, if any
};

// The camera: --camera, else the preset's bookmark, else the scene's own, else one framing it.
Camera chooseCamera(const RenderOptions& o, const Preset& preset, const Scene& scene, const std::string& spec,
                    std::string& source) {
    Camera cam;
    if (!o.camera.empty()) {
        Camera base = defaultCamera(scene);
        applyCameraOptions(base, o.clip, o.projection, o.depth); // "inf" far needs reversed depth
        cam = parseCamera(o.camera, base, scene.origin);         // file coordinates
        source = "--camera";
    } else if (preset.camera) {
        cam = cameraToScene(*preset.camera, scene); // presets hold file coordinates
        source = "preset";
    } else if (scene.camera) {
        cam = *scene.camera;
        source = spec.rfind("builtin:", 0) == 0 ? "builtin" : "file";
    } else {
        cam = frameBounds(scene.bounds);
        source = "framed";
    }
    applyCameraOptions(cam, o.clip, o.projection, o.depth);
    validateCamera(cam);
    return cam;
}

RenderJob prepareRender(const RenderOptions& o) {
    RenderJob job;
    Preset preset;
    if (!o.preset.empty()) preset = PresetStore::standard(o.presetDir).open(o.preset);
    if (!o.size.empty())
        parseSizeOption(o.size, job.w, job.h);
    else if (preset.size)
        std::tie(job.w, job.h) = *preset.size;
    job.settings = preset.settings;
    std::vector<std::string> warnings = preset.warnings; // settings that do nothing, said so once they are valid
    for (std::string& w : applyAssignments(job.settings, o.sets))
        warnings.push_back(std::move(w));
    validateSettings(job.settings);
    printWarnings(warnings);
    const std::string spec = !o.scene.empty() ? o.scene : preset.scene.value_or("builtin:showcase");
    if (o.scene.empty() && !preset.scene && preset.camera && !o.quiet)
        std::fprintf(stderr, "note: preset %s has a camera but no scene; rendering %s\n", preset.name.c_str(),
                     spec.c_str());
    job.scene = loadScene(spec);
    job.info.sceneName = job.scene.name;
    job.info.triangles = job.scene.triangleCount();
    job.info.materials = job.scene.materials;
    job.info.sceneOrigin = job.scene.origin;
    job.style.fit = o.fitRange;
    job.style.falseColor = o.falseColor;
    job.info.timingFrames = o.timingFrames;
    job.camera = chooseCamera(o, preset, job.scene, spec, job.info.cameraSource);
    if (preset.referenceRadiusScene) job.referenceRadius = *preset.referenceRadiusScene * 2.0f * job.scene.bounds.radius();
    return job;
}

// Every pass forced for `frames` frames, averaged per pass (the first frame includes JIT).
nlohmann::json timePasses(Renderer& r, const FrameReport& first, int frames) {
    nlohmann::json timing = nlohmann::json::object();
    std::vector<double> sums(first.passes.size(), 0.0);
    for (int f = 0; f < frames; ++f) {
        r.invalidate();
        const FrameReport fr = r.render();
        for (size_t i = 0; i < fr.passes.size() && i < sums.size(); ++i)
            sums[i] += fr.passes[i].gpuMs;
    }
    double total = 0;
    for (size_t i = 0; i < first.passes.size(); ++i) {
        const double ms = sums[i] / frames;
        timing[first.passes[i].name] = ms;
        total += ms;
    }
    timing["total"] = total;
    return timing;
}

// --score: AO images made elsewhere (another renderer, a web peer) of the same view, judged
// against the same reference and oracle as the frame: metrics.json "scored", one line each.
std::string scoreImages(const RenderOptions& o, const ReferenceImage& ref, const ReferenceSettings& rs,
                        const ReferenceImage* oracle, nlohmann::json& m) {
    std::string lines;
    // Decoded within the MASK textures' budget (--max-mask-mpix), checked from the header first.
    const ImageBudget budget{sceneBudget().maskPixels, 0, "decoded images", "--max-mask-mpix"};
    for (const std::string& file : o.score) {
        auto sizeCheck = [&](uint64_t w, uint64_t h) {
            if (w != uint64_t(ref.width) || h != uint64_t(ref.height))
                throw Error("--score " + file + ": " + std::to_string(w) + "x" + std::to_string(h) + ", the render is " +
                            std::to_string(ref.width) + "x" + std::to_string(ref.height));
        };
        // PNG, PGM, JPEG (stb) or OpenEXR, by their bytes; through the file gate (no FIFO, bounded).
        const Image img = decodeImage(readRegularFile(file, "--score", imageFileBytes(budget)), budget, "--score " + file,
                                      [&](const ImageHeader& h) { sizeCheck(h.width, h.height); });
        sizeCheck(uint64_t(img.width), uint64_t(img.height));
        Image ao{img.width, img.height, 1, std::vector<float>(size_t(img.width) * img.height)};
        for (size_t i = 0; i < ao.data.size(); ++i) ao.data[i] = img.data[i * size_t(img.channels)]; // channel 0
        size_t outside = 0;
        for (float v : ao.data) {
            if (!std::isfinite(v)) throw Error("--score " + file + ": non-finite AO values");
            outside += v < 0.0f || v > 1.0f;
        }
        if (outside)
            throw Error("--score " + file + ": " + std::to_string(outside) + (outside == 1 ? " pixel holds" : " pixels hold") +
                        " AO outside [0, 1] (1 is open, 0 fully occluded)");
        const ErrorMetrics e = evaluate(ao, ref).metrics;
        nlohmann::json entry = {{"file", file}, {"error", metricsJson(e, ref, rs)}};
        char b[300];
        std::snprintf(b, sizeof b, "\nscored %s: RMSE %.4f, bias %+.4f, edge %.4f, interior %.4f", file.c_str(), e.rmse,
                      e.bias, e.rmseEdge, e.rmseInterior);
        lines += b;
        if (oracle) {
            const ErrorMetrics t = evaluate(ao, *oracle).metrics;
            entry["technique"] = metricsJson(t, *oracle, rs);
            std::snprintf(b, sizeof b, "; technique (vs the oracle) %.4f", t.rmse);
            lines += b;
        }
        m["scored"].push_back(entry);
    }
    return lines;
}

// The screen-space oracle's depth layers for these settings: a frame that reads the second depth
// layer is split against the oracle of a two-layer G-buffer, as bench splits its two-layer rows.
int oracleLayersFor(const RenderOptions& o, const Settings& s) {
    return s.gbuffer.secondLayer ? std::max(2, o.oracleLayers) : o.oracleLayers;
}

// The error by place (metrics/error_places.h) of the final AO and of the raw AO before the denoiser
// and the upsample (the stages), against the truth and, with an oracle, the technique's part:
// metrics.json "error_by_place", and places.png (border yellow, silhouette magenta, crease red,
// convex blue, open grey, sky black); returns the final AO's line.
std::string errorByPlaceText(const std::string& out, const Renderer& r, const FrameCapture& frame, const ReferenceImage& ref,
                             const ReferenceSettings& rs, const ReferenceImage* oracle, nlohmann::json& m) {
    const PlaceMap places = placesOf(ref, r.camera(), rs.radius);
    static const float kColour[kPlaces][3] = {{1, 0.85f, 0}, {0.9f, 0, 0.9f}, {0.95f, 0.1f, 0.1f}, {0.2f, 0.4f, 1}, {0.6f, 0.6f, 0.6f}};
    Image map{places.width, places.height, 3, std::vector<float>(places.place.size() * 3, 0.0f)};
    for (size_t i = 0; i < places.place.size(); ++i)
        if (places.place[i] < kPlaces)
            for (int c = 0; c < 3; ++c) map.data[3 * i + size_t(c)] = kColour[places.place[i]][c];
    writePng(map, (std::filesystem::path(out) / "places.png").string());
    const ErrorByPlace final = errorByPlace(evaluate(frame.get("ao.denoised").values, ref), ref, places, oracle);
    const ErrorByPlace raw = errorByPlace(evaluate(frame.get("ao.raw").values, ref), ref, places, oracle);
    m["error_by_place"] = {{"ao.denoised", errorByPlaceJson(final)}, {"ao.raw", errorByPlaceJson(raw)},
                           {"note", "ao.raw: the AO before the denoiser and the upsample, read at the frame's size "
                                    "(nearest texel); ao.denoised: the final AO"},
                           {"files", {"places.png"}}};
    return "\n" + errorByPlaceLine(final);
}

// --reference: traces (or loads) the reference, writes its files and the error blocks into `m`;
// returns the summary line.
std::string judgeAgainstReference(const RenderOptions& o, const Renderer& r, const FrameCapture& frame,
                                  const Scene& scene, std::optional<float> referenceRadius, nlohmann::json& m) {
    ReferenceSettings rs = referenceSettingsFor(frame.radius, o.referenceRays, parseVariant(o.referenceVariant));
    if (referenceRadius) rs.radius = *referenceRadius; // the R the preset was judged against (tune)
    ReferenceProvider provider(scene, o.noCache ? std::string() : referenceCacheDir());
    bool cached = false;
    ReferenceImage ref;
    {
        ProgressBar bar("reference " + std::to_string(r.width()) + "x" + std::to_string(r.height()) + " x " +
                            std::to_string(rs.samples) + " rays",
                        !o.quiet);
        ref = provider.get(r.camera(), r.width(), r.height(), rs, [&](double f) { bar.update(f); }, &cached);
    }
    nlohmann::json e = writeReferenceOutputs(frame, ref, rs, o.out);
    e["error"]["reference"]["cached"] = cached;
    m["error"] = e["error"];
    m["error_raw"] = e["error_raw"];
    // The split: the screen-space oracle of the same view (what the G-buffer alone decides), the
    // AO against it (the technique's share) and it against the truth (the screen's).
    std::string split;
    std::optional<ReferenceImage> oracleKept; // for --score
    if (rs.variant == ReferenceVariant::Visibility) {
        ReferenceSettings os = rs;
        os.visibility = ReferenceVisibility::Screen;
        os.layers = oracleLayersFor(o, r.settings());
        os.thickness = float(o.oracleThickness);
        os.guardBand = o.oracleGuard;
        ReferenceImage oracle;
        {
            ProgressBar bar("screen-space oracle", !o.quiet);
            oracle = provider.get(r.camera(), r.width(), r.height(), os, [&](double f) { bar.update(f); });
        }
        const Image oracleImg{oracle.width, oracle.height, 1, oracle.ao};
        writeExr(oracleImg, (std::filesystem::path(o.out) / "ao_oracle.exr").string());
        writePng(referencePreview(oracle), (std::filesystem::path(o.out) / "ao_oracle.png").string());
        const Evaluation techEval = evaluate(frame.get("ao.denoised").values, oracle);
        const ErrorMetrics& tech = techEval.metrics;
        const ErrorMetrics screen = evaluate(oracleImg, ref).metrics;
        const ErrorShares shares = splitShares(techEval, oracle, ref); // the parts that add up
        m["error_split"] = {{"oracle", {{"layers", os.layers},
                                        {"thickness_r", std::isinf(os.thickness) ? nlohmann::json("inf") : nlohmann::json(os.thickness)},
                                        {"guard_band_px", os.guardBand},
                                        {"files", {"ao_oracle.exr", "ao_oracle.png"}}}},
                            {"technique", metricsJson(tech, oracle, os)},
                            {"shares", sharesJson(shares)},
                            {"screen", metricsJson(screen, ref, rs)},
                            {"note", "technique: ao.denoised against the screen-space oracle (what settings can "
                                     "still fix); screen: the oracle against the truth (what the G-buffer does not hold)"}};
        char b[320];
        std::snprintf(b, sizeof b,
                      "; split: technique (vs the screen-space oracle) %.4f, screen (oracle vs truth) %.4f; shares of "
                      "the squared error: technique %.2f + screen %.2f + interaction %+.2f = 1",
                      tech.rmse, screen.rmse, shares.technique, shares.screen, shares.interaction);
        split = b;
        oracleKept = std::move(oracle);
    }
    split += errorByPlaceText(o.out, r, frame, ref, rs, oracleKept ? &*oracleKept : nullptr, m);
    split += scoreImages(o, ref, rs, oracleKept ? &*oracleKept : nullptr, m);
    writeFileAtomically((std::filesystem::path(o.out) / "metrics.json").string(), dumpJson(m) + "\n");
    const auto& j = m["error"];
    char line[768];
    std::snprintf(line, sizeof line,
                  "reference (%s, R %.4g, %d rays%s): RMSE %.4f, MAE %.4f, bias %+.4f, PSNR %.2f dB (geometry, "
                  "sRGB), %.2f dB full frame, SSIM %.4f; reference noise %.4f%s%s\n",
                  variantName(rs.variant), rs.radius, rs.samples,
                  cached ? ", cached"
                         : (", " + std::to_string(int(ref.raysPerSecond() * 1e-6 + 0.5)) + " Mrays/s").c_str(),
                  j["rmse"].get<double>(), j["mae"].get<double>(), j["bias"].get<double>(),
                  j["psnr_geometry_srgb"].get<double>(), j["psnr_full_srgb"].get<double>(), j["ssim"].get<double>(),
                  j["reference"]["noise_rms"].get<double>(),
                  ref.ambiguousPixels() ? ("; " + std::to_string(ref.ambiguousPixels()) +
                                           " ambiguous pixels (coincident faces) left out")
                                              .c_str()
                                        : "",
                  split.c_str());
    return line;
}

// --motion: the path's frames against their references; the "motion" block, and the summary line.
std::string judgeMotion(const RenderOptions& o, Renderer& r, const RenderJob& job, const FrameCapture& frame,
                        nlohmann::json& m) {
    ReferenceSettings rs = referenceSettingsFor(frame.radius, o.referenceRays, parseVariant(o.referenceVariant));
    if (job.referenceRadius) rs.radius = *job.referenceRadius;
    ReferenceProvider provider(job.scene, o.noCache ? std::string() : referenceCacheDir());
    MotionTruth truth;
    {
        ProgressBar bar("motion references " + std::to_string(o.motionPath.frames) + " frames", !o.quiet);
        truth = traceMotionTruth(provider, r.bounds(), job.camera, r.width(), r.height(), o.motionPath, rs,
                                 [&](double f) { bar.update(f); });
    }
    const MotionMetrics mm = measureMotion(r, job.settings, truth);
    m["motion"] = motionJson(mm, truth);
    writeFileAtomically((std::filesystem::path(o.out) / "metrics.json").string(), dumpJson(m) + "\n");
    return motionLine(mm, truth) + "\n";
}

void printRenderSummary(const RenderOptions& o, const RenderJob& job, const std::string& glRenderer,
                        const FrameReport& first, const nlohmann::json& m, const nlohmann::json& timing,
                        const std::string& referenceLine) {
    if (o.quiet) return;
    if (m["geometry_pixels"].get<long>() == 0)
        std::printf("note: no geometry in view (check --camera): the AO statistics are empty\n");
    else if (m["radius"]["pixels_at_centre"].get<double>() < 2.0)
        std::printf("note: the AO radius is %.2f px at the centre of the view: the AO goes flat grey "
                    "(ao.radius_mode=scene makes the radius follow the scene)\n",
                    m["radius"]["pixels_at_centre"].get<double>());
    std::printf("%s: %dx%d on %s; AO mean %.4f (raw %.4f), darkest 5%% <= %.3f; radius %.4g units = %.1f px at "
                "the centre; gpu ms:",
                job.scene.name.c_str(), job.w, job.h, glRenderer.c_str(), m["ao"]["mean"].get<double>(),
                m["ao_raw"]["mean"].get<double>(), m["ao"]["p05"].get<double>(),
                m["radius"]["world_at_centre"].get<double>(), m["radius"]["pixels_at_centre"].get<double>());
    for (const auto& p : first.passes) // in graph order, not by name
        std::printf(" %s %.3f", p.name.c_str(), timing[p.name].get<double>());
    std::printf(" total %.3f", timing["total"].get<double>());
    std::printf("\nwrote %s/: one .exr per float buffer, one .png per buffer, metrics.json\n", o.out.c_str());
    if (o.reference) std::printf("%s", referenceLine.c_str());
}

} // namespace

int runRender(const RenderOptions& o) {
    if (!o.score.empty() && !o.reference) throw Error("--score judges an image against the reference: add --reference");
    makeOutputFolder(o.out); // before any work: a FIFO, a device or a file there fails in milliseconds
    RenderJob job = prepareRender(o);
    if (o.motion) checkMotionBudget(o.motionPath, job.w, job.h, 1); // before the still frame and its trace
    if (!o.motion) printWarnings(unusedMotionOptions(o.motionPath, "--motion"));
    if (o.reference && parseVariant(o.referenceVariant) == ReferenceVariant::Visibility) // before the render and trace
        ScreenLayers::checkBudget(job.w, job.h, oracleLayersFor(o, job.settings), o.oracleGuard);
    HeadlessRunner run({o.shaderDir, o.verboseGl});
    job.info.glRenderer = run.glRenderer();
    job.info.glPlatform = run.glPlatform();
    std::unique_ptr<Renderer> r = run.makeRenderer(job.w, job.h);
    r->setScene(job.scene);
    r->setCamera(job.camera);
    r->setSettings(job.settings);
    FrameReport first = r->render();
    while (r->accumulating()) // temporal accumulation: the frames it blends, deterministically
        first = r->render();
    // Captured before the timing frames: a forced temporal pass would blend the last frame in again.
    const FrameCapture frame = captureFrame(*r, job.style);
    const nlohmann::json timing = timePasses(*r, first, o.timingFrames);
    run.checkGl("while rendering " + job.scene.name);
    if (const ViewRadiusCheck vr = checkViewRadius(frame); vr.tooLarge) printWarnings({vr.message()});
    nlohmann::json m = writeOutputs(frame, o.out, job.info, first, timing);
    const std::string line = o.reference ? judgeAgainstReference(o, *r, frame, job.scene, job.referenceRadius, m) : "";
    const std::string motionText = o.motion ? judgeMotion(o, *r, job, frame, m) : "";
    run.checkGl("while writing the outputs");
    printRenderSummary(o, job, run.glRenderer(), first, m, timing, line);
    if (!o.quiet) std::printf("%s", motionText.c_str());
    long bad = 0;
    for (auto& [name, b] : m["buffers"].items())
        bad += b["nonfinite"].get<long>();
    if (bad > 0)
        throw Error(std::to_string(bad) + " non-finite values in the output buffers (see metrics.json)");
    return 0;
}

} // namespace ssao
