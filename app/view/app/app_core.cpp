// AppCore's actions: scenes, presets, camera, status.
#include "view/app/app_core.h"
#include "scene/load/load_scene.h"

#include "scene/load/builtin_scenes.h"
#include "settings/params.h"
#include "util/error.h"
#include "util/paths.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>

namespace fs = std::filesystem;

namespace ssao {

namespace {
std::string lower(std::string s) {
    for (auto& c : s)
        c = char(std::tolower((unsigned char)c));
    return s;
}
// A scene spec that still means the same file from another folder (presets store it).
std::string absoluteSpec(const std::string& spec) {
    if (spec.rfind("builtin:", 0) == 0) return spec;
    std::error_code ec;
    const fs::path p = fs::weakly_canonical(fs::absolute(spec, ec), ec);
    return ec ? spec : p.string();
}
} // namespace

AppCore::AppCore(const AppOptions& o)
    : opts_(o), store_(PresetStore::standard(o.userPresetDir)),
      frames_(o.shaderDir.empty() ? shaderRoot() : o.shaderDir, o.renderScale, o.interactiveScale, o.reference,
              o.wake),
      front_(o.shaderDir.empty() ? shaderRoot() : o.shaderDir, o.wake, [this] {
          frames_.postNews(); // an engine's result: the sleeping loop draws a frame
          if (opts_.wake) opts_.wake();
      }),
      techniques_(o.techniqueDir, o.probeProgram.empty() ? executablePath() : o.probeProgram, o.wake) {
    front_.engines().modules = o.engineModules;
    loaded_.name = "defaults";
    // A bad --preset or --scene opens the window anyway, on the defaults and the built-in scene, with
    // the problem in the status line: the user fixes it from the panel instead of reading a log.
    std::string startupError;
    if (!o.preset.empty()) {
        try {
            loaded_ = store_.open(o.preset);
        } catch (const std::exception& e) {
            startupError = e.what();
        }
    }
    settings_ = loaded_.settings;
    std::string spec = !o.scene.empty() ? o.scene : loaded_.scene.value_or("builtin:showcase");
    std::optional<Scene> scene;
    try {
        scene = loadScene(spec);
    } catch (const std::exception& e) {
        startupError += (startupError.empty() ? "" : "; ") + std::string(e.what());
        spec = "builtin:showcase";
        scene = loadScene(spec);
    }
    adoptScene(std::move(*scene), spec, false);
    if (loaded_.camera)
        camera_.reset(cameraToScene(*loaded_.camera, *scene_), scene_->bounds.radius(), scene_->bounds.center());
    if (o.projection) camera_.setProjection(*o.projection);
    if (o.depth) camera_.setDepth(*o.depth);
    if (!startupError.empty()) {
        startupError_ = startupError + " (showing " + spec + ")";
        setStatus(startupError_, true);
    }
    else
        setStatus("loaded " + scene_->name + (o.preset.empty() ? "" : " with preset " + loaded_.name) + "; " +
                      radiusNote(),
                  false);
}

AppCore::~AppCore() = default;

void AppCore::setStatus(const std::string& s, bool error) {
    status_ = s;
    statusError_ = error;
    frames_.keepAwake();
}

std::string AppCore::radiusNote() const {
    const float diag = 2.0f * scene_->bounds.radius();
    char buf[200];
    const AoSettings& a = settings_.ao;
    if (a.radiusMode == RadiusMode::Scene)
        std::snprintf(buf, sizeof buf, "AO radius follows the scene: %.3g x diagonal %.4g = %.4g units",
                      a.radiusScene, diag, a.radiusScene * diag);
    else if (a.radiusMode == RadiusMode::World)
        std::snprintf(buf, sizeof buf, "AO radius %.4g scene units (set by the preset; diagonal %.4g)",
                      a.radius, diag);
    else
        std::snprintf(buf, sizeof buf, "AO radius %.3g pixels at every depth", a.radiusPx);
    return buf;
}

void AppCore::adoptScene(Scene s, const std::string& spec, bool keepCamera) {
    scene_ = std::make_shared<const Scene>(std::move(s));
    sceneSpec_ = absoluteSpec(spec);
    frames_.sceneChanged(*scene_);
    // A radius the preset did not choose follows the scene: a radius tuned by hand for the last
    // scene (e.g. 0.5 m) would make a millimetre model flat grey.
    if (!loaded_.fixesRadius()) resetRadius(settings_);
    if (!keepCamera) resetCamera();
}

// A scene's cameras and the framed view take the lens the user chose (projection, depth mode);
// a preset's camera brings its own.
void AppCore::resetCameraKeepingLens(Camera c) {
    c.projectionKind = camera_.camera().projectionKind;
    c.depth = camera_.camera().depth;
    camera_.reset(c, scene_->bounds.radius(), scene_->bounds.center());
    frames_.keepAwake();
}

void AppCore::resetCamera() {
    resetCameraKeepingLens(scene_->camera.value_or(frameBounds(scene_->bounds)));
}

void AppCore::selectSceneCamera(int index) {
    if (index >= 0 && index < int(scene_->cameras.size()))
        resetCameraKeepingLens(scene_->cameras[size_t(index)].second);
    frames_.keepAwake();
}

bool AppCore::attempt(const char* what, const std::function<std::string()>& action) {
    try {
        setStatus(action(), false);
        return true;
    } catch (const std::exception& e) {
        // The error is shown in the window; the current scene, preset and settings stay.
        setStatus(std::string("could not ") + what + ": " + e.what(), true);
        return false;
    }
}

bool AppCore::openScene(const std::string& spec) {
    return attempt("load scene", [&] {
        adoptScene(loadScene(spec), spec, false);
        return "loaded " + scene_->name + " (" + std::to_string(scene_->triangleCount()) + " triangles); " +
               radiusNote();
    });
}

bool AppCore::setTransparent(Transparent mode) {
    const Transparent before = transparentMode();
    setTransparentMode(mode);
    const bool ok = attempt("reload the scene", [&] {
        adoptScene(loadScene(sceneSpec_), sceneSpec_, true);
        return std::string(mode == Transparent::Skip ? "transparent surfaces skipped" : "transparent surfaces drawn as opaque") +
               " (" + std::to_string(scene_->triangleCount()) + " triangles)";
    });
    if (!ok) setTransparentMode(before);
    return ok;
}

bool AppCore::openPreset(const std::string& nameOrPath) {
    return attempt("load preset", [&] {
        Preset p = store_.open(nameOrPath);
        std::optional<Scene> s;
        if (p.scene && absoluteSpec(*p.scene) != sceneSpec_)
            s = loadScene(*p.scene); // may throw: nothing changed yet
        loaded_ = p;
        settings_ = p.settings;
        if (s) adoptScene(std::move(*s), *p.scene, false);
        if (p.camera)
            camera_.reset(cameraToScene(*p.camera, *scene_), scene_->bounds.radius(), scene_->bounds.center());
        return "preset " + p.name + " loaded" + (s ? " with its scene " + scene_->name : "") + "; " +
               radiusNote();
    });
}

void AppCore::dropFiles(const std::vector<std::string>& paths) {
    for (const auto& p : paths) {
        const std::string ext = lower(fs::path(p).extension().string());
        if (ext == ".gltf" || ext == ".glb")
            openScene(p);
        else if (ext == ".json")
            openPreset(p);
        else
            setStatus("dropped file " + p + " is neither a .gltf/.glb scene nor a .json preset", true);
    }
}

bool AppCore::savePreset(const std::string& name) {
    return attempt("save preset", [&] {
        Preset p;
        p.name = name;
        p.description = "saved from the ssaolab app";
        p.settings = settings_;
        for (const auto& row : paramTable())
            p.keys.insert(row.key); // a saved preset is complete: it fixes every parameter
        p.scene = sceneSpec_;
        if (frames_.fullSize().first > 0) p.size = frames_.fullSize(); // when still, not the reduced size while moving
        p.camera = cameraToFile(camera_.camera(), *scene_); // a bookmark, in the file's coordinates
        const std::string path = store_.save(p);
        descriptions_.erase(path);
        loaded_ = p;
        return "saved preset " + name + " to " + path;
    });
}

bool AppCore::renamePreset(const std::string& from, const std::string& to) {
    return attempt("rename preset", [&] {
        store_.rename(from, to);
        descriptions_.clear();
        if (loaded_.name == from) loaded_.name = to;
        return "renamed preset " + from + " to " + to;
    });
}

bool AppCore::deletePreset(const std::string& name) {
    return attempt("delete preset", [&] {
        store_.remove(name);
        descriptions_.clear();
        return "deleted preset " + name;
    });
}

const std::string& AppCore::presetDescription(const PresetEntry& e) {
    auto it = descriptions_.find(e.path);
    if (it != descriptions_.end()) return it->second;
    std::string d;
    try {
        d = store_.load(e.name).description;
    } catch (const std::exception& ex) {
        d = std::string("(does not read: ") + ex.what() + ")";
    }
    return descriptions_[e.path] = d;
}

bool AppCore::unsavedChanges() const {
    return settings_ != loaded_.settings;
}

void AppCore::applyCandidate(const Candidate& c) {
    if (c.isEngine()) { // JavaScript for another renderer: "copy snippet" in the Front tab gives it
        compareCandidate(c);
        return;
    }
    settings_ = withRadiusOf(c.settings, settings_);
    frames_.keepAwake();
    setStatus("applied " + c.label + " (the radius stays yours)", false);
}

void AppCore::compareCandidate(const Candidate& c) {
    view_.splitCandidateB = c.label;
    view_.splitKind = SplitKind::Candidate;
    view_.mode = ViewMode::Split;
    view_.splitCandidateImage = c.isEngine();
    frames_.keepAwake();
    if (!c.isEngine()) {
        splitCandidate_ = withRadiusOf(c.settings, settings_);
        setStatus("split view: A = current, B = " + c.label, false);
        return;
    }
    splitCandidate_.reset(); // no chain B: B is the engine's frame
    view_.splitDifference = false;
    if (view_.splitBuffer == "composite") view_.splitBuffer = "ao.denoised"; // its AO against the current AO
    setStatus("split view: A = current " + view_.splitBuffer + ", B = the AO frame of " + c.label +
                  " from Chromium (an image: B shows AO whatever A shows)",
              false);
}

const gl::Texture2D* AppCore::splitImageB(std::string& why) {
    const std::shared_ptr<const EngineSample> s = front_.engines().sample(view_.splitCandidateB);
    if (!s) {
        why = view_.splitCandidateB + ": no frame of this view yet (the Front tab measures it)";
        return nullptr;
    }
    splitImage_.show(std::shared_ptr<const Image>(s, &s->shown)); // uploaded once per frame measured
    return splitImage_.texture();
}

std::optional<Settings> AppCore::settingsB() {
    if (view_.mode != ViewMode::Split) return std::nullopt;
    if (view_.splitKind == SplitKind::AoOnOff) {
        Settings s = settings_;
        s.composite.useAo = false;
        return s;
    }
    if (view_.splitKind == SplitKind::Candidate) return splitCandidate_;
    // The B preset is read from disk when it is chosen, not on every frame.
    if (view_.splitPresetB != cachedSplitPreset_) {
        cachedSplitPreset_ = view_.splitPresetB;
        try {
            cachedSplitSettings_ = store_.open(view_.splitPresetB).settings;
        } catch (const std::exception& e) {
            cachedSplitSettings_.reset();
            setStatus(std::string("split view: ") + e.what(), true);
        }
    }
    return cachedSplitSettings_;
}

void AppCore::renderIfNeeded(int viewW, int viewH) {
    // A technique's first use compiles its shaders: about a second on llvmpipe, one stalled frame.
    // The frame the choice is made shows a notice instead (the render waits one frame), the frame
    // after says how long it took.
    const std::string technique = settings_.ao.technique;
    if (technique != renderedTechnique_ && !renderedTechnique_.empty() && !announced_) {
        announced_ = true;
        setStatus("compiling " + technique + "'s shaders (the first use of a technique takes a moment)...", false);
        frames_.keepAwake();
        return;
    }
    const auto t0 = std::chrono::steady_clock::now();
    frames_.render({camera_.camera(), settings_, settingsB(), scene_}, view_, viewW, viewH);
    if (announced_) {
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        char b[160];
        std::snprintf(b, sizeof b, "switched to %s (%.2f s to compile and render; switching back is instant)",
                      technique.c_str(), s);
        setStatus(b, false);
        announced_ = false;
    }
    renderedTechnique_ = technique;
    noteViewRadius();
}

void AppCore::noteViewRadius() {
    const ViewRadiusCheck& c = frames_.viewRadius();
    if (c.tooLarge && !radiusHinted_)
        setStatus(c.message() + " (Parameters: \"use the view's radius\")", false);
    radiusHinted_ = c.tooLarge;
}

void AppCore::useViewRadius() {
    const ViewRadiusCheck& c = frames_.viewRadius();
    if (!(c.suggested > 0.0)) return;
    settings_.ao.radiusMode = RadiusMode::World;
    settings_.ao.radius = std::clamp(float(c.suggested), 1e-4f, 1e4f); // the ao.radius row's range
    char b[200];
    std::snprintf(b, sizeof b, "AO radius %.3g world units: %.0f%% of what the view spans (ao.radius_mode=world)",
                  double(settings_.ao.radius), 100.0 * kViewRadiusTarget);
    setStatus(b, false);
}

void AppCore::pollShaderReload() {
    frames_.pollShaderReload();
    if (frames_.reloadedShaders()) setStatus("shaders reloaded", false);
    // Probed at the size the explorer renders its still frames at: a shader that passes there does
    // not stall the window.
    const TechniqueWatch::News news = techniques_.poll(frames_.renderer().width(), frames_.renderer().height());
    techniqueVerdicts_ += unsigned(news.errors.size() + news.adopted.size());
    for (const std::string& e : news.errors) {
        setStatus(e, true);
        frames_.setShaderError(e);
    }
    if (!news.adopted.empty()) {
        // Values the new header no longer has, or holds in another range, are fitted to it.
        fitUserValues(settings_);
        fitUserValues(loaded_.settings);
        if (splitCandidate_) fitUserValues(*splitCandidate_);
        setStatus("new version running: " + news.adopted.back(), false);
        frames_.setShaderError("");
    }
    if (!news.adopted.empty() || !news.errors.empty()) frames_.keepAwake();
}

const std::optional<PixelInspection>& AppCore::inspection() {
    std::string error;
    const auto& in = inspector_.inspection(frames_.renderer(), view_, frames_.interacting(), error);
    if (!error.empty()) frames_.setShaderError(error);
    return in;
}

} // namespace ssao
