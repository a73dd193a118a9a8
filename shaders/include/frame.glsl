// Per-frame constants shared by every pass (layout declared once in bindings.h).
#include "include/bindings.h"

layout(std140, binding = SSAO_UBO_FRAME) uniform FrameBlock { FrameConstants_ frame; };

// Projection-generic helpers: every pass that maps between pixels, depths and view space goes
// through these, so an orthographic camera and reversed depth (scene/camera.h) work everywhere.
bool frameOrthographic() { return frame.camera.x != 0.0; }

// What screen-sized lengths scale with at view distance `depth`: depth under perspective (a
// pixel spans depth / (proj[1][1] H / 2) units), 1 under orthographic (every pixel is as wide).
float frameDepthScale(float depth) { return frameOrthographic() ? 1.0 : depth; }

// Pixels a scene-unit length spans at view distance `depth` (scene units, positive).
float framePixelsPerUnit(float depth) {
    return frame.proj[1][1] * 0.5 * frame.viewport.y / frameDepthScale(depth);
}

// View-space position of the pixel at uv whose linear depth (distance along -z) is z. Perspective
// (seed 001): the ray through the pixel at unit distance, times z; orthographic: a parallel ray.
vec3 frameViewPosition(vec2 uv, float z) {
    vec2 ndc = uv * 2.0 - 1.0;
    vec2 xy = vec2(ndc.x * frame.invProj[0][0], ndc.y * frame.invProj[1][1]);
    return frameOrthographic() ? vec3(xy, -z) : vec3(xy, -1.0) * z;
}

// Linear depth from the hardware depth d in [0, 1]; 0 for sky (the clear value: 1, or 0 reversed).
// z_ndc = 2d - 1 (standard) or d (reversed, GL_ZERO_TO_ONE). Perspective: z_ndc (-z_v) = P22 z_v +
// P32, so z = P32 / (z_ndc + P22) (seed 000's 2nf / (f + n - z_ndc (f - n)) for the standard
// matrix); orthographic: z_ndc = P22 z_v + P32.
float frameLinearDepth(float d) {
    bool reversed = frame.camera.y != 0.0;
    if (reversed ? d <= 0.0 : d >= 1.0) return 0.0;
    float zn = reversed ? d : d * 2.0 - 1.0;
    float p22 = frame.proj[2][2], p32 = frame.proj[3][2];
    return frameOrthographic() ? (p32 - zn) / p22 : p32 / (zn + p22);
}

// Unit vector from the view-space point P toward the eye: -P normalised, or +z for parallel rays.
vec3 frameViewVector(vec3 P) { return frameOrthographic() ? vec3(0.0, 0.0, 1.0) : normalize(-P); }
