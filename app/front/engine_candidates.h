// The web engines as Front tab candidates (engines/engine_table.h): each engine at its make-peers
// settings (its defaults with every length from R) and as its package ships it, and each `ssaolab tune --engine --out` result
// found in the user's folder for them or added by path. A tuned result is its fit, as `tune`
// applies it to its held-out views: a knob relative to the view's make-peers value is that factor
// (the runner multiplies, as `bench --engine-settings` runs it), one per R is that multiple of this
// view's R, every other setting (cost settings included) the engine's value.
#pragma once
#include "engines/engine_table.h"

#include <utility>

#include <map>
#include <string>
#include <vector>

namespace ssao {

struct EngineCandidate {
    std::string engine; // the table's name ("n8ao")
    std::string label;  // "N8AO defaults", "N8AO tuned (n8ao-cornell)"
    std::string file;   // the tune result ("" = the make-peers settings)
    std::map<std::string, double> scale;     // x the view's make-peers value (EngineJob::scale)
    std::map<std::string, std::pair<double, int>> perRadius; // factor x the view's R^exponent
    std::map<std::string, double> values;    // the engine's value
    bool shipped = false;                    // the package's defaults verbatim (no length from R)
    bool tuned() const { return !file.empty(); }
};

// "N8AO" of "N8AO (N8AOPass)", "three.js SAOPass" as it is.
std::string engineShortTitle(const EngineTable& t);

// Each named engine's make-peers candidate and its as-shipped one, in the order given.
std::vector<EngineCandidate> engineDefaultCandidates(const std::vector<std::string>& engines);

// A `tune --engine --out` JSON file as a candidate (engines/engine_settings_file.h reads it); throws
// ssao::Error (one line) naming the file.
EngineCandidate tunedEngineCandidate(const std::string& file);

// The tune results directly in `dir` (*.json, sorted; an absent folder holds none): candidates of
// `engines` only; a file that does not read adds its one-line reason to `errors`.
std::vector<EngineCandidate> tunedEnginesIn(const std::string& dir, const std::vector<std::string>& engines,
                                            std::vector<std::string>& errors);

// The engine's values for a candidate on a view of world radius R (integers rounded, 6 significant
// digits); scale goes to the runner as it is. Empty for the make-peers candidate.
std::map<std::string, double> engineJobValues(const EngineCandidate& c, const EngineTable& t, double radius);

} // namespace ssao
