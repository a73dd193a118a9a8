#version 450 core
// GTAO (Jimenez, Wu, Pesce, Jarabo 2016), laid out like Intel XeGTAO's MainPass (our own code):
// for each slice (a screen direction ω through the pixel, i.e. a plane containing the view
// vector V), march the depth buffer on both sides to find the highest horizon, then integrate the
// cosine-weighted visibility between the two horizons analytically (the paper's eq. 10):
//   â = ¼(−cos(2h₀ − n) + cos n + 2h₀ sin n) + ¼(−cos(2h₁ − n) + cos n + 2h₁ sin n)
// weighted by the length of the normal projected into the slice, averaged over slices.
#include "include/bindings.h"
#include "techniques/gtao/layout.h"
#include "include/frame.glsl"
#include "include/ao_common.glsl"
#include "include/noise.glsl"
#include "include/position_taps.glsl"
#include "include/slice.glsl"
#include "include/inspect.glsl"

layout(std140, binding = SSAO_UBO_AO) uniform GtaoBlock { GtaoConstants_ ssao; };
layout(binding = SSAO_TEX_POSITION) uniform sampler2D gPosition;
layout(binding = SSAO_TEX_NORMAL) uniform sampler2D gNormal;

in vec2 vUv;
layout(location = 0) out float oAO;



void main() {
    vec2 uv0 = aoPixelUv(vUv); // the G-buffer texel this AO pixel stands for
    vec4 P4 = texture(gPosition, uv0);
    AO_SKY_EARLY_OUT(P4, uv0) // sky: unoccluded, no work spent (ao_common.glsl)
    vec3 P = P4.xyz;
    vec3 N = aoNormal(ssao.aoCommon, gPosition, gNormal, uv0, P); // G-buffer or from depth
    vec3 V = frameViewVector(P);
    float depth = -P.z;

    // Search radius (world) and its size in G-buffer pixels: a unit at view depth d spans
    // proj[1][1] * H / (2 d) pixels.
    float R = aoRadius(ssao.aoCommon, depth) * ssao.search.x;
    float radiusPx = R * framePixelsPerUnit(depth);
    float falloffMul = ssao.search.y / R, falloffAdd = ssao.search.z;
    // The first step lands at least ~1.3 px away: sampling the pixel itself gives a zero delta
    // (NaN direction) and self-occlusion lines (XeGTAO minS; HBAO "first step >= 1 px").
    float minS = ssao.thin.y / max(radiusPx, 1e-6);
    // At least one of each (the parameter table's minimum): the loops below test at their end.
    int slices = max(ssao.modes.x, 1), steps = max(aoAdaptiveSteps(ssao.aoCommon, ssao.modes.y, radiusPx), 1); // ao.adaptive
    vec2 noise = vec2(0.5);
    if (aoNoiseOn(ssao.aoCommon)) noise = aoNoise(ssao.aoCommon, gl_FragCoord.xy);

    // Each step's distance as a fraction of R, the same in every slice: computed once per pixel
    // rather than once per slice and step (a pow is an exp2 and a log2 on llvmpipe; vbao.frag does
    // the same). The same AO to the last bit.
    float stepS[GTAO_MAX_STEPS]; // steps <= GTAO_MAX_STEPS (the parameter table's maximum)
    int k = 0;
    do { stepS[k] = pow((float(k) + noise.y) / float(steps), ssao.search.w) + minS; } while (++k < steps);
    float visibility = 0.0, openSum = 0.0;
    int slice = 0;
    do { // do-while, not for: no masked pass after the last slice (ao_common.glsl, aoLoops)
        AoSlice sl = aoSlice((float(slice) + noise.x) / float(slices) * PI, V, N);
        vec2 omega = sl.omega;
        float projNLen = sl.projNLen, cosNorm = sl.cosN, n = sl.n; // n: the normal's angle from V
        // With no occluder the horizons are the tangent plane: n ± π/2.
        // cos(n ± π/2) = ∓sin n, and sin n = ±sqrt(1 - cos² n): no trigonometry.
        float sinN = sign(n) * sqrt(max(1.0 - cosNorm * cosNorm, 0.0));
        float lowCos0 = -sinN, lowCos1 = sinN;
        float hCos0 = lowCos0, hCos1 = lowCos1;
        int step = 0;
        do {
            float s = stepS[step];
            // Snap to texel centres: positions are not interpolated (XeGTAO rounds likewise).
            vec2 offsetUv = round(s * radiusPx * omega) * frame.viewport.zw;
            for (int side = 0; side < 2; ++side) {
                vec2 uv = uv0 + (side == 0 ? offsetUv : -offsetUv);
                vec4 S; // off the held area (the frame and its guard band): unseen, no occluder
                bool held = aoTapHeld(ssao.aoCommon, gPosition, uv, s * radiusPx, S);
                vec3 delta = S.xyz - P;
                float dist = length(delta);
                // Off the frame, on the sky or the same texel (no direction to a horizon): the tap
                // leaves the horizon where it is. A select, not a branch per case (vbao.frag: on
                // llvmpipe the branches only cost); the same AO to the last bit.
                bool counts = held && S.w != 0.0 && dist > 0.0;
                vec3 inSlice = aoSliceDelta(sl, delta); // the angle in the slice plane (slice.glsl)
                float shc = dot(inSlice, V) / max(length(inSlice), 1e-30);
                // Thin-occluder heuristic: depth differences count (1 + t) times in the falloff.
                float falloffBase = length(vec3(delta.xy, delta.z * (1.0 + ssao.thin.x)));
                float w = clamp(falloffBase * falloffMul + falloffAdd, 0.0, 1.0);
                float low = side == 0 ? lowCos0 : lowCos1;
                // Beyond the radius an occluder fades to the tangent plane; a tap that does not
                // count is the tangent plane itself, which never raises a horizon (hCos >= low).
                shc = counts ? mix(low, shc, w) : low;
                // What the depth buffer hides behind the tap (gbuffer.second_layer) is a candidate
                // horizon too, weighed by the same falloff: where the tap is out of reach (an
                // occluder near the eye), the surface behind it may not be.
                vec4 S2 = aoSecondLayerAt(uv);
                vec3 delta2 = S2.xyz - P;
                bool second = false; // the second layer's surface set this tap's horizon
                if (S2.w != 0.0 && dot(delta2, delta2) > 0.0) {
                    vec3 inSlice2 = aoSliceDelta(sl, delta2);
                    float shc2 = dot(inSlice2, V) / max(length(inSlice2), 1e-30);
                    float w2 = clamp(length(vec3(delta2.xy, delta2.z * (1.0 + ssao.thin.x))) * falloffMul + falloffAdd, 0.0, 1.0);
                    shc2 = mix(low, shc2, w2);
                    second = shc2 > shc;
                    shc = max(shc, shc2);
                }
                bool raises = side == 0 ? shc > hCos0 : shc > hCos1;
                if (side == 0) hCos0 = max(hCos0, shc);
                else hCos1 = max(hCos1, shc);
                INSPECT_TAP(held && S.w != 0.0 ? S.xyz : P, uv,
                            !held         ? SSAO_TAP_OFFSCREEN
                            : S.w == 0.0  ? SSAO_TAP_SKY
                            : second      ? (raises ? SSAO_TAP_OCCLUDED : SSAO_TAP_OPEN) | SSAO_TAP_SECOND_LAYER
                            : !counts     ? SSAO_TAP_OPEN
                            : raises && w > 0.0 ? SSAO_TAP_OCCLUDED : SSAO_TAP_OPEN,
                            counts ? w : 0.0, slice);
            }
        } while (++step < steps);
        // Horizon angles from V (side 0 positive), kept within the hemisphere around the normal.
        float h0 = -safeAcos(hCos1), h1 = safeAcos(hCos0);
        h0 = n + clamp(h0 - n, -HALF_PI, HALF_PI);
        h1 = n + clamp(h1 - n, -HALF_PI, HALF_PI);
        float iarc0 = (cosNorm + 2.0 * h0 * sinN - cos(2.0 * h0 - n)) * 0.25;
        float iarc1 = (cosNorm + 2.0 * h1 * sinN - cos(2.0 * h1 - n)) * 0.25;
        visibility += projNLen * (iarc0 + iarc1);
        openSum += projNLen * (cosNorm + n * sinN); // the same with both horizons on the tangent plane
    } while (++slice < slices);
    visibility = aoSliceRatio(visibility, openSum);
    oAO = AO_RESULT(aoFinish(ssao.aoCommon, visibility));
    INSPECT_RESULT(true, P, N, 1.0 - visibility, float(slices), R, oAO);
}
