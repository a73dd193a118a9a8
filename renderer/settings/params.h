// The parameter table: one row per user-facing setting (key, range, unit, help, when it applies).
// It drives JSON presets, `--set key=value`, the UI, `ssaolab params` and the tests. The table
// is the core rows (gbuffer, ao, denoise, composite) plus each registered technique's rows.
// Defaults are not written here: each row reads its default from Settings{} (settings.h).
#pragma once
#include "base/param.h"
#include "settings/settings.h"

#include <nlohmann/json_fwd.hpp>

#include <functional>
#include <string>
#include <vector>

namespace ssao {

const std::vector<Param>& paramTable();
const Param* findParam(const std::string& key);

// Settings{} — every default, the one place they are defined.
Settings defaultSettings();

// Sets `key` from its text form; throws ssao::Error naming the key on unknown key, bad
// syntax, out-of-range or non-finite value.
void setParam(Settings& s, const std::string& key, const std::string& text);
// `--set key=value`.
void applyAssignment(Settings& s, const std::string& assignment);
// Every row that applies holds a finite value within its range (an integer for integer rows, a
// known choice for enums): the one place ranges are checked - the packing functions trust it.
// Throws ssao::Error naming the first key that does not. Renderer::setSettings calls it.
void validateSettings(const Settings& s);

// After the user techniques changed (a new version adopted): drops the user values whose rows are
// gone and brings the others into their rows' new ranges (the nearest valid value).
void fitUserValues(Settings& s);

// JSON: {"ao": {"radius": 0.5, ...}, ...}. Presets are patches over defaults; toJson writes
// every key, so write → read round-trips exactly.
nlohmann::json toJson(const Settings& s);
// toJson without the rows that do not apply (e.g. denoise.sigma under box4): what a pass's
// output depends on, so changing an inactive row re-runs nothing.
nlohmann::json toEffectiveJson(const Settings& s);
// Applies a patch; the preset metadata keys (settings/preset.h) at top level are skipped.
void applyJson(Settings& s, const nlohmann::json& patch, const std::string& origin);
Settings loadPreset(const std::string& path); // defaults + the file's patch

bool operator==(const Settings& a, const Settings& b);
inline bool operator!=(const Settings& a, const Settings& b) {
    return !(a == b);
}

} // namespace ssao
