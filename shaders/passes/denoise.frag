#version 450 core
// One direction of the separable denoise filter (box 4x4 of seed 004 or gaussian of seed 003).
// Both 2-D kernels are products of 1-D ones and clamp-to-edge is per axis, so two passes give
// exactly the seeds' double loop. Offsets are in texels of the input, so the y pass can read a
// reduced-resolution x result (bilinearly) and upsample. No NaN scrubbing here: a NaN from the AO
// pass must stay visible.
#include "include/bindings.h"

layout(std140, binding = SSAO_UBO_DENOISE) uniform DenoiseBlock { DenoiseConstants_ denoise; };
layout(binding = SSAO_TEX_AO) uniform sampler2D aoIn;
layout(binding = SSAO_TEX_LINEAR_DEPTH) uniform sampler2D gDepth; // read with SSAO_DENOISE_SKIP_SKY

in vec2 vUv;
layout(location = 0) out float oAO;

void main() {
    // The last pass writes nothing a later pass filters: sky pixels (no surface to shade) skip it.
    if ((denoise.taps.z & SSAO_DENOISE_SKIP_SKY) != 0 && !(textureLod(gDepth, vUv, 0.0).r > 0.0)) {
        oAO = 1.0;
        return;
    }
    vec2 texel = 1.0 / vec2(textureSize(aoIn, 0));
    vec2 dir = denoise.taps.y == 0 ? vec2(texel.x, 0.0) : vec2(0.0, texel.y);
    float sum = 0.0;
    int i = 0;
    if (denoise.taps.x > 0) do { // do-while, not for: no masked pass after the last tap (ao_common.glsl, aoLoops)
        vec4 ow = denoise.offsetsWeights[i];
        sum += texture(aoIn, vUv + dir * ow.x).r * ow.y;
    } while (++i < denoise.taps.x);
    // Weights summing to at most 1 still round a sum of ones to 1.0000001-1.0000004 in float
    // (seed003 on CornellBox did): clamp from above. A NaN fails the comparison and stays visible.
    oAO = sum > 1.0 ? 1.0 : sum;
}
