// Settings that were given but do nothing: a row of the parameter table applies only under its
// conditions (Param::when, e.g. denoise.sigma only while denoise.kind = gaussian|bilateral), and the UI greys
// out the rows that do not; on the command line and in preset files such a key was silently ignored. These
// pure functions name each one and what it needs; the CLI prints them as warnings.
#pragma once
#include "settings/params.h"

#include <set>
#include <string>
#include <vector>

namespace ssao {

// Why `p` has no effect under `s`: the first condition it fails, as "denoise.kind = gaussian|bilateral
// (here box4)", following a condition on a row that itself does not apply; "" when `p` applies.
std::string inapplicableReason(const Param& p, const Settings& s);

// One line per key of `keys` (each once, in order; unknown keys skipped) that has no effect under
// `s`: "denoise.sigma has no effect: it applies only when denoise.kind = gaussian|bilateral (here box4)".
std::vector<std::string> inapplicableKeys(const Settings& s, const std::vector<std::string>& keys);

struct AssignmentCheck {
    Settings settings;                 // the input, with ao.radius_mode switched where a radius asks for it
    std::vector<std::string> warnings; // one line each, naming the key
};
// The settings after `--set` of `keys` (in order), checked: a radius row (ao.radius, ao.radius_scene,
// ao.radius_px) assigned while ao.radius_mode is another mode switches the mode to the radius's own,
// with one line saying so, unless ao.radius_mode is among `keys` too (the user chose it: the radius is
// then reported as having no effect); every other key that has no effect is reported.
AssignmentCheck checkAssignments(const Settings& s, const std::vector<std::string>& keys);

// `--set key=value` each, in order, onto `s`, then checkAssignments; returns its warnings, each
// starting "--set KEY". Throws ssao::Error on a bad assignment (as applyAssignment).
std::vector<std::string> applyAssignments(Settings& s, const std::vector<std::string>& assignments);

// The keys a preset file sets that have no effect under its own settings. A complete preset (the
// app, tune and bench write every row) holds the rows that do not apply too: of those only the ones
// moved off their defaults are reported.
std::vector<std::string> inapplicablePresetKeys(const Settings& s, const std::set<std::string>& keys);

} // namespace ssao
