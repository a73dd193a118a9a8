#version 450 core
// Scalable Ambient Obscurance (McGuire, Mara, Luebke 2012) with the Alchemy AO estimator
// (McGuire et al. 2011):  A = max(0, 1 - (2σ/N) Σ f(v) max(0, v·n - β) / (v·v + ε))
// over N taps on a spiral, f = (1 - v·v)³ the paper's recommended falloff. Every length is in
// units of the radius R (v = (Q - P) / R), so β and ε mean the same at any scene scale (the
// paper's constants assume R ≈ 1 world unit). The contrast k of the paper is ao.power.
#include "include/bindings.h"
#include "techniques/sao/layout.h"
#include "include/frame.glsl"
#include "include/ao_common.glsl"
#include "include/noise.glsl"
#include "include/position_taps.glsl"
#include "include/inspect.glsl"

layout(std140, binding = SSAO_UBO_AO) uniform SaoBlock { SaoConstants_ ssao; };
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
    float radiusPx = R * framePixelsPerUnit(depth);
    float spin = aoNoiseOn(ssao.aoCommon) ? aoNoise(ssao.aoCommon, gl_FragCoord.xy).x * TWO_PI : 0.0;
    int n = aoAdaptiveSamples(ssao.aoCommon, ssao.modes.x, radiusPx); // ao.adaptive: fewer where the disc is small
    float occlusion = 0.0;
    int i = 0;
    if (n > 0) do { // do-while, not for: no masked pass after the last tap (ao_common.glsl, aoLoops)
        float alpha = (float(i) + 0.5) / float(n);
        float angle = alpha * ssao.params.x * TWO_PI + spin;
        vec2 uv = uv0 + round(alpha * radiusPx * vec2(cos(angle), sin(angle))) * frame.viewport.zw;
        vec4 Q; // off the held area (the frame and its guard band): unseen, no occluder
        bool held = aoTapHeld(ssao.aoCommon, gPosition, uv, alpha * radiusPx, Q);
        vec3 v = (Q.xyz - P) / R;
        float vv = dot(v, v), vn = dot(v, N);
        float f = max(1.0 - vv, 0.0);
        // ε keeps taps at the pixel itself (v = 0) finite and stops crevices over-darkening.
        float term = f * f * f * max(vn - ssao.params.z, 0.0) / (vv + ssao.params.w) * ssao.params.y;
        // Off the frame or on the sky: no occluder. A select, not a branch per case (vbao.frag:
        // on llvmpipe the branches only cost); the same AO to the last bit.
        term = held && Q.w != 0.0 ? term : 0.0;
        occlusion += term;
        INSPECT_TAP(held && Q.w != 0.0 ? Q.xyz : P, uv,
                    !held        ? SSAO_TAP_OFFSCREEN
                    : Q.w == 0.0 ? SSAO_TAP_SKY
                    : term > 0.0 ? SSAO_TAP_OCCLUDED : SSAO_TAP_OPEN,
                    term, 0);
    } while (++i < n);
    occlusion *= float(ssao.modes.x) / float(n); // params.y holds 2 sigma / modes.x (pack.cpp)
    oAO = AO_RESULT(aoFinish(ssao.aoCommon, 1.0 - occlusion));
    INSPECT_RESULT(true, P, N, occlusion, 1.0, R, oAO);
}
