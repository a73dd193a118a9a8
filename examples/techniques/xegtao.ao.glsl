/*ssaolab
interface = 1;
label = "GTAO (example)";
summary = "Horizon-based, cosine-weighted visibility per slice (Jimenez et al. 2016), as the built-in gtao computes it.";
uniform int slices < ui_type = "slider"; ui_min = 1; ui_max = 16; ui_label = "Slices";
    ui_tooltip = "Directions around the view vector per pixel (the built-in's high quality: 3)."; > = 3;
uniform int steps < ui_type = "slider"; ui_min = 1; ui_max = 32; ui_label = "Steps"; ui_units = " per side";
    ui_tooltip = "Depth samples along each side of a slice (the built-in's high quality: 3)."; > = 3;
uniform float radius_multiplier < ui_type = "slider"; ui_min = 0.1; ui_max = 5.0; ui_step = 0.01;
    ui_label = "Radius multiplier"; ui_units = " x R"; ui_tooltip = "Search radius = R x this (XeGTAO 1.457)."; > = 1.457;
uniform float falloff_range < ui_type = "slider"; ui_min = 0.01; ui_max = 1.0; ui_step = 0.01;
    ui_label = "Falloff range"; ui_units = " x radius";
    ui_tooltip = "Occluders fade to nothing over this last fraction of the search radius (XeGTAO 0.615)."; > = 0.615;
uniform float distribution_power < ui_type = "slider"; ui_min = 0.5; ui_max = 4.0; ui_step = 0.05;
    ui_label = "Step distribution"; ui_tooltip = "Step k of n lies at (k/n)^p of the radius (XeGTAO 2)."; > = 2.0;
uniform float thin_compensation < ui_type = "slider"; ui_min = 0.0; ui_max = 0.7; ui_step = 0.01;
    ui_label = "Thin occluders"; ui_tooltip = "Depth differences count (1 + t) times in the falloff (XeGTAO)."; > = 0.0;
*/

// GTAO (Jimenez, Wu, Pesce, Jarabo 2016) laid out like Intel XeGTAO's MainPass: the same
// computation as shaders/techniques/gtao/gtao.frag, written against the user interface
// (shaders/include/user_interface.glsl). With the values above and the technique's noise given
// to the pass as gtao.noise, it gives the built-in gtao's ao.raw at gtao.quality = high.

const int MAX_STEPS = 32;     // the steps parameter's maximum
const float MIN_FIRST_STEP_PX = 1.3; // the first step lands at least this far: never the pixel itself

float ssaoUserAo() {
    vec2 uv0 = ssaoUv();
    vec3 P = ssaoPosition();
    vec3 N = ssaoNormal();
    vec3 V = ssaoViewVector();
    float depth = -P.z;

    float R = ssaoRadius() * radius_multiplier; // the search radius (scene units)
    float radiusPx = R * ssaoPixelsPerUnit(depth);
    // Weight = saturate(d * mul + add): 1 up to R (1 - range), 0 at R (XeGTAO's falloff).
    float falloffMul = (-1.0 / falloff_range) / R, falloffAdd = (1.0 - falloff_range) / falloff_range + 1.0;
    float minS = MIN_FIRST_STEP_PX / max(radiusPx, 1e-6);
    int nSlices = max(slices, 1), nSteps = max(ssaoAdaptiveSteps(steps, radiusPx), 1);
    vec2 noise = ssaoNoise();

    float stepS[MAX_STEPS]; // each step's distance as a fraction of R, the same in every slice
    int k = 0;
    do { stepS[k] = pow((float(k) + noise.y) / float(nSteps), distribution_power) + minS; } while (++k < nSteps);
    float visibility = 0.0, openSum = 0.0;
    int slice = 0;
    do { // do-whiles: no masked pass after the last iteration on llvmpipe (ao_common.glsl aoLoops)
        AoSlice sl = aoSlice((float(slice) + noise.x) / float(nSlices) * PI, V, N);
        vec2 omega = sl.omega;
        float projNLen = sl.projNLen, cosNorm = sl.cosN, n = sl.n;
        // With no occluder the horizons are the tangent plane: cos(n -+ pi/2) = +-sin n.
        float sinN = sign(n) * sqrt(max(1.0 - cosNorm * cosNorm, 0.0));
        float lowCos0 = -sinN, lowCos1 = sinN;
        float hCos0 = lowCos0, hCos1 = lowCos1;
        int step = 0;
        do {
            float s = stepS[step];
            vec2 offsetUv = round(s * radiusPx * omega) * ssaoFrameSize().zw; // texel centres
            for (int side = 0; side < 2; ++side) {
                vec2 uv = uv0 + (side == 0 ? offsetUv : -offsetUv);
                vec4 S;
                bool held = ssaoTapAt(uv, s * radiusPx, S);
                vec3 delta = S.xyz - P;
                float dist = length(delta);
                bool counts = held && S.w != 0.0 && dist > 0.0;
                vec3 inSlice = aoSliceDelta(sl, delta);
                float shc = dot(inSlice, V) / max(length(inSlice), 1e-30);
                float falloffBase = length(vec3(delta.xy, delta.z * (1.0 + thin_compensation)));
                float w = clamp(falloffBase * falloffMul + falloffAdd, 0.0, 1.0);
                float low = side == 0 ? lowCos0 : lowCos1;
                shc = counts ? mix(low, shc, w) : low;
                bool raises = side == 0 ? shc > hCos0 : shc > hCos1;
                if (side == 0) hCos0 = max(hCos0, shc);
                else hCos1 = max(hCos1, shc);
                ssaoRecordTap(held && S.w != 0.0 ? S.xyz : P, uv,
                              !held         ? SSAO_TAP_OFFSCREEN
                              : S.w == 0.0  ? SSAO_TAP_SKY
                              : !counts     ? SSAO_TAP_OPEN
                              : raises && w > 0.0 ? SSAO_TAP_OCCLUDED : SSAO_TAP_OPEN,
                              counts ? w : 0.0, slice);
            }
        } while (++step < nSteps);
        // Horizon angles from V, kept within the hemisphere around the normal; the paper's eq. 10.
        float h0 = -safeAcos(hCos1), h1 = safeAcos(hCos0);
        h0 = n + clamp(h0 - n, -HALF_PI, HALF_PI);
        h1 = n + clamp(h1 - n, -HALF_PI, HALF_PI);
        float iarc0 = (cosNorm + 2.0 * h0 * sinN - cos(2.0 * h0 - n)) * 0.25;
        float iarc1 = (cosNorm + 2.0 * h1 * sinN - cos(2.0 * h1 - n)) * 0.25;
        visibility += projNLen * (iarc0 + iarc1);
        openSum += projNLen * (cosNorm + n * sinN); // both horizons on the tangent plane
    } while (++slice < nSlices);
    visibility = aoSliceRatio(visibility, openSum);
    ssaoInspectSums(1.0 - visibility, float(nSlices));
    return visibility;
}
