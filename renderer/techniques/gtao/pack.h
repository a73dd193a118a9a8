// GTAO settings → its GPU constants (shaders/techniques/gtao/layout.h), pure and tested.
#pragma once
#include "techniques/technique_settings.h"

#include "../../../shaders/include/bindings.h"
#include "../../../shaders/techniques/gtao/layout.h"

namespace ssao {

// The slices and steps per side a setting means: XeGTAO's quality presets, or the custom rows.
void gtaoSlicesSteps(const GtaoSettings& s, int& slices, int& steps);
gpu::GtaoConstants packGtaoConstants(const GtaoSettings& s, const gpu::AoCommon& common);

} // namespace ssao
