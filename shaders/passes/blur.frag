#version 450 core
// One direction of a separable blur (box 4x4 of seed 004 or gaussian of seed 003). Both 2-D
// kernels are products of 1-D ones and clamp-to-edge is per axis, so two passes give exactly
// the seeds' double loop. No NaN scrubbing here: a NaN from the AO pass must stay visible.
#include "include/frame.glsl"

layout(std140, binding = SSAO_UBO_BLUR) uniform BlurBlock { BlurConstants_ blur; };
layout(binding = SSAO_TEX_AO) uniform sampler2D aoIn;

in vec2 vUv;
layout(location = 0) out float oAO;

void main() {
    vec2 dir = blur.taps.y == 0 ? vec2(frame.viewport.z, 0.0) : vec2(0.0, frame.viewport.w);
    float sum = 0.0;
    for (int i = 0; i < blur.taps.x; ++i) {
        vec4 ow = blur.offsetsWeights[i];
        sum += texture(aoIn, vUv + dir * ow.x).r * ow.y;
    }
    oAO = sum;
}
