#include "settings/preset.h"

#include "settings/params.h"
#include "util/error.h"

#include <cmath>
#include <filesystem>
#include <fstream>

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

nlohmann::json cameraToJson(const Camera& c) {
    return {{"eye", {c.eye.x, c.eye.y, c.eye.z}},
            {"target", {c.target.x, c.target.y, c.target.z}},
            {"up", {c.up.x, c.up.y, c.up.z}},
            {"fov_y_deg", c.fovYDeg},
            {"near", c.nearZ},
            {"far", c.farZ}};
}

Camera cameraFromJson(const nlohmann::json& j, const std::string& origin) {
    if (!j.is_object()) throw Error(origin + ": camera must be an object");
    for (auto& [k, v] : j.items())
        if (k != "eye" && k != "target" && k != "up" && k != "fov_y_deg" && k != "near" && k != "far")
            throw Error(origin + ": unknown key 'camera." + k + "'");
    Camera c;
    c.eye = vec3From(j, "eye", origin);
    c.target = vec3From(j, "target", origin);
    c.up = j.contains("up") ? vec3From(j, "up", origin) : glm::vec3(0, 1, 0);
    c.fovYDeg = numberFrom(j, "fov_y_deg", c.fovYDeg, origin);
    c.nearZ = numberFrom(j, "near", c.nearZ, origin);
    c.farZ = numberFrom(j, "far", c.farZ, origin);
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
    if (p.camera) j["camera"] = cameraToJson(*p.camera);
    j.update(toJson(p.settings));
    return j;
}

Preset presetFromJson(const nlohmann::json& j, const std::string& origin) {
    Preset p;
    p.settings = defaultSettings();
    applyJson(p.settings, j, origin); // skips name / description / camera, rejects anything unknown
    if (j.contains("name")) {
        if (!j["name"].is_string()) throw Error(origin + ": name must be a string");
        p.name = j["name"].get<std::string>();
    }
    if (j.contains("description") && j["description"].is_string())
        p.description = j["description"].get<std::string>();
    if (j.contains("camera")) p.camera = cameraFromJson(j["camera"], origin);
    return p;
}

Preset readPresetFile(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error("preset file not found: " + path);
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& e) {
        std::string what = e.what();
        throw Error("preset " + path + " is not valid JSON (" + what.substr(what.find("parse error")) + ")");
    }
    Preset p = presetFromJson(j, "preset " + path);
    if (p.name.empty()) p.name = std::filesystem::path(path).stem().string();
    return p;
}

void writePresetFile(const Preset& p, const std::string& path) {
    std::error_code ec;
    const auto parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent, ec);
    std::ofstream out(path);
    if (!out) throw Error("cannot write preset " + path);
    out << presetToJson(p).dump(2) << "\n";
    if (!out) throw Error("cannot write preset " + path);
}

} // namespace ssao
