#version 450 core
// Temporal accumulation of the denoised AO. Each frame's AO (new noise per frame) is blended with
// the history of the same surface point: the pixel's world position, projected through the
// previous frame's camera, finds where that point was. The history there is read as a bilinear
// footprint of its four texels, each kept only if the surface it recorded lies on this pixel's
// tangent plane within a tolerance measured in the pixel's own footprint (the width of one pixel
// at that depth): a test of the pixel's scale, so a far, detailed object keeps no other surface's
// history and no tap across a depth edge is mixed in. With no tap kept the pixel starts over
// (disocclusion). Running mean: frame k of a pixel weighs 1/k, up to `frames`, and up to
// `moving_frames` while the point moves on screen. The history is first brought into the range of
// this frame's AO around the pixel. Noise that is the same every frame leaves nothing to average:
// the history is not read.
// RESOLVE: copy the new history's AO into the AO target the rest of the graph reads.
#include "include/bindings.h"
#include "include/frame.glsl"

layout(binding = SSAO_TEX_AO) uniform sampler2D aoCurrent;
layout(binding = SSAO_TEX_LINEAR_DEPTH) uniform sampler2D gDepth;
layout(binding = SSAO_TEX_NORMAL) uniform sampler2D gNormal;
layout(binding = SSAO_TEX_HISTORY) uniform sampler2D history; // r: AO, g: linear depth, b: frames

layout(location = 0) uniform mat4 uPrevViewProj; // previous frame: world → clip
layout(location = 1) uniform mat4 uPrevView;     // previous frame: world → view
layout(location = 2) uniform mat4 uInvView;      // this frame: view → world
// x: 1 = drop all history, y: frames, z: tolerance (pixel footprints), w: 1 = the AO's noise is the
// same every frame (nothing to average: the history is not read)
layout(location = 3) uniform vec4 uParams;
// The previous frame's lens: x, y its inverse projection's [0][0] and [1][1], z: 1 = orthographic.
layout(location = 4) uniform vec4 uPrevLens;
layout(location = 5) uniform float uMovingFrames; // the running mean's length while the camera moves

in vec2 vUv;

#ifdef RESOLVE
layout(location = 0) out float oAO;
void main() {
    float ao = textureLod(history, vUv, 0.0).r;
    oAO = ao > 1.0 ? 1.0 : ao; // a running mean of ones may round past 1; a NaN stays visible
}
#else
layout(location = 0) out vec4 oHistory;

// The previous view's position of the history texel centred at uv whose linear depth is z.
vec3 previousViewPosition(vec2 uv, float z) {
    vec2 xy = (uv * 2.0 - 1.0) * uPrevLens.xy;
    return uPrevLens.z > 0.5 ? vec3(xy, -z) : vec3(xy, -1.0) * z;
}

// Catmull-Rom weights of the four texels around a sample at fraction t past the second.
vec4 catmullRom(float t) {
    float t2 = t * t, t3 = t2 * t;
    return vec4(-0.5 * t3 + t2 - 0.5 * t, 1.5 * t3 - 2.5 * t2 + 1.0, -1.5 * t3 + 2.0 * t2 + 0.5 * t, 0.5 * t3 - 0.5 * t2);
}

// The history of the point Q (previous view) on the plane of normal n, resampled over the 4x4
// texels around it (Catmull-Rom: a bilinear blend would blur the AO once per frame while the camera
// moves), each texel kept only on that plane; and the fewest frames among the kept ones. Frames 0
// when the kept texels carry too little of the weight.
vec2 reprojected(vec2 puv, vec3 Q, vec3 n) {
    vec2 size = vec2(textureSize(history, 0));
    vec2 p = puv * size - 0.5;
    vec2 base = floor(p), f = p - base;
    vec4 wx = catmullRom(f.x), wy = catmullRom(f.y);
    float pixel = 2.0 * uPrevLens.y / size.y * (uPrevLens.z > 0.5 ? 1.0 : -Q.z); // one pixel's width there
    float tolerance = uParams.z * pixel;
    float sum = 0.0, weights = 0.0, frames = 1e9;
    for (int k = 0; k < 16; ++k) {
        ivec2 o = ivec2(k & 3, k >> 2);
        ivec2 t = ivec2(base) + o - 1;
        float w = wx[o.x] * wy[o.y];
        if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, ivec2(size)))) continue;
        vec4 h = texelFetch(history, t, 0);
        if (!(h.g > 0.0)) continue; // sky then
        vec3 P = previousViewPosition((vec2(t) + 0.5) / size, h.g);
        if (abs(dot(n, P - Q)) > tolerance) continue; // another surface
        sum += w * h.r;
        weights += w;
        if (abs(w) > 0.01) frames = min(frames, h.b);
    }
    return weights > 0.5 ? vec2(clamp(sum / weights, 0.0, 1.0), frames) : vec2(0.0);
}

void main() {
    float ao = textureLod(aoCurrent, vUv, 0.0).r;
    float z = textureLod(gDepth, vUv, 0.0).r;
    if (!(z > 0.0)) { // sky: nothing to accumulate
        oHistory = vec4(ao, 0.0, 1.0, 0.0);
        return;
    }
    float frames = 1.0, result = ao;
    vec4 world = uInvView * vec4(frameViewPosition(vUv, z), 1.0);
    vec4 clip = uPrevViewProj * world;
    if (uParams.x < 0.5 && uParams.w < 0.5 && clip.w > 0.0) {
        vec2 puv = clip.xy / clip.w * 0.5 + 0.5;
        vec3 N = texelFetch(gNormal, ivec2(gl_FragCoord.xy), 0).xyz;
#ifdef NORMAL_UNORM
        N = N * 2.0 - 1.0;
#endif
        vec3 Q = (uPrevView * world).xyz;
        // A surface with no normal (degenerate triangles) is taken as facing the previous eye.
        vec3 n = dot(N, N) > 1e-12 ? normalize(mat3(uPrevView) * (mat3(uInvView) * N)) : normalize(-Q);
        vec2 h = reprojected(puv, Q, n);
        if (h.y > 0.0) {
            // This frame's AO around the pixel: the history is brought into its range (a point's AO
            // changes with the view; the last frames can only narrow this frame's noise, not replace it).
            float lo = ao, hi = ao;
            for (int k = 0; k < 9; ++k) {
                ivec2 q = clamp(ivec2(gl_FragCoord.xy) + ivec2(k % 3 - 1, k / 3 - 1), ivec2(0),
                                textureSize(aoCurrent, 0) - 1);
                if (!(texelFetch(gDepth, q, 0).r > 0.0)) continue;
                float a = texelFetch(aoCurrent, q, 0).r;
                lo = min(lo, a), hi = max(hi, a);
            }
            // Moving (the point was elsewhere on screen last frame): a shorter memory, so what the
            // view changed and what resampling blurred fade within a few frames.
            bool moving = any(greaterThan(abs(puv - vUv) * vec2(textureSize(history, 0)), vec2(0.01)));
            frames = min(h.y + 1.0, moving ? uMovingFrames : uParams.y);
            result = mix(clamp(h.x, lo, hi), ao, 1.0 / frames);
        }
    }
    oHistory = vec4(result, z, frames, 0.0);
}
#endif
