#include "ssao/sample_inspector.h"

#include "ssao/constants.h"
#include "ssao/kernel.h"

#include <algorithm>
#include <cmath>

namespace ssao {

namespace {

// texture() with NEAREST filtering and CLAMP_TO_EDGE, at GL uv (origin bottom-left).
glm::vec4 fetch(const Image& img, glm::vec2 uv) {
    int tx = std::clamp(int(std::floor(uv.x * float(img.width))), 0, img.width - 1);
    int ty = std::clamp(int(std::floor(uv.y * float(img.height))), 0, img.height - 1);
    int row = img.height - 1 - ty;
    glm::vec4 v(0.0f, 0.0f, 0.0f, 1.0f);
    for (int c = 0; c < std::min(img.channels, 4); ++c)
        v[c] = img.at(tx, row, c);
    return v;
}

float smoothstep01(float x) {
    float t = std::clamp(x, 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

struct Replay {
    const gpu::SsaoConstants& c;
    const gpu::FrameConstants& f;
    const GBufferImages& gb;

    bool flag(int bit) const { return (c.modes.w & bit) != 0; }

    glm::vec4 viewPosition(glm::vec2 uv) const { // mirrors viewPosition() in ssao.frag
        if (flag(SSAO_FLAG_POS_FROM_DEPTH)) {
            float d = fetch(*gb.depth, uv).x;
            if (d >= 1.0f) return glm::vec4(0.0f);
            float n = f.clip.x, fa = f.clip.y;
            float dist = 2.0f * n * fa / (fa + n - (d * 2.0f - 1.0f) * (fa - n));
            glm::vec2 ndc = uv * 2.0f - 1.0f;
            glm::vec3 ray(ndc.x * f.invProj[0][0], ndc.y * f.invProj[1][1], -1.0f);
            return glm::vec4(ray * dist, 1.0f);
        }
        return fetch(*gb.position, uv);
    }

    SampleTap tap(const glm::vec3& P, const glm::vec3& S, int set) const { // mirrors sampleOcclusion()
        SampleTap t;
        t.viewPos = S;
        t.set = set;
        const float radius = c.params0.x, bias = c.params0.y;
        glm::vec4 clip = f.proj * glm::vec4(S, 1.0f);
        if (clip.w <= 1e-5f * f.clip.x) {
            t.state = SampleTap::State::BehindEye;
            return t;
        }
        t.uv = glm::vec2(clip) / clip.w * 0.5f + 0.5f;
        bool off = t.uv.x < 0.0f || t.uv.y < 0.0f || t.uv.x > 1.0f || t.uv.y > 1.0f;
        if (off && !flag(SSAO_FLAG_OFFSCREEN_CLAMP)) {
            t.state = SampleTap::State::Offscreen;
            return t;
        }
        glm::vec4 Q = viewPosition(t.uv);
        if (Q.w == 0.0f) {
            t.state = SampleTap::State::Sky;
            return t;
        }
        float dz = std::abs(P.z - Q.z);
        float range = 1.0f;
        if (c.modes.y == SSAO_RANGE_SMOOTHSTEP)
            range = smoothstep01(radius / std::max(dz, c.params0.w));
        else if (c.modes.y == SSAO_RANGE_HARD)
            range = dz < radius ? 1.0f : 0.0f;
        bool occluded = c.modes.z == SSAO_DEPTHTEST_SAMPLE ? Q.z >= S.z + bias : P.z + bias < Q.z;
        t.occlusion = occluded ? range : 0.0f;
        t.state = occluded && range > 0.0f ? SampleTap::State::Occluded : SampleTap::State::Open;
        return t;
    }
};

} // namespace

const char* tapStateName(SampleTap::State s) {
    switch (s) {
    case SampleTap::State::Open:
        return "open";
    case SampleTap::State::Occluded:
        return "occluded";
    case SampleTap::State::BehindEye:
        return "behind eye";
    case SampleTap::State::Offscreen:
        return "off screen";
    case SampleTap::State::Sky:
        return "sky";
    }
    return "?";
}

PixelInspection inspectPixel(const SsaoSettings& s, const GBufferSettings& g,
                             const gpu::FrameConstants& frame, const GBufferImages& gb, int x, int y) {
    PixelInspection out;
    const int w = int(frame.viewport.x), h = int(frame.viewport.y);
    if (x < 0 || y < 0 || x >= w || y >= h) return out;
    const gpu::SsaoConstants c = packSsaoConstants(s, g, w, h);
    Replay r{c, frame, gb};
    const glm::vec2 uv((float(x) + 0.5f) / float(w), (float(h - 1 - y) + 0.5f) / float(h));
    glm::vec4 P = r.viewPosition(uv);
    if (P.w == 0.0f) return out;
    out.geometry = true;
    out.position = glm::vec3(P);
    glm::vec3 N = glm::vec3(fetch(*gb.normal, uv));
    if (r.flag(SSAO_FLAG_NORMAL_UNORM)) N = N * 2.0f - 1.0f;
    float nl2 = glm::dot(N, N);
    N = nl2 > 1e-12f ? N / std::sqrt(nl2) : glm::vec3(0, 0, 1);
    out.normal = N;
    glm::vec3 rv(1, 0, 0);
    if (r.flag(SSAO_FLAG_NOISE)) rv = makeNoise(uint32_t(s.seed))[size_t((x % 4) + 4 * ((h - 1 - y) % 4))];
    const glm::mat3 tbn = tangentFrame(N, rv);
    const int n = c.modes.x;
    const int sets = r.flag(SSAO_FLAG_SEPARABLE) ? 2 : 1;
    float occ = 0.0f;
    for (int set = 0; set < sets; ++set)
        for (int i = 0; i < n; ++i) {
            glm::vec3 S = glm::vec3(P) + tbn * glm::vec3(c.kernel[set * SSAO_MAX_SAMPLES + i]) * c.params0.x;
            out.taps.push_back(r.tap(glm::vec3(P), S, set));
            occ += out.taps.back().occlusion;
        }
    float visibility = std::clamp(1.0f - occ / float(n * sets), 0.0f, 1.0f);
    out.ao = std::pow(visibility, c.params0.z);
    return out;
}

} // namespace ssao
