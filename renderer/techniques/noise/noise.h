// The per-pixel noise the horizon techniques (SAO, HBAO, GTAO, visibility bitmask) rotate their
// directions and offset their steps by: one choice for all of them, packed into AoCommon.estimator.y
// and evaluated by shaders/include/noise.glsl. Every kind also moves with the temporal frame index
// so accumulation averages different patterns.
#pragma once
#include "../../../shaders/include/bindings.h"

#include <string>
#include <utility>
#include <vector>

namespace ssao {

enum class AoNoise { Ign, R2, Blue, Tile4, None }; // SSAO_NOISE_* (bindings.h), same order

// The parameter rows' choices: {"ign", "r2", "blue", "tile4", "none"}.
std::vector<std::pair<std::string, AoNoise>> aoNoiseChoices();
// One line for the rows' help.
extern const char* const kAoNoiseHelp;

// Help of the techniques' "pyramid" rows (passes/position_pyramid_pass.h).
extern const char* const kPyramidHelp;

// Writes the noise kind into the shared constants (estimator.y).
void packNoise(gpu::AoCommon& c, AoNoise n);

} // namespace ssao
