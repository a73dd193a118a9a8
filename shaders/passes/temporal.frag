#version 450 core
// Temporal accumulation of the denoised AO. Each frame's AO (new noise per frame) is blended with
// the history of the same surface point: the pixel's world position, projected through the
// previous frame's camera, finds where that point was; the history there is kept only if the
// surface it recorded lies at the depth the point had then (else it was something else:
// disocclusion, start over). Running mean: frame k of a pixel weighs 1/k, up to `frames`.
// RESOLVE: copy the new history's AO into the AO target the rest of the graph reads.
#include "include/bindings.h"
#include "include/frame.glsl"

layout(binding = SSAO_TEX_AO) uniform sampler2D aoCurrent;
layout(binding = SSAO_TEX_LINEAR_DEPTH) uniform sampler2D gDepth;
layout(binding = SSAO_TEX_HISTORY) uniform sampler2D history; // r: AO, g: linear depth, b: frames

layout(location = 0) uniform mat4 uPrevViewProj; // previous frame: world → clip
layout(location = 1) uniform mat4 uPrevView;     // previous frame: world → view
layout(location = 2) uniform mat4 uInvView;      // this frame: view → world
layout(location = 3) uniform vec4 uParams;       // x: 1 = drop all history, y: frames, z: depth tolerance

in vec2 vUv;

#ifdef RESOLVE
layout(location = 0) out float oAO;
void main() {
    float ao = textureLod(history, vUv, 0.0).r;
    oAO = ao > 1.0 ? 1.0 : ao; // a running mean of ones may round past 1; a NaN stays visible
}
#else
layout(location = 0) out vec4 oHistory;
void main() {
    float ao = textureLod(aoCurrent, vUv, 0.0).r;
    float z = textureLod(gDepth, vUv, 0.0).r;
    if (!(z > 0.0)) { // sky: nothing to accumulate
        oHistory = vec4(ao, 0.0, 1.0, 0.0);
        return;
    }
    vec3 view = frameViewPosition(vUv, z);
    vec4 world = uInvView * vec4(view, 1.0);
    float frames = 1.0, result = ao;
    vec4 clip = uPrevViewProj * world;
    if (uParams.x < 0.5 && clip.w > 0.0) {
        vec2 puv = clip.xy / clip.w * 0.5 + 0.5;
        if (all(greaterThanEqual(puv, vec2(0.0))) && all(lessThanEqual(puv, vec2(1.0)))) {
            vec4 h = textureLod(history, puv, 0.0);
            float expected = -(uPrevView * world).z; // the point's depth in the previous view
            if (h.g > 0.0 && abs(h.g - expected) <= uParams.z * expected) {
                frames = min(h.b + 1.0, uParams.y);
                result = mix(h.r, ao, 1.0 / frames);
            }
        }
    }
    oHistory = vec4(result, z, frames, 0.0);
}
#endif
