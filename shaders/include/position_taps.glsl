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
