#version 450 core
// The second depth layer (renderer/passes/second_layer_pass.h): keeps fragments facing the eye that
// lie more than the separation behind the first layer's surface at this pixel; the depth test keeps
// the nearest of them.
#include "include/bindings.h"
#include "include/frame.glsl"
#include "include/alpha_mask.glsl"

in vec3 vViewPos;
in vec3 vViewNormal;
in vec2 vUv;

layout(binding = SSAO_TEX_POSITION) uniform sampler2D gPosition; // the first layer
layout(location = SSAO_LOC_SECOND_LAYER_SEPARATION) uniform float uSeparation; // scene units

layout(location = 0) out float oInverseDepth; // 1 / distance along -z (1 / scene units)

void main() {
    alphaMaskTest(vUv); // MASK draws: cut-outs are not surfaces
    if (dot(vViewNormal, frameViewVector(vViewPos)) < 0.0) discard; // faces away: the back-face layer's
    vec4 first = texelFetch(gPosition, ivec2(gl_FragCoord.xy), 0);
    if (first.w == 0.0 || -vViewPos.z <= -first.z + uSeparation) discard; // the first layer, or too near it
    oInverseDepth = 1.0 / -vViewPos.z;
}
