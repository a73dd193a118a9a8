// What the explorer's front panel measures for the view on screen: every shipped preset of every
// technique, the user's current settings, the current settings' neighbours (AO resolution
// full/half/quarter, each denoiser, the technique's quality ladder) and each user technique
// (techniques/user/) at its defaults. Every candidate runs with the
// world radius R the live reference traced, as `bench` gives every configuration the reference's R.
#pragma once
#include "settings/preset_store.h"
#include "settings/settings.h"

#include <string>
#include <vector>

namespace ssao {

struct Candidate {
    std::string label;  // "gtao-high", "current", "current + ao.resolution=half"
    std::string origin; // "preset", "current", "neighbour", "user technique" or "engine" (front/engine_front.h)
    Settings settings;  // with the reference's world radius (withRadius); unused for an engine
    bool baseline = false;
    bool current = false;
    // A web engine's point: its settings are the engine's own (JavaScript), not ssaolab's.
    bool isEngine() const { return origin == "engine"; }
};

// Distinct candidates (by effective settings; the first label wins), the baseline preset included
// and flagged, the current settings second. Throws ssao::Error when the baseline is missing.
std::vector<Candidate> frontCandidates(const Settings& current, const PresetStore& store, float radius,
                                       const std::string& baseline = "learnopengl");

// Settings `chosen` with the user's radius fields of `current` (the candidate measured with the
// reference's R; applied, it keeps the radius the user chose).
Settings withRadiusOf(Settings chosen, const Settings& current);

} // namespace ssao
