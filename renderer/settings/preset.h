// A preset file: a JSON patch over the defaults, plus optional metadata, the scene it was made
// for, the render size and a camera bookmark.
//   {"name": "...", "description": "...", "scene": "builtin:showcase" | "path/to/file.gltf",
//    "size": [1280, 720], "camera": {"eye": [..], "target": [..], "up": [..], "fov_y_deg": 60,
//    "near": 0.1, "far": 100, "clip": "fit"}, "reference_radius_scene": 0.05, "scores": {...},
//    "ao": {"radius_mode": "world", "radius": 0.8}, ...}
// The app saves exactly this format and `ssaolab render --preset` reads it, so a preset tuned
// in the window reproduces the same image headless.
#pragma once
#include "scene/camera.h"
#include "settings/settings.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace ssao {

struct Preset {
    std::string name;
    std::string description;
    Settings settings;
    std::set<std::string> keys;       // parameter keys the file sets (the rest are defaults)
    std::optional<std::string> scene; // scene spec; a relative path is relative to the preset file
    std::optional<std::pair<int, int>> size;
    std::optional<Camera> camera;
    // The reference's R the preset was judged against, as a fraction of the scene's diagonal, when
    // it is not the preset's own AO radius (a tune that fitted a radius multiplier): render
    // --reference then judges against this R, as tune did.
    std::optional<float> referenceRadiusScene;
    // How the preset scored where it was made (tune: training and held-out geometry RMSE, scenes);
    // kept as written, shown, never applied.
    nlohmann::json scores;
    // readPresetFile: one line per key the file sets that has no effect under its own settings,
    // "preset PATH: KEY has no effect: ..." (settings/applicability.h); the CLI prints them.
    std::vector<std::string> warnings;

    // True when the preset chooses the AO radius itself; otherwise the radius follows the scene.
    bool fixesRadius() const;
};

// Top-level keys that are preset metadata, not parameter groups.
// The shipped preset a new user's first frame uses (the window, and the headless render the
// README's first command runs without a display): a point of the time-against-error front that
// shows AO clearly on every shared scene at less than the learnopengl seed's cost
// (tests/gl/test_start_preset.cpp). The seeds' kernel is one click away in the preset list.
inline constexpr const char* kStartPreset = "vbao-medium";

bool isPresetMetadataKey(const std::string& key);

nlohmann::json cameraToJson(const Camera& c);
Camera cameraFromJson(const nlohmann::json& j, const std::string& origin); // validated

nlohmann::json presetToJson(const Preset& p); // every parameter written: a complete preset
// `baseDir` resolves a relative "scene" path (the folder of the preset file).
Preset presetFromJson(const nlohmann::json& j, const std::string& origin, const std::string& baseDir = "");
Preset readPresetFile(const std::string& path); // throws ssao::Error naming file and key
void writePresetFile(const Preset& p, const std::string& path);

// Every key the radius depends on: a preset setting any of them fixes the radius.
const std::vector<std::string>& radiusKeys();
// Resets those keys to their defaults, so the radius follows the scene.
void resetRadius(Settings& s);

} // namespace ssao
