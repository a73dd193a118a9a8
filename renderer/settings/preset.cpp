#include "settings/preset.h"

#include "settings/applicability.h"
#include "techniques/registry.h"
#include "settings/params.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/json_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace ssao {

namespace {
glm::vec3 vec3From(const nlohmann::json& j, const char* key, const std::string& origin) {
    const auto it = j.find(key);
    if (it == j.end() || !it->is_array() || it->size() != 3 || !(*it)[0].is_number() ||
        !(*it)[1].is_number() || !(*it)[2].is_number())
        throw Error(origin + ": camera." + key + " must be an array of 3 numbers");
    return {(*it)[0].get<float>(), (*it)[1].get<float>(), (*it)[2].get<float>()};
}
float numberFrom(const nlohmann::json& j, const char* key, float def, const std::string& origin) {
    const auto it = j.find(key);
    if (it == j.end()) return def;
    if (!it->is_number()) throw Error(origin + ": camera." + key + " must be a number");
    return it->get<float>();
}
} // namespace

bool isPresetMetadataKey(const std::string& key) {
    return key == "name" || key == "description" || key == "camera" || key == "scene" || key == "size" ||
           key == "reference_radius_scene" || key == "scores" || key == "technique_file";
}

const std::vector<std::string>& radiusKeys() {
    static const std::vector<std::string> keys = {"ao.radius_mode", "ao.radius", "ao.radius_scene",
                                                  "ao.radius_px"};
    return keys;
}

bool Preset::fixesRadius() const {
    for (const auto& k : radiusKeys())
        if (keys.count(k)) return true;
    return false;
}

void resetRadius(Settings& s) {
    const Settings d{};
    for (const auto& k : radiusKeys())
        if (const Param* p = findParam(k)) p->set(s, p->get(d));
}

nlohmann::json cameraToJson(const Camera& c) {
    nlohmann::json j = {{"eye", {c.eye.x, c.eye.y, c.eye.z}},
                        {"target", {c.target.x, c.target.y, c.target.z}},
                        {"up", {c.up.x, c.up.y, c.up.z}},
                        {"fov_y_deg", c.fovYDeg},
                        {"near", c.nearZ},
                        {"clip", c.clip == ClipMode::Fit ? "fit" : "fixed"},
                        {"projection", projectionName(c.projectionKind)},
                        {"depth", depthModeName(c.depth)}};
    if (std::isinf(c.farZ))
        j["far"] = "inf"; // JSON has no infinity
    else
        j["far"] = c.farZ;
    return j;
}

Camera cameraFromJson(const nlohmann::json& j, const std::string& origin) {
    if (!j.is_object()) throw Error(origin + ": camera must be an object");
    static const char* const keys[] = {"eye", "target", "up", "fov_y_deg", "near", "far", "clip", "projection", "depth"};
    for (auto& [k, v] : j.items())
        if (std::find(std::begin(keys), std::end(keys), k) == std::end(keys))
            throw Error(origin + ": unknown key 'camera." + k + "'");
    Camera c;
    c.eye = vec3From(j, "eye", origin);
    c.target = vec3From(j, "target", origin);
    c.up = j.contains("up") ? vec3From(j, "up", origin) : glm::vec3(0, 1, 0);
    c.fovYDeg = numberFrom(j, "fov_y_deg", c.fovYDeg, origin);
    c.nearZ = numberFrom(j, "near", c.nearZ, origin);
    if (j.contains("far") && j["far"] == "inf")
        c.farZ = INFINITY;
    else
        c.farZ = numberFrom(j, "far", c.farZ, origin);
    auto text = [&](const char* key) {
        const auto& v = j[key];
        if (!v.is_string()) throw Error(origin + ": camera." + key + " must be a string");
        return v.get<std::string>();
    };
    if (j.contains("clip")) {
        const std::string clip = text("clip");
        if (clip == "fit")
            c.clip = ClipMode::Fit;
        else if (clip == "fixed")
            c.clip = ClipMode::Fixed;
        else
            throw Error(origin + ": camera.clip must be \"fit\" or \"fixed\"");
    }
    const std::string projection = j.contains("projection") ? text("projection") : "";
    const std::string depth = j.contains("depth") ? text("depth") : "";
    try {
        if (!projection.empty()) c.projectionKind = parseProjection(projection);
        if (!depth.empty()) c.depth = parseDepthMode(depth);
    } catch (const Error& e) {
        throw Error(origin + ": camera." + e.what());
    }
    try {
        validateCamera(c);
    } catch (const Error& e) {
        throw Error(origin + ": " + e.what());
    }
    return c;
}

nlohmann::json presetToJson(const Preset& p) {
    nlohmann::json j = nlohmann::json::object();
    if (!p.name.empty()) j["name"] = p.name;
    if (!p.description.empty()) j["description"] = p.description;
    if (p.scene) j["scene"] = *p.scene;
    if (p.size) j["size"] = {p.size->first, p.size->second};
    if (p.camera) j["camera"] = cameraToJson(*p.camera);
    if (p.referenceRadiusScene) j["reference_radius_scene"] = *p.referenceRadiusScene;
    if (!p.scores.is_null()) j["scores"] = p.scores;
    j.update(toJson(p.settings));
    // A user technique's preset names its file and the file's hash; the other user techniques'
    // rows are left out, so the preset opens where only its own technique is installed.
    for (const TechniqueRows& t : registeredTechniques()) {
        if (t.file.empty()) continue;
        if (t.id != p.settings.ao.technique)
            j.erase(t.id);
        else
            j["technique_file"] = {{"id", t.id}, {"file", fs::path(t.file).filename().string()}, {"hash", t.version}};
    }
    return j;
}

namespace {
// A preset saved with a user technique: that technique must be loaded, and a file that has changed
// since is said to have (its parameters may now mean something else).
void checkTechniqueFile(const nlohmann::json& j, const std::string& origin, std::vector<std::string>& warnings) {
    if (!j.contains("technique_file")) return;
    const auto& f = j["technique_file"];
    if (!f.is_object() || !f.contains("id") || !f["id"].is_string() || !f.contains("hash") || !f["hash"].is_string())
        throw Error(origin + ": technique_file must be {\"id\": ..., \"file\": ..., \"hash\": ...}");
    // Names from the file reach a warning or an error line: clipped, as a name is never that long.
    auto clipped = [](std::string v) { return v.size() > 80 ? v.substr(0, 80) + "..." : v; };
    const std::string id = clipped(f["id"].get<std::string>()), hash = clipped(f["hash"].get<std::string>());
    const std::string file = f.contains("file") && f["file"].is_string() ? clipped(f["file"].get<std::string>()) : id;
    for (const TechniqueRows& t : registeredTechniques())
        if (t.id == id) {
            if (t.version != hash)
                warnings.push_back(origin + ": " + file + " has changed since the preset was saved (hash " +
                                   hash.substr(0, 16) + " then, " + t.version + " now): its values may mean something else");
            return;
        }
    throw Error(origin + ": it uses the user technique " + id + " (" + file +
                "), which is not loaded: put the file in the technique folder or name its folder with --technique-dir");
}
} // namespace

Preset presetFromJson(const nlohmann::json& j, const std::string& origin, const std::string& baseDir) {
    Preset p;
    if (j.is_object()) checkTechniqueFile(j, origin, p.warnings);
    applyJson(p.settings, j, origin); // skips metadata, rejects anything unknown
    for (auto& [group, members] : j.items())
        if (!isPresetMetadataKey(group))
            for (auto& [name, value] : members.items())
                p.keys.insert(group + "." + name);
    if (j.contains("name")) {
        if (!j["name"].is_string()) throw Error(origin + ": name must be a string");
        p.name = j["name"].get<std::string>();
    }
    if (j.contains("description") && j["description"].is_string())
        p.description = j["description"].get<std::string>();
    if (j.contains("scene")) {
        if (!j["scene"].is_string() || j["scene"].get<std::string>().empty())
            throw Error(origin + ": scene must be a non-empty string (builtin:NAME or a glTF path)");
        std::string spec = j["scene"].get<std::string>();
        if (spec.rfind("builtin:", 0) != 0 && fs::path(spec).is_relative() && !baseDir.empty())
            spec = (fs::path(baseDir) / spec).lexically_normal().string();
        p.scene = spec;
    }
    if (j.contains("size")) {
        const auto& s = j["size"];
        if (!s.is_array() || s.size() != 2 || !s[0].is_number_integer() || !s[1].is_number_integer() ||
            s[0].get<long>() < 1 || s[1].get<long>() < 1 || s[0].get<long>() > 16384 ||
            s[1].get<long>() > 16384)
            throw Error(origin + ": size must be [width, height] with each in 1..16384");
        p.size = std::make_pair(s[0].get<int>(), s[1].get<int>());
    }
    if (j.contains("camera")) p.camera = cameraFromJson(j["camera"], origin);
    if (j.contains("reference_radius_scene")) {
        const auto& r = j["reference_radius_scene"];
        if (!r.is_number() || !(r.get<double>() >= 1e-4 && r.get<double>() <= 0.5))
            throw Error(origin + ": reference_radius_scene must be a number in 0.0001..0.5 (a fraction of the diagonal)");
        p.referenceRadiusScene = r.get<float>();
    }
    if (j.contains("scores")) {
        if (!j["scores"].is_object()) throw Error(origin + ": scores must be an object");
        p.scores = j["scores"];
    }
    return p;
}

Preset readPresetFile(const std::string& path) {
    if (fs::is_directory(path)) throw Error("preset file not found: " + path);
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Error("preset file not found: " + path);
    const nlohmann::json j = readJsonFile(path, "preset"); // regular files only, nesting bounded
    if (j.is_object() && j.contains("asset") && j["asset"].is_object() && j["asset"].contains("version"))
        throw Error("preset " + path + " is a glTF scene, not a preset");
    Preset p = presetFromJson(j, "preset " + path, fs::path(path).parent_path().string());
    if (p.name.empty()) p.name = fs::path(path).stem().string();
    for (const std::string& w : inapplicablePresetKeys(p.settings, p.keys))
        p.warnings.push_back("preset " + path + ": " + w);
    return p;
}

void writePresetFile(const Preset& p, const std::string& path) {
    std::error_code ec;
    const auto parent = fs::path(path).parent_path();
    if (!parent.empty()) fs::create_directories(parent, ec);
    writeFileAtomically(path, dumpJson(presetToJson(p)) + "\n"); // complete or untouched, never half a preset
}

} // namespace ssao
