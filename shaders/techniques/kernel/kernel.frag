#version 450 core
// Kernel SSAO as the seeds describe it (000, 001, 003, 004), with every variant selectable
// through KernelConstants and every numerical trap guarded (research-accuracy.md §4).
#include "include/bindings.h"
#include "techniques/kernel/layout.h"
#include "include/frame.glsl"
#include "include/onb.glsl"
#include "include/ao_common.glsl"
#include "include/inspect.glsl"

layout(std140, binding = SSAO_UBO_AO) uniform KernelBlock { KernelConstants_ ssao; };
layout(binding = SSAO_TEX_POSITION) uniform sampler2D gPosition;
layout(binding = SSAO_TEX_NORMAL) uniform sampler2D gNormal;
layout(binding = SSAO_TEX_DEPTH) uniform sampler2D gDepth;
layout(binding = KERNEL_TEX_NOISE) uniform sampler2D texNoise;

in vec2 vUv;
layout(location = 0) out float oAO;

bool hasFlag(int f) { return (ssao.modes.w & f) != 0; }

// View-space position at uv; w = 0 where there is no geometry (sky).
vec4 viewPosition(vec2 uv) {
    if (hasFlag(KERNEL_FLAG_POS_FROM_DEPTH)) { // seeds 000 and 001: depth buffer -> distance -> ray
        float dist = frameLinearDepth(texture(gDepth, uv).r);
        return dist > 0.0 ? vec4(frameViewPosition(uv, dist), 1.0) : vec4(0.0);
    }
    return texture(gPosition, uv);
}

// Occlusion contributed by one view-space sample point S of the pixel at P.
float sampleOcclusion(vec3 P, vec3 S, float radius, int set) {
    float bias = ssao.params.x * radius; // a fraction of the radius: scales with the scene
    vec4 clip = frame.proj * vec4(S, 1.0);
    // Behind the eye (w <= 0) the divide flips the sample across the screen: no pixel to read
    // (orthographic: w = 1, every sample projects).
    if (!frameOrthographic() && clip.w <= 1e-5 * frame.clip.x) {
        INSPECT_TAP(S, vec2(0.0), SSAO_TAP_BEHIND_EYE, 0.0, set);
        return 0.0;
    }
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    bool offscreen = any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)));
    if (offscreen && !hasFlag(KERNEL_FLAG_OFFSCREEN_CLAMP)) { // unseen: count as open
        INSPECT_TAP(S, uv, SSAO_TAP_OFFSCREEN, 0.0, set);
        return 0.0;
    }
    // A sample that reads the pixel's own texel compares the surface with itself, displaced: on a
    // plane seen at an angle a sample above it lands behind the texel's point and reads as occluded
    // (acne at any radius under a pixel or two; bias 0). The surface cannot occlude itself: open
    // (kernel.own_texel = open; the seeds test it like any other sample).
    if (hasFlag(KERNEL_FLAG_OWN_TEXEL_OPEN) && !offscreen &&
        all(equal(floor(uv * frame.viewport.xy), floor(vUv * frame.viewport.xy)))) {
        INSPECT_TAP(S, uv, SSAO_TAP_OPEN, 0.0, set);
        return 0.0;
    }
    vec4 Q = viewPosition(uv); // texture clamp-to-edge does the seeds' clamping
    if (Q.w == 0.0) { // sky occludes nothing
        INSPECT_TAP(S, uv, SSAO_TAP_SKY, 0.0, set);
        return 0.0;
    }
    float sceneZ = Q.z;
    float dz = abs(P.z - sceneZ);

    float range = 1.0;
    if (ssao.modes.y == KERNEL_RANGE_SMOOTHSTEP) // seed 004, |dz| = 0 guarded
        range = smoothstep(0.0, 1.0, radius / max(dz, ssao.params.y * radius));
    else if (ssao.modes.y == KERNEL_RANGE_HARD)
        range = dz < radius ? 1.0 : 0.0; // seed 003

    bool occluded = ssao.modes.z == KERNEL_DEPTHTEST_SAMPLE ? sceneZ >= S.z + bias // seeds 000/004
                                                            : P.z + bias < sceneZ; // seed 003
    float occ = occluded ? range : 0.0;
    INSPECT_TAP(S, uv, occ > 0.0 ? SSAO_TAP_OCCLUDED : SSAO_TAP_OPEN, occ, set);
    return occ;
}

float accumulate(vec3 P, mat3 TBN, float radius, int first, int count, int set) {
    float occ = 0.0;
    int i = 0;
    if (count > 0) do { // do-while, not for: no masked pass after the last sample (ao_common.glsl, aoLoops)
        vec3 S = P + TBN * ssao.kernel[first + i].xyz * radius;
        occ += sampleOcclusion(P, S, radius, set);
    } while (++i < count);
    return occ;
}

void main() {
    vec4 P = viewPosition(vUv);
    AO_SKY_EARLY_OUT(P, vUv) // sky: unoccluded, no work spent (ao_common.glsl)
    vec3 N = aoNormal(ssao.aoCommon, gPosition, gNormal, vUv, P.xyz); // G-buffer or from depth

    // Temporal accumulation shifts the 4x4 tile by a texel pattern per frame (16 arrangements), so
    // successive frames rotate each pixel's kernel differently (frame index 0 otherwise).
    float k = frame.clip.w;
    vec2 shift = vec2(mod(k, 4.0), mod(floor(k / 4.0), 4.0)) * 0.25;
    vec3 r = hasFlag(KERNEL_FLAG_NOISE) ? texture(texNoise, vUv * ssao.noiseScale.xy + shift).xyz : vec3(1.0, 0.0, 0.0);
    mat3 TBN = tangentFrame(N, r);
    float radius = aoRadius(ssao.aoCommon, -P.z);

    int n = ssao.modes.x;
    float occ = accumulate(P.xyz, TBN, radius, 0, n, 0);
    float total = float(n);
    if (hasFlag(KERNEL_FLAG_SEPARABLE)) { // seed 003: second set in the y-z plane, N samples too
        occ += accumulate(P.xyz, TBN, radius, KERNEL_MAX_SAMPLES, n, 1);
        total *= 2.0;
    }
    oAO = AO_RESULT(aoFinish(ssao.aoCommon, 1.0 - occ / total));
    INSPECT_RESULT(true, P.xyz, N, occ, total, radius, oAO);
}
