#include "view/app_core.h"

#include "scene/builtin_scenes.h"
#include "settings/params.h"
#include "ssao/constants.h"
#include "util/error.h"

#include <filesystem>

namespace fs = std::filesystem;

namespace ssao {

namespace {
std::string lower(std::string s) {
    for (auto& c : s)
        c = char(std::tolower((unsigned char)c));
    return s;
}
constexpr size_t kTimingHistory = 60;
} // namespace

double AppCore::PassTiming::average() const {
    if (ms.empty()) return 0.0;
    double s = 0;
    for (double v : ms)
        s += v;
    return s / double(ms.size());
}

AppCore::AppCore(const AppOptions& o)
    : opts_(o), store_(std::string(SSAOLAB_ASSET_DIR) + "/presets",
                       o.userPresetDir.empty() ? PresetStore::defaultUserDir() : o.userPresetDir) {
    if (opts_.shaderDir.empty()) opts_.shaderDir = SSAOLAB_SHADER_DIR;
    renderScale = std::clamp(o.renderScale, 0.25f, 1.0f);
    loaded_.settings = defaultSettings();
    loaded_.name = "defaults";
    if (!o.preset.empty()) {
        const PresetEntry* e = store_.find(o.preset);
        loaded_ = e ? store_.load(o.preset) : readPresetFile(o.preset);
    }
    settings_ = loaded_.settings;
    rendererA_ = std::make_unique<Renderer>(opts_.shaderDir);
    adoptScene(loadScene(o.scene), false);
    if (loaded_.camera) camera_.reset(*loaded_.camera, scene_.bounds.radius());
    shaderTime_ = rendererA_->shaders().newestSourceTime();
    setStatus("loaded " + scene_.name + (o.preset.empty() ? "" : " with preset " + loaded_.name), false);
}

AppCore::~AppCore() = default;

void AppCore::setStatus(const std::string& s, bool error) {
    status_ = s;
    statusError_ = error;
    poke();
}

void AppCore::adoptScene(Scene s, bool keepCamera) {
    scene_ = std::move(s);
    rendererA_->setScene(scene_);
    if (rendererB_) rendererB_->setScene(scene_);
    if (!keepCamera) resetCamera();
    cpuVersion_ = ~0u;
    poke();
}

void AppCore::resetCamera() {
    camera_.reset(scene_.camera.value_or(frameBounds(scene_.bounds)), scene_.bounds.radius());
    poke();
}

void AppCore::selectSceneCamera(int index) {
    if (index >= 0 && index < int(scene_.cameras.size()))
        camera_.reset(scene_.cameras[size_t(index)].second, scene_.bounds.radius());
    poke();
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
        adoptScene(loadScene(spec), false);
        return "loaded " + scene_.name + " (" + std::to_string(scene_.triangleCount()) + " triangles)";
    });
}

bool AppCore::openPreset(const std::string& nameOrPath) {
    return attempt("load preset", [&] {
        Preset p = store_.find(nameOrPath) ? store_.load(nameOrPath) : readPresetFile(nameOrPath);
        loaded_ = p;
        settings_ = p.settings;
        if (p.camera) camera_.reset(*p.camera, scene_.bounds.radius());
        return "preset " + p.name + " loaded";
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
        p.camera = camera_.camera(); // the camera as a bookmark
        const std::string path = store_.save(p);
        loaded_ = p;
        return "saved preset " + name + " to " + path;
    });
}

bool AppCore::renamePreset(const std::string& from, const std::string& to) {
    return attempt("rename preset", [&] {
        store_.rename(from, to);
        if (loaded_.name == from) loaded_.name = to;
        return "renamed preset " + from + " to " + to;
    });
}

bool AppCore::deletePreset(const std::string& name) {
    return attempt("delete preset", [&] {
        store_.remove(name);
        return "deleted preset " + name;
    });
}

bool AppCore::unsavedChanges() const {
    return settings_ != loaded_.settings;
}

Settings AppCore::settingsB() {
    if (splitKind == SplitKind::AoOnOff) {
        Settings s = settings_;
        s.composite.useAo = false;
        return s;
    }
    // The B preset is read from disk when it is chosen, not on every frame.
    if (splitPresetB != cachedSplitPreset_) {
        cachedSplitPreset_ = splitPresetB;
        try {
            cachedSplitSettings_ = store_.load(splitPresetB).settings;
        } catch (const std::exception& e) {
            cachedSplitSettings_ = settings_;
            setStatus(std::string("split view: ") + e.what(), true);
        }
    }
    return cachedSplitSettings_;
}

void AppCore::renderIfNeeded(int width, int height) {
    width = std::max(int(float(width) * renderScale), 16);
    height = std::max(int(float(height) * renderScale), 16);
    // Cheap when nothing changed: the renderer compares keys and runs no pass.
    auto prepare = [&](Renderer& r, const Settings& s) {
        if (r.width() != width || r.height() != height) r.setSize(width, height);
        r.setCamera(camera_.camera());
        r.setSettings(s);
    };
    try {
        Renderer& r = *rendererA_;
        prepare(r, settings_);
        FrameReport rep = r.render();
        if (!rep.ran().empty()) {
            lastReport_ = rep;
            ++framesRendered_;
            for (const auto& p : rep.passes) {
                if (!p.ran || p.gpuMs < 0) continue;
                auto& t = timings_[p.name].ms;
                t.push_back(p.gpuMs);
                if (t.size() > kTimingHistory) t.pop_front();
            }
        }
        views_.update(r);
        if (viewMode == ViewMode::Split) {
            if (!rendererB_) {
                rendererB_ = std::make_unique<Renderer>(opts_.shaderDir);
                rendererB_->setScene(scene_);
            }
            prepare(*rendererB_, settingsB());
            rendererB_->render();
        }
    } catch (const std::exception& e) {
        // A shader that fails mid-session (e.g. a new variant after hot reload) must not kill the app.
        shaderError_ = e.what();
    }
}

void AppCore::noteFrameMs(float ms) {
    frameMs_.push_back(ms);
    if (frameMs_.size() > 120) frameMs_.pop_front();
}

void AppCore::pollShaderReload() {
    const auto t = rendererA_->shaders().newestSourceTime();
    if (t == shaderTime_) return;
    shaderTime_ = t;
    try {
        rendererA_->shaders().reload();
        if (rendererB_) rendererB_->shaders().reload();
        rendererA_->invalidate();
        if (rendererB_) rendererB_->invalidate();
        shaderError_.clear();
        setStatus("shaders reloaded", false);
    } catch (const std::exception& e) {
        shaderError_ = e.what(); // the last good programs keep running
        poke();
    }
}

glm::vec4 AppCore::texelOf(BufferId id, int x, int y) {
    return rendererA_->buffer(id).readTexel(x, y);
}

const PixelInspection& AppCore::inspection() {
    Renderer& r = *rendererA_;
    if (cpuVersion_ != r.gbuffer().version()) {
        cpuPos_ = readBack(r.gbuffer().position(), 4);
        cpuNormal_ = readBack(r.gbuffer().normal(), 3);
        cpuDepth_ = readBack(r.gbuffer().depth(), 1);
        cpuVersion_ = r.gbuffer().version();
        inspectionStale_ = true;
    }
    // Replayed only when the pixel, the settings or the G-buffer changed, not on every frame.
    if (inspectionStale_ || hoverPixel != inspectedPixel_ || settings_ != inspectedSettings_) {
        const gpu::FrameConstants fc = packFrameConstants(r.camera(), r.width(), r.height(), r.sceneRadius());
        inspection_ = inspectPixel(settings_.ssao, settings_.gbuffer, fc, {&cpuPos_, &cpuNormal_, &cpuDepth_},
                                   hoverPixel.x, hoverPixel.y);
        inspectedPixel_ = hoverPixel;
        inspectedSettings_ = settings_;
        inspectionStale_ = false;
    }
    return inspection_;
}

void AppCore::drawUi() {
    const ImGuiIO& io = ImGui::GetIO();
    const float panelWidth = std::min(400.0f * io.FontGlobalScale, io.DisplaySize.x * 0.45f);
    drawControlPanel(*this, ImVec2(0, 0), ImVec2(panelWidth, io.DisplaySize.y));
    drawMainView(*this, ImVec2(panelWidth, 0), ImVec2(io.DisplaySize.x - panelWidth, io.DisplaySize.y));
    if (busyFrames_ > 0) --busyFrames_;
}

} // namespace ssao
