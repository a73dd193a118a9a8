#version 450 core
// Visibility-bitmask AO (Therrien, Levesque, Gilet 2023), on GTAO's slices (gtao.frag): in each
// slice through the view vector V, every depth sample within the radius hides the angular
// interval between its front point and its back point (the front pushed away from the camera by
// the assumed thickness). The intervals are OR-ed into a mask of 32 equal sectors spanning the
// hemisphere around the normal, n - π/2 .. n + π/2 (angles from V, n the projected normal's).
// Unlike a horizon, a thin object hides only its own sectors: light passing behind it still counts.
// Visibility integrates the open sectors with GTAO's cosine weight cos(h - n)|sin h| (Jimenez
// 2016, eq. 10), so an empty mask reproduces GTAO's open value exactly.
#include "include/bindings.h"
#include "techniques/vbao/layout.h"
#include "include/frame.glsl"
#include "include/ao_common.glsl"
#include "include/noise.glsl"
#include "include/position_taps.glsl"
#include "include/slice.glsl"
#include "include/inspect.glsl"

layout(std140, binding = SSAO_UBO_AO) uniform VbaoBlock { VbaoConstants_ ssao; };
layout(binding = SSAO_TEX_POSITION) uniform sampler2D gPosition;
layout(binding = SSAO_TEX_NORMAL) uniform sampler2D gNormal;

in vec2 vUv;
layout(location = 0) out float oAO;



// Sector index (0..32) of angle h on the hemisphere's 32 sectors, rounded to the nearest edge.
int sectorEdge(float h, float n) {
    return int(clamp(round((h - (n - HALF_PI)) / PI * float(VBAO_SECTORS)), 0.0, float(VBAO_SECTORS)));
}
float edgeAngle(int e, float n) { return n - HALF_PI + float(e) * (PI / float(VBAO_SECTORS)); }

// G(h) = ∫₀ʰ cos(θ - n)|sin θ| dθ with the sign of h = ±(cos n + 2h sin n - cos(2h - n)) / 4: the
// cosine-weighted measure between V and angle h in a slice (GTAO's inner integral; the weight of
// [a, b] is G(b) - G(a)). Taken only at sector edges e (h = n - π/2 + e·π/32), where
// cos(2h - n) = cos(n - π + e·π/16) = -(cos n · C[e] - sin n · S[e]) with C, S the cos and sin of
// e·π/16: no trigonometry per pixel.
const float EDGE_C[33] = float[33](1.0, 0.98078528, 0.92387953, 0.83146961, 0.70710678, 0.55557023,
    0.38268343, 0.19509032, 0.0, -0.19509032, -0.38268343, -0.55557023, -0.70710678, -0.83146961,
    -0.92387953, -0.98078528, -1.0, -0.98078528, -0.92387953, -0.83146961, -0.70710678, -0.55557023,
    -0.38268343, -0.19509032, 0.0, 0.19509032, 0.38268343, 0.55557023, 0.70710678, 0.83146961,
    0.92387953, 0.98078528, 1.0);
const float EDGE_S[33] = float[33](0.0, 0.19509032, 0.38268343, 0.55557023, 0.70710678, 0.83146961,
    0.92387953, 0.98078528, 1.0, 0.98078528, 0.92387953, 0.83146961, 0.70710678, 0.55557023,
    0.38268343, 0.19509032, 0.0, -0.19509032, -0.38268343, -0.55557023, -0.70710678, -0.83146961,
    -0.92387953, -0.98078528, -1.0, -0.98078528, -0.92387953, -0.83146961, -0.70710678, -0.55557023,
    -0.38268343, -0.19509032, 0.0);
float arcGEdge(int e, float n, float cosN, float sinN) { // G at sector edge e
    float h = edgeAngle(e, n);
    float a = 0.25 * (cosN + 2.0 * h * sinN + (cosN * EDGE_C[e] - sinN * EDGE_S[e]));
    return h < 0.0 ? -a : a;
}

// The sectors a solid hides on one side of the slice: from its front point (`front`, already in the
// slice plane: aoSliceDelta) to its back point, the front pushed `gap` along -V.
uint intervalBits(vec3 front, float gap, vec3 V, float sgn, float n) {
    float ff = dot(front, front), fv = dot(front, V);
    float hFront = sgn * safeAcos(fv * inversesqrt(ff));
    float hBack = sgn * safeAcos((fv - gap) * inversesqrt(ff - 2.0 * gap * fv + gap * gap));
    int a = sectorEdge(min(hFront, hBack), n), b = sectorEdge(max(hFront, hBack), n);
    return b - a >= 32 ? 0xFFFFFFFFu : ((1u << uint(b - a)) - 1u) << uint(a);
}

void main() {
    vec2 uv0 = aoPixelUv(vUv); // the G-buffer texel this AO pixel stands for
    vec4 P4 = texture(gPosition, uv0);
    AO_SKY_EARLY_OUT(P4, uv0) // sky: unoccluded, no work spent (ao_common.glsl)
    vec3 P = P4.xyz;
    vec3 N = aoNormal(ssao.aoCommon, gPosition, gNormal, uv0, P);
    vec3 V = frameViewVector(P);
    float depth = -P.z;
    // Binary visibility within R, as the reference defines it: no falloff, no radius multiplier.
    float R = aoRadius(ssao.aoCommon, depth);
    float radiusPx = R * framePixelsPerUnit(depth);
    float thickness = ssao.params.x * R;
    float minS = ssao.params.z / max(radiusPx, 1e-6); // first step >= ~1.3 px: no self-occlusion
    // At least one of each (the parameter table's minimum): the loops below test at their end.
    int slices = max(ssao.modes.x, 1), steps = max(aoAdaptiveSteps(ssao.aoCommon, ssao.modes.y, radiusPx), 1); // ao.adaptive
    vec2 noise = aoNoiseOn(ssao.aoCommon) ? aoNoise(ssao.aoCommon, gl_FragCoord.xy) : vec2(0.5);

    // Each step's distance as a fraction of R, the same in every slice: computed once per pixel
    // rather than once per slice and step (a pow is an exp2 and a log2 on llvmpipe). The same AO
    // to the last bit.
    float stepS[VBAO_MAX_STEPS]; // steps <= VBAO_MAX_STEPS (the parameter table's maximum)
    int k = 0;
    do { stepS[k] = pow((float(k) + noise.y) / float(steps), ssao.params.y) + minS; } while (++k < steps);
    float visibility = 0.0, openSum = 0.0;
    int slice = 0;
    do { // do-while, not for: no masked pass after the last slice (ao_common.glsl, aoLoops)
        AoSlice sl = aoSlice((float(slice) + noise.x) / float(slices) * PI, V, N);
        vec2 omega = sl.omega;
        float projNLen = sl.projNLen, cosN = sl.cosN, n = sl.n;
        float sinN = sign(n) * sqrt(max(1.0 - cosN * cosN, 0.0)); // sin n, n = ±acos(cosN)
        uint mask = 0u;
        int step = 0;
        do {
            float s = stepS[step];
            vec2 offsetUv = round(s * radiusPx * omega) * frame.viewport.zw;
            for (int side = 0; side < 2; ++side) {
                vec2 uv = uv0 + (side == 0 ? offsetUv : -offsetUv);
                vec4 S; // off the held area (the frame and its guard band): unseen, no occluder
                bool held = aoTapHeld(ssao.aoCommon, gPosition, uv, s * radiusPx, S);
                vec3 front = S.xyz - P;
                float dist = length(front);
                // Off the frame, on the sky, the pixel itself or beyond the radius: hides nothing.
                // One select at the end rather than a branch per case: llvmpipe runs every side of a
                // branch its lanes disagree on, so the branches only cost; the same AO to the last
                // bit.
                bool counts = held && S.w != 0.0 && dist > 0.0 && dist <= R;
                front = aoSliceDelta(sl, front); // the angles in the slice plane (slice.glsl)
                // How far behind its front the sample's solid reaches: the assumed thickness, or
                // the true one where the back-face layer holds the far side of this surface
                // (gbuffer.back_faces). The back point is the front pushed by it along -V, the
                // pixel's own view direction, as the paper does (Therrien et al. 2023, listing 1:
                // deltaPosBackface = deltaPos - viewVec * thickness), not along the sample's own
                // ray: its angle then needs no vector of its own, |front - gap V|^2 = ff - 2 gap fv
                // + gap^2.
                float gap = aoBackGapOf(ssao.aoCommon, uv, S.xyz, thickness, ssao.modes.z != 0);
                float sgn = side == 0 ? 1.0 : -1.0; // side 0 at positive angles from V
                uint bits = intervalBits(front, gap, V, sgn, n);
                bits = counts ? bits : 0u; // a tap that does not count (NaN angles included) hides nothing
                bool hides = (bits & ~mask) != 0u; // the inspector's: it closes sectors still open
                mask |= bits;
                // What the depth buffer hides behind the tap (gbuffer.second_layer): its own interval,
                // its thickness bounded by the back-face layer where that lies behind it.
                vec4 S2 = aoSecondLayerAt(uv);
                vec3 front2 = S2.xyz - P;
                float dist2 = length(front2);
                bool counts2 = S2.w != 0.0 && dist2 > 0.0 && dist2 <= R;
                uint bits2 = 0u;
                if (counts2) // most taps have nothing within R behind them: no angles to compute
                    bits2 = intervalBits(aoSliceDelta(sl, front2), aoBackGapOf(ssao.aoCommon, uv, S2.xyz, thickness, ssao.modes.z != 0), V, sgn, n);
                bool hides2 = (bits2 & ~mask) != 0u;
                mask |= bits2;
                INSPECT_TAP(hides2 && !hides ? S2.xyz : held && S.w != 0.0 ? S.xyz : P, uv,
                            !held           ? SSAO_TAP_OFFSCREEN
                            : S.w == 0.0    ? SSAO_TAP_SKY
                            : !counts && !hides2 ? SSAO_TAP_OPEN
                                            : (hides || hides2 ? SSAO_TAP_OCCLUDED : SSAO_TAP_OPEN) |
                                                  (gap != thickness ? SSAO_TAP_BACK_LAYER : 0) |
                                                  (hides2 ? SSAO_TAP_SECOND_LAYER : 0),
                            float(bitCount(bits | bits2)) / 32.0, slice);
            }
        } while (++step < steps);
        // Open measure of the whole hemisphere minus that of each run of hidden sectors.
        float open = cosN + n * sinN; // G(n + π/2) - G(n - π/2), |n| <= π/2
        openSum += projNLen * open;
        // One run per pass; a do-while (ao_common.glsl, aoLoops) whose pass over an empty mask takes nothing.
        uint m = mask;
        int guard = 0;
        do {
            int a = max(findLSB(m), 0);
            uint rest = ~(m >> uint(a));
            int b = rest == 0u ? VBAO_SECTORS : min(a + findLSB(rest), VBAO_SECTORS);
            open -= m != 0u ? arcGEdge(b, n, cosN, sinN) - arcGEdge(a, n, cosN, sinN) : 0.0;
            m = b >= VBAO_SECTORS ? 0u : m & (0xFFFFFFFFu << uint(b));
        } while (m != 0u && ++guard < VBAO_SECTORS);
        visibility += projNLen * max(open, 0.0);
    } while (++slice < slices);
    visibility = aoSliceRatio(visibility, openSum);
    oAO = AO_RESULT(aoFinish(ssao.aoCommon, visibility));
    INSPECT_RESULT(true, P, N, 1.0 - visibility, float(slices), R, oAO);
}
