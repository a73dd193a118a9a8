#version 450 core
// The joint-bilateral 2x2 upsample of reduced-resolution AO as a pass of its own (its output,
// ao.denoised, is shown or judged): include/joint_upsample.glsl.
#include "include/bindings.h"
#include "include/joint_upsample.glsl"

layout(std140, binding = SSAO_UBO_DENOISE) uniform DenoiseBlock { DenoiseConstants_ denoise; };
layout(binding = SSAO_TEX_AO) uniform sampler2D aoIn;
layout(binding = SSAO_TEX_LINEAR_DEPTH) uniform sampler2D gDepth; // linear view depth, sky = 0

layout(location = 0) out float oAO;

void main() { oAO = jointUpsample(aoIn, gDepth, ivec2(gl_FragCoord.xy), denoise.taps.w); }
