// The G-buffer's optional layers by resource name: their passes write them (passes/), the AO passes
// read them (techniques/ao_pass.cpp), and the renderer adds a layer's pass when the settings ask.
#pragma once

namespace ssao::gbuffer {

constexpr const char* kPositionMips = "gbuffer.position_mips"; // passes/position_pyramid_pass.h
constexpr const char* kGuardBand = "gbuffer.guard_band";       // passes/guard_band_pass.h
constexpr const char* kBackDepth = "gbuffer.back_depth";       // passes/back_face_pass.h
constexpr const char* kSecondLayer = "gbuffer.second_layer";   // passes/second_layer_pass.h

} // namespace ssao::gbuffer
