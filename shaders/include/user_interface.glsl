// The input interface of a user technique, version 1 (`interface = 1;` in a NAME.ao.glsl header;
// renderer/techniques/user/user_header.h). This file is the reference a technique's author reads.
//
// A user file is a parameter header followed by a GLSL 4.50 body that defines
//
//     float ssaoUserAo()
//
// which returns the visibility of the pixel ssaoUv() (1 = open, 0 = fully occluded). The
// interface's main() below finds the pixel's position, skips sky pixels, calls ssaoUserAo(),
// clamps its result to [0, 1], applies the shared contrast (ao.power) and writes ao.raw as every
// built-in technique does. The body's parameters are globals named as in its header (a float a
// float; an int, an enum or a bool an int: a bool is 0 or 1); an enum's items are #defines
// NAME_ITEM (user_header.h). The body may declare its own functions, constants and globals; it
// may not #include (everything it can read is here). The interface's names are camelCase (ssao...,
// ao..., frame..., gPosition, gNormal), so a parameter's lowercase name never meets them; the
// blocks `frame` and `ssao` are reserved (user_source.h). The body should not declare names that
// begin with ssao or ao itself. What the files below hold beyond the functions promised here is
// not part of the interface and may change.
//
// Units: view space is right-handed, the camera looks down -z, lengths in scene units. A uv is
// [0,1]^2 over the frame, (0,0) at the bottom left; a linear depth is the distance along -z
// (positive). A "pixel" in a radius or an offset is a G-buffer pixel.
//
// The file is assembled after bindings.h, techniques/user/layout.h (the block `ssao`), frame.glsl,
// onb.glsl (tangentFrame), ao_common.glsl, noise.glsl, position_taps.glsl, slice.glsl (AoSlice,
// aoSlice, aoSliceDelta, aoSliceRatio, safeAcos, PI, HALF_PI) and inspect.glsl; the functions of
// those files that a built-in uses may be called as well, but only the ones below are promised.

layout(std140, binding = SSAO_UBO_AO) uniform UserBlock { UserConstants_ ssao; };
layout(binding = SSAO_TEX_POSITION) uniform sampler2D gPosition;
layout(binding = SSAO_TEX_NORMAL) uniform sampler2D gNormal;

in vec2 vUv;
layout(location = 0) out float oAO;

// Set by main() before it calls ssaoUserAo() (initialised: Mesa warns of globals read in functions).
vec2 ssaoIn_uv = vec2(0.5);
vec3 ssaoIn_position = vec3(0.0, 0.0, -1.0), ssaoIn_normal = vec3(0.0, 0.0, 1.0);
float ssaoIn_radius = 1.0;
// What the sample inspector shows as the pixel's sums (ssaoInspectSums); < 0: 1 - visibility over 1.
float ssaoIn_occlusion = -1.0, ssaoIn_normaliser = 1.0;

// ---- The pixel ----------------------------------------------------------------------------

// The uv of the G-buffer texel this AO pixel stands for, at that texel's centre (at half or
// quarter AO resolution, the texel at the pixel's lower left: ao_common.glsl aoPixelUv).
vec2 ssaoUv() { return ssaoIn_uv; }

// The AO pixel being computed, in whole pixels of the AO target from its lower left.
ivec2 ssaoPixel() { return ivec2(gl_FragCoord.xy); }

// The AO target's width, height, 1/width, 1/height (pixels).
vec4 ssaoTargetSize() { return ssao.aoCommon.target; }

// The G-buffer's width, height, 1/width, 1/height (pixels): a step of one pixel in uv is .zw.
vec4 ssaoFrameSize() { return frame.viewport; }

// The pixel's view-space position (a geometry pixel: sky pixels never reach ssaoUserAo).
vec3 ssaoPosition() { return ssaoIn_position; }

// The pixel's unit view-space normal, facing the camera: the G-buffer's, or reconstructed from the
// positions where ao.normals = depth (ao_common.glsl aoNormal).
vec3 ssaoNormal() { return ssaoIn_normal; }

// The unit vector from the pixel toward the eye (+z under an orthographic camera).
vec3 ssaoViewVector() { return frameViewVector(ssaoIn_position); }

// The world radius R at this pixel (scene units): ao.radius, or in screen mode the radius in
// pixels converted at the pixel's depth (ao_common.glsl aoRadius).
float ssaoRadius() { return ssaoIn_radius; }

// R in G-buffer pixels at the pixel's depth.
float ssaoRadiusPixels() { return ssaoIn_radius * framePixelsPerUnit(-ssaoIn_position.z); }

// ---- The G-buffer at any uv ---------------------------------------------------------------

// The view-space position at uv: xyz, w = 1 on geometry, w = 0 (and xyz = 0) on sky. A uv off
// the frame reads the nearest edge texel (clamp to edge), as the seeds' kernel does.
vec4 ssaoPositionAt(vec2 uv) { return textureLod(gPosition, uv, 0.0); }

// The view-space position a tap `offsetPx` pixels from the pixel reads at uv, with what the
// settings hold beyond the frame: true and S where something is held there (the frame, and the
// guard band where gbuffer.guard_band_px > 0), false (S = 0) where nothing is (position_taps.glsl
// aoTapHeld). S.w = 0 on sky.
bool ssaoTapAt(vec2 uv, float offsetPx, out vec4 S) { return aoTapHeld(ssao.aoCommon, gPosition, uv, offsetPx, S); }

// Linear depth at uv (positive), 0 on sky; off the frame the edge texel's.
float ssaoLinearDepthAt(vec2 uv) {
    vec4 S = ssaoPositionAt(uv);
    return S.w != 0.0 ? -S.z : 0.0;
}

// How far behind the view-space point S (at uv) its solid reaches along the view ray: the
// back-face layer's depth where gbuffer.back_faces is on and it holds a back face behind S, never
// less than `assumed`; `assumed` otherwise (position_taps.glsl aoBackGap).
float ssaoBackGap(vec2 uv, vec3 S, float assumed) { return aoBackGap(ssao.aoCommon, uv, S, assumed); }

// The second depth layer at uv, where gbuffer.second_layer is on: the view-space point of the
// nearest surface facing the camera behind the one the G-buffer shows there, w = 1; w = 0 where
// there is none, the layer is off or uv is off the frame (position_taps.glsl aoSecondLayerAt).
vec4 ssaoSecondLayerAt(vec2 uv) { return aoSecondLayerAt(uv); }

// ---- Projection (perspective or orthographic, standard or reversed depth) ------------------

// Whether the camera is orthographic (parallel rays).
bool ssaoOrthographic() { return frameOrthographic(); }

// Whether the view-space point S lies behind the eye (or on its plane), where projecting it would
// flip it across the screen; never under an orthographic camera.
bool ssaoBehindEye(vec3 S) { return !frameOrthographic() && (frame.proj * vec4(S, 1.0)).w <= 1e-5 * frame.clip.x; }

// The uv the view-space point S projects to (may lie off [0,1]; meaningless behind the eye).
vec2 ssaoProject(vec3 S) {
    vec4 clip = frame.proj * vec4(S, 1.0);
    return clip.xy / clip.w * 0.5 + 0.5;
}

// The view-space point at uv whose linear depth is `depth` (frame.glsl frameViewPosition).
vec3 ssaoUnproject(vec2 uv, float depth) { return frameViewPosition(uv, depth); }

// Pixels a scene-unit length spans at linear depth `depth`.
float ssaoPixelsPerUnit(float depth) { return framePixelsPerUnit(depth); }

// ---- Noise and sample counts --------------------------------------------------------------

// Whether the technique's noise is on (a kind other than none).
bool ssaoNoiseOn() { return aoNoiseOn(ssao.aoCommon); }

// Two values in [0,1) for this pixel, of the noise kind the settings choose for the technique
// (IGN, R2, blue noise, a 4x4 tile; moving with the temporal frame index), exactly as the
// built-ins get it (noise.glsl aoNoise); (0.5, 0.5) for none.
vec2 ssaoNoise() { return ssaoNoiseOn() ? aoNoise(ssao.aoCommon, gl_FragCoord.xy) : vec2(0.5); }

// The temporal frame index (0 without temporal accumulation).
float ssaoFrameIndex() { return frame.clip.w; }

// `count` steps or samples as ao.adaptive reduces them for a pixel whose radius spans `radiusPx`
// pixels (include/adaptive.h); `count` without ao.adaptive.
int ssaoAdaptiveSteps(int count, float radiusPx) { return aoAdaptiveSteps(ssao.aoCommon, count, radiusPx); }
int ssaoAdaptiveSamples(int count, float radiusPx) { return aoAdaptiveSamples(ssao.aoCommon, count, radiusPx); }

// ---- The sample inspector -----------------------------------------------------------------

// Records one tap for the sample inspector: the view-space point S, the uv it read, its state
// (SSAO_TAP_OPEN, _OCCLUDED, _BEHIND_EYE, _OFFSCREEN, _SKY, optionally OR SSAO_TAP_BACK_LAYER),
// the occlusion it contributed and the set it belongs to (a slice, a ring; 0 if one). Compiled
// to nothing outside the inspector's variant (inspect.glsl).
void ssaoRecordTap(vec3 S, vec2 uv, int state, float contribution, int set) {
    INSPECT_TAP(S, uv, state, contribution, set);
}

// The occlusion sum and its normaliser the inspector shows for the pixel (default: 1 - the
// visibility returned, over 1).
void ssaoInspectSums(float occlusion, float normaliser) {
    ssaoIn_occlusion = occlusion;
    ssaoIn_normaliser = normaliser;
}

// ---- The pass -----------------------------------------------------------------------------

float ssaoUserAo(); // the body's entry point

void main() {
    ssaoIn_uv = aoPixelUv(vUv);
    vec4 P4 = texture(gPosition, ssaoIn_uv);
    AO_SKY_EARLY_OUT(P4, ssaoIn_uv) // sky: unoccluded, no work spent (ao_common.glsl)
    ssaoIn_position = P4.xyz;
    ssaoIn_normal = aoNormal(ssao.aoCommon, gPosition, gNormal, ssaoIn_uv, ssaoIn_position);
    ssaoIn_radius = aoRadius(ssao.aoCommon, -ssaoIn_position.z);
    float visibility = clamp(ssaoUserAo(), 0.0, 1.0);
    oAO = AO_RESULT(aoFinish(ssao.aoCommon, visibility));
    float occ = ssaoIn_occlusion >= 0.0 ? ssaoIn_occlusion : 1.0 - visibility;
    INSPECT_RESULT(true, ssaoIn_position, ssaoIn_normal, occ, ssaoIn_normaliser, ssaoIn_radius, oAO);
}
