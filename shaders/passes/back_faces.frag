#version 450 core
// The back-face layer (renderer/passes/back_face_pass.h): keeps fragments whose normal faces away
// from the eye and writes their linear depth; the depth test keeps the nearest of them.
#include "include/frame.glsl"
#include "include/alpha_mask.glsl"

in vec3 vViewPos;
in vec3 vViewNormal;
in vec2 vUv;

layout(location = 0) out float oBackDepth; // distance along -z, scene units

void main() {
    alphaMaskTest(vUv); // MASK draws: cut-outs are not surfaces
    if (dot(vViewNormal, frameViewVector(vViewPos)) > 0.0) discard; // faces the eye: the front layer's
    oBackDepth = -vViewPos.z;
}
