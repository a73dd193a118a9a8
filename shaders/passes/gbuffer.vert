#version 450 core
#include "include/frame.glsl"

layout(location = 0) in vec3 aPosition; // world space
layout(location = 1) in vec3 aNormal;   // world space
layout(location = 2) in vec2 aUv;       // MASK draws' texture coordinates (0 without them)

out vec3 vViewPos;
out vec3 vViewNormal;
out vec2 vUv;

void main() {
    vec4 vp = frame.view * vec4(aPosition, 1.0);
    vViewPos = vp.xyz;
    // view is a rigid transform (lookAt), so its inverse-transpose is mat3(view) itself.
    vViewNormal = mat3(frame.view) * aNormal;
    vUv = aUv;
    gl_Position = frame.proj * vp;
}
