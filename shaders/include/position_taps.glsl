// Reading positions at a tap: from the position pyramid when the constants enable it (AoCommon
// estimator.w = offset > 0; renderer/passes/position_pyramid_pass.h), else from the G-buffer itself.
// A tap d G-buffer pixels from the pixel reads level floor(log2(d) - offset) (SAO's
// "log2(ssR) - LOG_MAX_OFFSET"; XeGTAO's offset is 3.3): nearby taps stay exact, far taps touch
// few cache lines. Needs bindings.h.
//
// The optional inputs (pyramid, guard band, back-face layer) are compiled in only where the
// constants enable them: AO_PYRAMID, AO_BAND and AO_BACK_DEPTH are defined from the packed block
// itself (renderer/techniques/ao_pass.cpp, aoFeatureDefines), so a variant never disagrees with
// its constants. A branch on a uniform is not free on llvmpipe: compiled in and off, each input
// still costs every tap.

layout(binding = SSAO_TEX_POSITION_MIPS) uniform sampler2D aoPositionMips;

vec4 aoTap(AoCommon_ c, sampler2D positions, vec2 uv, float offsetPx) {
#ifdef AO_PYRAMID
    if (c.estimator.w > 0.0) {
        float top = float(textureQueryLevels(aoPositionMips) - 1);
        float lod = clamp(floor(log2(max(offsetPx, 1.0)) - c.estimator.w), 0.0, top);
        return textureLod(aoPositionMips, uv, lod);
    }
#endif
    return textureLod(positions, uv, 0.0);
}

// The guard band (gbuffer.guard_band_px > 0: AoCommon flags.w = 1; passes/guard_band_pass.h): the
// positions of the frame and a margin beyond each edge, rendered with the same pixel grid. A tap
// off the frame reads it there. False when the tap lies beyond what is held (the frame without a
// band, or beyond the band): the screen knows nothing there.
layout(binding = SSAO_TEX_POSITION_BAND) uniform sampler2D aoPositionBand;

bool aoTapHeld(AoCommon_ c, sampler2D positions, vec2 uv, float offsetPx, out vec4 S) {
    bool inside = all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
    // Read whether or not the tap is on the frame (off it, the clamped edge texel, discarded):
    // a read under a divergent branch costs more on llvmpipe than the read itself.
    vec4 T = aoTap(c, positions, uv, offsetPx);
    S = inside ? T : vec4(0.0);
#ifdef AO_BAND
    if (!inside && (int(c.flags.w) & SSAO_AO_BAND) != 0) {
        vec2 band = vec2(textureSize(aoPositionBand, 0));  // the frame plus g pixels on each side
        vec2 g = 0.5 * (band - frame.viewport.xy);
        vec2 uvBand = (uv * frame.viewport.xy + g) / band;
        if (any(lessThan(uvBand, vec2(0.0))) || any(greaterThan(uvBand, vec2(1.0)))) return false;
        S = textureLod(aoPositionBand, uvBand, 0.0);
        return true;
    }
#endif
    return inside;
}

// The back-face layer (gbuffer.back_faces: passes/back_face_pass.h): the nearest surface facing away
// from the camera along a pixel's ray, as a linear depth. For a tap S (view space) at uv, how far
// behind S along the view ray its solid reaches: where the layer holds a back face behind S, that
// depth (the true thickness) but never less than `assumed` (the technique's thickness); else
// `assumed`. Never less: with the true thickness of a thin wall every tap hides only a sliver of
// sectors and the rays between the taps pass, so the error against the reference grows; the
// assumed thickness is what fills the gaps between sparse samples (vbao.true_thickness asks for the
// true one; docs/bench/layers.md measures both). Taps off the frame have no back layer.
layout(binding = SSAO_TEX_BACK_DEPTH) uniform sampler2D aoBackDepth;

// The second depth layer at uv (gbuffer.second_layer, passes/second_layer_pass.h): the nearest
// surface facing the camera behind the one the G-buffer shows there, w = 1, or w = 0 where there is
// none, the layer is off or uv is off the frame (the layer covers the frame only).
#ifdef AO_SECOND_LAYER
layout(binding = SSAO_TEX_SECOND_LAYER) uniform sampler2D aoSecondLayer;
#endif
vec4 aoSecondLayerAt(vec2 uv) {
#ifndef AO_SECOND_LAYER
    return vec4(0.0);
#else
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return vec4(0.0);
    float inverseDepth = textureLod(aoSecondLayer, uv, 0.0).r; // 1 / scene units, 0 = none
    return inverseDepth > 0.0 ? vec4(frameViewPosition(uv, 1.0 / inverseDepth), 1.0) : vec4(0.0);
#endif
}

// `exact` (vbao.true_thickness): the far side's depth even where it is less than `assumed`.
float aoBackGapOf(AoCommon_ c, vec2 uv, vec3 S, float assumed, bool exact) {
#ifndef AO_BACK_DEPTH
    return assumed;
#else
    if ((int(c.flags.w) & SSAO_AO_BACK_DEPTH) == 0) return assumed;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return assumed;
    float back = textureLod(aoBackDepth, uv, 0.0).r, front = -S.z;
    if (!(back > front)) return assumed; // no back face behind it (an open surface, or none at all)
    float gap = frame.camera.x != 0.0 ? back - front : length(S) * (back / front - 1.0); // along the view ray
    return exact ? gap : max(gap, assumed);
#endif
}

float aoBackGap(AoCommon_ c, vec2 uv, vec3 S, float assumed) { return aoBackGapOf(c, uv, S, assumed, false); }
