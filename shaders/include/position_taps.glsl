// Reading positions at a tap: from the position pyramid when the constants enable it (AoCommon
// estimator.w = offset > 0; renderer/techniques/position_pyramid.h), else from the G-buffer itself.
// A tap d G-buffer pixels from the pixel reads level floor(log2(d) - offset) (SAO's
// "log2(ssR) - LOG_MAX_OFFSET"; XeGTAO's offset is 3.3): nearby taps stay exact, far taps touch
// few cache lines. Needs bindings.h.

layout(binding = SSAO_TEX_POSITION_MIPS) uniform sampler2D aoPositionMips;

vec4 aoTap(AoCommon_ c, sampler2D positions, vec2 uv, float offsetPx) {
    if (c.estimator.w > 0.0) {
        float top = float(textureQueryLevels(aoPositionMips) - 1);
        float lod = clamp(floor(log2(max(offsetPx, 1.0)) - c.estimator.w), 0.0, top);
        return textureLod(aoPositionMips, uv, lod);
    }
    return textureLod(positions, uv, 0.0);
}

// The guard band (gbuffer.guard_band_px > 0: AoCommon flags.w = 1; passes/guard_band_pass.h): the
// positions of the frame and a margin beyond each edge, rendered with the same pixel grid. A tap
// off the frame reads it there. False when the tap lies beyond what is held (the frame without a
// band, or beyond the band): the screen knows nothing there.
layout(binding = SSAO_TEX_POSITION_BAND) uniform sampler2D aoPositionBand;

bool aoTapHeld(AoCommon_ c, sampler2D positions, vec2 uv, float offsetPx, out vec4 S) {
    S = vec4(0.0);
    if (all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)))) {
        S = aoTap(c, positions, uv, offsetPx);
        return true;
    }
    if (c.flags.w == 0.0) return false;
    vec2 band = vec2(textureSize(aoPositionBand, 0));  // the frame plus g pixels on each side
    vec2 g = 0.5 * (band - frame.viewport.xy);
    vec2 uvBand = (uv * frame.viewport.xy + g) / band;
    if (any(lessThan(uvBand, vec2(0.0))) || any(greaterThan(uvBand, vec2(1.0)))) return false;
    S = textureLod(aoPositionBand, uvBand, 0.0);
    return true;
}
