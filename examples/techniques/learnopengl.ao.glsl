/*ssaolab
interface = 1;
label = "LearnOpenGL kernel (example)";
summary = "The seeds' normal-oriented hemisphere kernel (LearnOpenGL SSAO), as the built-in kernel technique computes it at the learnopengl preset.";
uniform int samples < ui_type = "slider"; ui_min = 1; ui_max = 256; ui_label = "Samples";
    ui_tooltip = "Points of the hemisphere kernel (LearnOpenGL: 64)."; > = 64;
uniform float bias < ui_type = "slider"; ui_min = 0.0; ui_max = 0.5; ui_step = 0.005; ui_label = "Bias";
    ui_units = " x R"; ui_tooltip = "Depth bias as a fraction of the radius (LearnOpenGL: 0.025 at R = 0.5)."; > = 0.05;
uniform bool rotate < ui_label = "Rotation noise";
    ui_tooltip = "Rotate the kernel per pixel by a 4x4 tile of random vectors (LearnOpenGL's noise texture)."; > = true;
*/

// LearnOpenGL's SSAO (the seeds 000/004): a hemisphere of sample points around the normal, rotated
// per pixel by a 4x4 tile, each point occluded where the surface seen through it lies in front of
// it, weighted by a smoothstep range check. The same computation as the built-in kernel technique
// (shaders/techniques/kernel/kernel.frag) at the learnopengl preset: hemisphere, not separable,
// bias as a fraction of R, smoothstep range check, depth test at the sample, clamp-to-edge reads,
// the pixel's own texel tested like any other, positions from the G-buffer, seed 0.
//
// The built-in makes its kernel and its 4x4 tile on the CPU with a SplitMix64 generator
// (renderer/techniques/kernel/sampling.cpp). GLSL 4.50 has no 64-bit integers without an
// extension, so the generator is emulated here on uvec2 (low, high words); its state after k draws
// is seed * G + C + k * G, so any draw is reached directly. Every float operation is the CPU's, in
// its order, and `precise` keeps the compiler from fusing or reordering them: the points are
// bitwise the built-in's. The draw order follows the CPU: five draws a kernel point (x, y, z of the
// hemisphere, one for the sphere shape, the length) and two a tile vector - y first, then x, as
// makeNoise draws them - with none rejected (none are, for seed 0).

const uint SEED = 0u; // kernel.seed
const uvec2 SPLITMIX_GAMMA = uvec2(0x7F4A7C15u, 0x9E3779B9u); // 0x9E3779B97F4A7C15
const uvec2 SPLITMIX_OFFSET = uvec2(0xD9B4E019u, 0x632BE59Bu); // 0x632BE59BD9B4E019

// 64-bit arithmetic on 32-bit words. Plain operations, not uaddCarry and umulExtended: with constant
// operands llvmpipe (Mesa, LLVM 15) folded those to wrong values.
uvec2 add64(uvec2 a, uvec2 b) {
    uint lo = a.x + b.x;
    return uvec2(lo, a.y + b.y + (lo < a.x ? 1u : 0u));
}
uvec2 mul32(uint a, uint b) { // the full 64-bit product, from 16-bit halves
    uint a0 = a & 0xFFFFu, a1 = a >> 16, b0 = b & 0xFFFFu, b1 = b >> 16;
    uint p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0;
    uint mid = (p00 >> 16) + (p01 & 0xFFFFu) + (p10 & 0xFFFFu);
    return uvec2((p00 & 0xFFFFu) | (mid << 16), a1 * b1 + (p01 >> 16) + (p10 >> 16) + (mid >> 16));
}
uvec2 mul64(uvec2 a, uvec2 b) { // modulo 2^64
    uvec2 p = mul32(a.x, b.x);
    return uvec2(p.x, p.y + a.x * b.y + a.y * b.x);
}
uvec2 xorShift(uvec2 z, int k) { return z ^ uvec2((z.x >> k) | (z.y << (32 - k)), z.y >> k); } // 0 < k < 32

// Draw k (1 = the first) in [0,1) of the CPU's Rng(stream): SplitMix64's output, its top 24 bits.
float draw(uint stream, uint k) {
    uvec2 z = add64(add64(mul64(uvec2(stream, 0u), SPLITMIX_GAMMA), SPLITMIX_OFFSET), mul64(uvec2(k, 0u), SPLITMIX_GAMMA));
    z = mul64(xorShift(z, 30), uvec2(0x1CE4E5B9u, 0xBF58476Du));
    z = mul64(xorShift(z, 27), uvec2(0x133111EBu, 0x94D049BBu));
    z = xorShift(z, 31);
    return float(z.y >> 8u) * (1.0 / 16777216.0);
}

// Kernel point i of n (tangent space, z along the normal): makeKernel's hemisphere.
vec3 kernelPoint(int i, int n) {
    uint k = uint(5 * i), stream = SEED * 4u; // the hemisphere's stream
    precise vec3 v = vec3(-1.0 + 2.0 * draw(stream, k + 1u), -1.0 + 2.0 * draw(stream, k + 2u), draw(stream, k + 3u));
    precise float len2 = v.x * v.x + v.y * v.y + v.z * v.z;
    precise vec3 unit = v * (1.0 / sqrt(len2));         // glm::normalize
    precise float t = float(i) / float(n);
    precise float scale = 0.1 + 0.9 * t * t;              // lerp(0.1, 1, t^2): more points near the pixel
    precise vec3 p = unit * draw(stream, k + 5u) * scale; // a uniform length, pulled towards the centre
    return p;
}

// The 4x4 tile's rotation vector for this pixel (makeNoise), shifted per temporal frame as the
// built-in shifts its tile (16 arrangements).
vec3 rotation() {
    float f = ssaoFrameIndex();
    ivec2 shift = ivec2(mod(f, 4.0), mod(floor(f / 4.0), 4.0));
    ivec2 cell = (ssaoPixel() + shift) & 3;
    uint j = uint(cell.x + 4 * cell.y), stream = SEED * 4u + 7u;
    precise vec3 r = vec3(-1.0 + 2.0 * draw(stream, 2u * j + 2u), -1.0 + 2.0 * draw(stream, 2u * j + 1u), 0.0);
    return r;
}

float sampleOcclusion(vec3 P, vec3 S, float radius) {
    float b = bias * radius;
    if (ssaoBehindEye(S)) { // the divide would flip it across the screen: no pixel to read
        ssaoRecordTap(S, vec2(0.0), SSAO_TAP_BEHIND_EYE, 0.0, 0);
        return 0.0;
    }
    vec2 uv = ssaoProject(S);
    vec4 Q = ssaoPositionAt(uv); // off the frame: the edge texel, as the seeds' clamp to edge
    if (Q.w == 0.0) { // sky occludes nothing
        ssaoRecordTap(S, uv, SSAO_TAP_SKY, 0.0, 0);
        return 0.0;
    }
    float sceneZ = Q.z;
    float dz = abs(P.z - sceneZ);
    float range = smoothstep(0.0, 1.0, radius / max(dz, 1e-4 * radius)); // |dz| = 0 guarded
    float occ = sceneZ >= S.z + b ? range : 0.0;
    ssaoRecordTap(S, uv, occ > 0.0 ? SSAO_TAP_OCCLUDED : SSAO_TAP_OPEN, occ, 0);
    return occ;
}

float ssaoUserAo() {
    vec3 P = ssaoPosition();
    mat3 TBN = tangentFrame(ssaoNormal(), rotate != 0 ? rotation() : vec3(1.0, 0.0, 0.0));
    float radius = ssaoRadius();
    float occ = 0.0;
    int i = 0;
    do { // do-while: no masked pass after the last sample on llvmpipe (ao_common.glsl aoLoops)
        vec3 S = P + TBN * kernelPoint(i, samples) * radius;
        occ += sampleOcclusion(P, S, radius);
    } while (++i < samples);
    ssaoInspectSums(occ, float(samples));
    return 1.0 - occ / float(samples);
}
