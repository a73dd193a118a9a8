// A preset file: a JSON patch over the defaults, plus optional metadata and a camera bookmark.
//   {"name": "...", "description": "...", "camera": {"eye": [..], "target": [..], "up": [..],
//    "fov_y_deg": 60, "near": 0.1, "far": 100}, "ssao": {"radius": 0.8}, ...}
// The app saves exactly this format and `ssaolab render --preset` reads it, so a preset tuned
// in the window reproduces the same image headless.
#pragma once
#include "scene/camera.h"
#include "settings/settings.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace ssao {

struct Preset {
    std::string name;
    std::string description;
    Settings settings;
    std::optional<Camera> camera;
};

nlohmann::json cameraToJson(const Camera& c);
Camera cameraFromJson(const nlohmann::json& j, const std::string& origin); // validated

nlohmann::json presetToJson(const Preset& p); // every parameter written: a complete preset
Preset presetFromJson(const nlohmann::json& j, const std::string& origin);
Preset readPresetFile(const std::string& path); // throws ssao::Error naming file and key
void writePresetFile(const Preset& p, const std::string& path);

} // namespace ssao
