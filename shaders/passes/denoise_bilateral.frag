#version 450 core
// Edge-aware (bilateral) denoise: each neighbour of the AO input weighs
//   exp(-d²/2σ²)                      spatial, d in input texels
// × exp(-(|z - z₀| / z₀ · sharpness)²) depth similarity (relative: the same at any distance)
// × max(0, n·n₀)^p                    normal similarity (creases stay sharp)
// × exp(-((a - a₀) / σ_a)²)              AO similarity, when σ_a > 0 (a range term, Tomasi and
//                                      Manduchi 1998: detail that stands out of the noise stays)
// with z, n read from the full-resolution G-buffer at the neighbour's centre, so a reduced-
// resolution input is upsampled jointly (Kopf et al. 2007, "Joint Bilateral Upsampling") rather
// than bilinearly across silhouettes (denoise.upsample=filter). With denoise.upsample=joint the
// filter runs at the AO's own resolution (taps.y = k: 1/k of the G-buffer's) and reads, for AO
// texel t, the G-buffer texel its AO was computed at (t·k, aoPixelUv); passes/upsample_joint.frag
// then brings it to full size. Not separable: a 2-D window (the bilateral is not a product of 1-D
// filters). Sky pixels pass through as 1.
#include "include/bindings.h"

layout(std140, binding = SSAO_UBO_DENOISE) uniform DenoiseBlock { DenoiseConstants_ denoise; };
layout(binding = SSAO_TEX_AO) uniform sampler2D aoIn;
layout(binding = SSAO_TEX_LINEAR_DEPTH) uniform sampler2D gDepth;
layout(binding = SSAO_TEX_NORMAL) uniform sampler2D gNormal;

in vec2 vUv;
layout(location = 0) out float oAO;

vec3 normalAt(vec2 uv) {
    vec3 n = textureLod(gNormal, uv, 0.0).xyz;
    if ((denoise.taps.z & SSAO_DENOISE_NORMAL_UNORM) != 0) n = n * 2.0 - 1.0;
    float l2 = dot(n, n);
    return l2 > 1e-12 ? n * inversesqrt(l2) : vec3(0.0, 0.0, 1.0);
}

// The G-buffer sample of AO texel t: its centre when the output is at the G-buffer's resolution,
// texel t·k when the filter runs at the AO's resolution (taps.y = k).
vec2 gbufferUv(ivec2 t, ivec2 inSize) {
    int k = denoise.taps.y;
    return k > 0 ? (vec2(t * k) + 0.5) / vec2(textureSize(gDepth, 0)) : (vec2(t) + 0.5) / vec2(inSize);
}

void main() {
    ivec2 inSize = textureSize(aoIn, 0);
    ivec2 c = clamp(ivec2(vUv * vec2(inSize)), ivec2(0), inSize - 1);
    vec2 uv0 = denoise.taps.y > 0 ? gbufferUv(c, inSize) : vUv; // this output pixel's own sample
    float z0 = textureLod(gDepth, uv0, 0.0).r;
    if (!(z0 > 0.0)) { // sky
        oAO = 1.0;
        return;
    }
    vec3 n0 = normalAt(uv0);
    float sigma = denoise.offsetsWeights[0].x, sharp = denoise.offsetsWeights[0].y;
    float npow = denoise.offsetsWeights[0].z, invAoSigma = denoise.offsetsWeights[0].w;
    float a0 = texelFetch(aoIn, c, 0).r;
    int r = denoise.taps.x;
    float sum = 0.0, wsum = 0.0;
    // do-whiles, not fors: no masked pass after the last row and column (ao_common.glsl, aoLoops);
    // -r <= r always holds, so each runs at least once, and a continue goes to the test.
    int dy = -r;
    do {
        int dx = -r;
        do {
            ivec2 t = c + ivec2(dx, dy);
            if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, inSize))) continue;
            vec2 tuv = gbufferUv(t, inSize);
            float z = textureLod(gDepth, tuv, 0.0).r;
            if (!(z > 0.0)) continue; // sky holds no AO of a surface
            float rel = abs(z - z0) / z0 * sharp;
            float a = texelFetch(aoIn, t, 0).r;
            float ra = (a - a0) * invAoSigma;
            float w = exp(-float(dx * dx + dy * dy) / (2.0 * sigma * sigma)) * exp(-rel * rel) *
                      pow(max(dot(normalAt(tuv), n0), 0.0), npow) * exp(-ra * ra);
            sum += a * w;
            wsum += w;
        } while (++dx <= r);
    } while (++dy <= r);
    // No similar neighbour at all (a lone pixel): keep its own value rather than divide by ~0.
    float ao = wsum > 1e-6 ? sum / wsum : a0;
    oAO = ao > 1.0 ? 1.0 : ao; // a weighted mean of ones may round past 1; a NaN stays visible
}
