// Rows every horizon technique (SAO, HBAO, GTAO, visibility bitmask) has, written once: its noise
// kind (techniques/noise/noise.h) and its position pyramid switch (passes/position_pyramid_pass.h).
// `field` is the member path in Settings, e.g. gtao.noise.
#pragma once
#include "base/param_rows.h"
#include "techniques/noise/noise.h"

#define NOISE_ROW(key, field) ENUM_ROW(key, "Noise", field, AoNoise, ::ssao::kAoNoiseHelp, (::ssao::aoNoiseChoices()))
#define PYRAMID_ROW(key, field) BOOL_ROW(key, "Position MIPs", field, ::ssao::kPyramidHelp)
