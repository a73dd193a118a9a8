#version 450 core
// Seed 004's lighting: ambient * albedo * AO plus one Blinn–Phong point light with linear 0.7 /
// quadratic 0.9 attenuation — distances measured in scene radii so mm and m scenes look alike.
#include "include/bindings.h"
#include "include/frame.glsl"
#include "include/joint_upsample.glsl"

layout(binding = SSAO_TEX_POSITION) uniform sampler2D gPosition;
layout(binding = SSAO_TEX_NORMAL) uniform sampler2D gNormal;
layout(binding = SSAO_TEX_ALBEDO) uniform sampler2D gAlbedo;
layout(binding = SSAO_TEX_AO) uniform sampler2D aoIn; // ao.denoised, or with FUSED_UPSAMPLE the reduced AO
#ifdef FUSED_UPSAMPLE
// The joint upsample done here, per pixel, when nothing shows or judges ao.denoised itself
// (passes/composite_pass.h): one full-resolution pass fewer.
layout(std140, binding = SSAO_UBO_DENOISE) uniform DenoiseBlock { DenoiseConstants_ denoise; };
layout(binding = SSAO_TEX_LINEAR_DEPTH) uniform sampler2D gDepth;
#endif

layout(location = 0) uniform vec2 uAmbientLight; // x: ambient strength, y: light intensity
layout(location = 1) uniform float uUseAo;       // 1: apply AO, 0: AO off (comparison)

in vec2 vUv;
layout(location = 0) out vec4 oColor;

void main() {
    vec4 P = texture(gPosition, vUv);
    if (P.w == 0.0) { // sky gradient
        oColor = vec4(mix(vec3(0.75, 0.82, 0.9), vec3(0.45, 0.6, 0.8), vUv.y), 1.0);
        return;
    }
    vec3 N = texture(gNormal, vUv).xyz;
#ifdef NORMAL_UNORM
    N = N * 2.0 - 1.0;
#endif
    N = normalize(N);
    vec3 albedo = texture(gAlbedo, vUv).rgb;
    float ao = 1.0; // AO off: no AO texture is bound
#ifdef FUSED_UPSAMPLE
    if (uUseAo > 0.5) ao = jointUpsample(aoIn, gDepth, ivec2(gl_FragCoord.xy), denoise.taps.w);
#else
    if (uUseAo > 0.5) ao = texture(aoIn, vUv).r;
#endif

    float R = max(frame.clip.z, 1e-6);
    vec3 lightPos = vec3(-0.6, 0.9, 0.3) * R; // view space: above-left of the camera
    vec3 L = lightPos - P.xyz;
    float d = length(L) / R;
    L = normalize(L);
    vec3 V = frameViewVector(P.xyz);
    vec3 H = normalize(L + V);
    float att = 1.0 / (1.0 + 0.7 * d + 0.9 * d * d);
    vec3 color = uAmbientLight.x * albedo * ao;
    color += uAmbientLight.y * att * (max(dot(N, L), 0.0) * albedo + 0.25 * pow(max(dot(N, H), 0.0), 32.0));
    oColor = vec4(pow(clamp(color, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0); // display gamma
}
