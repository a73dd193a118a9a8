#version 450 core
// HBAO (Bavoil, Sainz, Dimitrov 2008; seed 002), with HBAO+'s per-sample attenuation: along each
// of D screen directions, march S steps; every sample that raises the horizon above the highest
// so far adds (sin h - sin h_prev) W(r), W = max(0, 1 - r/R) (the paper's linear falloff), with
// the horizon starting at the tangent bias. AO = 1 - mean over directions (uniform solid angle).
#include "include/bindings.h"
#include "techniques/hbao/layout.h"
#include "include/frame.glsl"
#include "include/ao_common.glsl"
#include "include/noise.glsl"
#include "include/position_taps.glsl"
#include "include/inspect.glsl"

layout(std140, binding = SSAO_UBO_AO) uniform HbaoBlock { HbaoConstants_ ssao; };
layout(binding = SSAO_TEX_POSITION) uniform sampler2D gPosition;
layout(binding = SSAO_TEX_NORMAL) uniform sampler2D gNormal;

in vec2 vUv;
layout(location = 0) out float oAO;

const float TWO_PI = 6.28318530717959;


void main() {
    vec2 uv0 = aoPixelUv(vUv); // the G-buffer texel this AO pixel stands for
    vec4 P4 = texture(gPosition, uv0);
    AO_SKY_EARLY_OUT(P4, uv0) // sky: unoccluded, no work spent (ao_common.glsl)
    vec3 P = P4.xyz;
    vec3 N = aoNormal(ssao.aoCommon, gPosition, gNormal, uv0, P); // G-buffer or from depth
    float depth = -P.z;
    float R = aoRadius(ssao.aoCommon, depth);
    // The radius projected to G-buffer pixels, clamped (a close-up would march the whole screen).
    float radiusPx = min(R * framePixelsPerUnit(depth), ssao.params.y / aoFramePixels); // the cap is in frame pixels
    // At least one of each (the parameter table's minimum): the loops below test at their end.
    int dirs = max(ssao.modes.x, 1), steps = max(aoAdaptiveSteps(ssao.aoCommon, ssao.modes.y, radiusPx), 1); // ao.adaptive
    // Steps of at least a pixel, the first one pixel out: never the pixel itself (no self-
    // occlusion lines), every step a new texel.
    float stepPx = max(radiusPx / float(steps + 1), 1.0);
    vec2 noise = vec2(0.0, 0.5);
    if (aoNoiseOn(ssao.aoCommon)) noise = aoNoise(ssao.aoCommon, gl_FragCoord.xy);

    float occlusion = 0.0;
    int d = 0;
    do { // do-while, not for: no masked pass after the last direction (ao_common.glsl, aoLoops)
        float phi = (float(d) + noise.x) / float(dirs) * TWO_PI;
        vec2 omega = vec2(cos(phi), sin(phi));
        float sinH = ssao.params.x; // the horizon starts at the tangent bias
        float occ = 0.0;
        int s = 0;
        do {
            vec2 offsetPx = round(omega * (1.0 + (float(s) + noise.y) * stepPx));
            vec2 uv = uv0 + offsetPx * frame.viewport.zw;
            vec4 S; // off the held area (the frame and its guard band): unseen, no occluder
            bool held = aoTapHeld(ssao.aoCommon, gPosition, uv, length(offsetPx), S);
            vec3 H = S.xyz - P;
            float r = length(H);
            float sinS = r > 0.0 ? dot(N, H) / r : -1.0; // elevation above the tangent plane
            // Off the frame or on the sky: no occluder. A select, not a branch per case (vbao.frag:
            // on llvmpipe the branches only cost); the same AO to the last bit.
            bool raises = held && S.w != 0.0 && sinS > sinH;
            float W = max(0.0, 1.0 - r / R); // Bavoil 2008 eq. 3: linear falloff
            float contribution = raises ? (sinS - sinH) * W : 0.0;
            occ += contribution;
            sinH = raises ? sinS : sinH;
            INSPECT_TAP(held && S.w != 0.0 ? S.xyz : P, uv,
                        !held        ? SSAO_TAP_OFFSCREEN
                        : S.w == 0.0 ? SSAO_TAP_SKY
                        : contribution > 0.0 ? SSAO_TAP_OCCLUDED : SSAO_TAP_OPEN,
                        contribution, d);
        } while (++s < steps);
        occlusion += occ;
    } while (++d < dirs);
    // Each direction's occlusion is at most 1 - bias; normalise so a fully closed pixel reads 0.
    float norm = float(dirs) * (1.0 - ssao.params.x);
    oAO = AO_RESULT(aoFinish(ssao.aoCommon, 1.0 - occlusion / norm));
    INSPECT_RESULT(true, P, N, occlusion, norm, R, oAO);
}
