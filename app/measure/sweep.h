// A benchmark sweep: a base preset plus groups of parameter lists whose products are the
// configurations (JSON, assets/bench/sweep_builtin.json is the built-in one):
//   {"name": "...", "base": {"preset": "learnopengl" | "" (defaults), "set": {"key": value}},
//    "groups": [{"name": "...", "set": {"key": value}, "vary": {"key": [v1, v2], "key2": [...]}}]}
// Each group yields base + set + every combination of its "vary" lists. Configurations that render
// alike (equal effective settings, denoise.kind=auto resolved) are measured once, under the first
// label, the later labels kept as its aliases; every registered technique at its defaults and the
// `learnopengl` baseline are always added.
#pragma once
#include "settings/settings.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace ssao {

struct BenchConfig {
    std::string label;   // "ao.resolution=half denoise.kind=none"; the baseline is "learnopengl (baseline)"
    std::string group;   // the sweep group it came from
    Settings settings;   // before the bench's radius is applied
    nlohmann::json keys; // {"ao.power": 2, ...}: what differs from the base
    bool baseline = false;
    std::vector<std::string> aliases; // later labels of the same configuration ("vbao defaults")
    // A web engine's row (bench --engines, commands/bench/bench_engines.h): {"name", "title", "package",
    // "version", "values", "scale"}; null for ssaolab's own configurations (then `settings` holds it).
    nlohmann::json engine;

    bool isEngine() const { return engine.is_object(); }
    // The technique column: ssaolab's technique, or the engine's name.
    std::string technique() const { return isEngine() ? engine.value("name", std::string()) : settings.ao.technique; }
};

constexpr size_t kMaxAliases = 16; // aliases kept per configuration (a list of equal values repeats one)

struct Sweep {
    std::string name, description;
    std::vector<BenchConfig> configs;
    size_t baseline = 0; // index of the baseline configuration
    std::vector<std::string> warnings; // of the presets it opened (Preset::warnings), each once
};

// Keys a sweep may not set: the bench gives every configuration the same radius (the reference's).
bool isRadiusKey(const std::string& key);

// Throws ssao::Error naming the file and the key on bad input (unknown key, bad value, radius key,
// empty lists, more than `maxConfigs` configurations).
// `baseline` names the preset every row is compared with.
Sweep parseSweep(const nlohmann::json& j, const std::string& origin, const std::string& presetDir = "",
                 size_t maxConfigs = 2000, const std::string& baseline = "learnopengl");
// "builtin" or a JSON file path.
Sweep loadSweep(const std::string& nameOrPath, const std::string& presetDir = "",
                const std::string& baseline = "learnopengl");

} // namespace ssao
