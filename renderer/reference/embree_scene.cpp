#include "reference/embree_scene.h"

#include "scene/alpha_mask.h"
#include "util/error.h"

#include <chrono>
#include <cstring>

namespace ssao {

namespace {
void onEmbreeError(void* user, RTCError code, const char* msg) {
    auto* first = static_cast<std::string*>(user);
    if (first->empty()) first->assign("embree error " + std::to_string(int(code)) + ": " + (msg ? msg : "?"));
}
// An Embree filter (intersection and occlusion alike): a candidate hit on a MASK triangle where
// its alpha is cut out is no hit, so the reference sees through the holes the G-buffer has
// (alpha_mask.h; both read the texel nearest the same interpolated UV).
void maskFilter(const RTCFilterFunctionNArguments* args) {
    const auto* m = static_cast<const EmbreeScene::MaskData*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        const int32_t d = prim < m->drawOf.size() ? m->drawOf[prim] : -1;
        if (d < 0) continue;
        const Scene& s = *m->scene;
        const uint32_t* tri = &s.indices[size_t(prim) * 3];
        const float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
        const glm::vec2 uv = (1.0f - u - v) * s.uvs[tri[0]] + u * s.uvs[tri[1]] + v * s.uvs[tri[2]];
        if (cutOut(s, s.draws[size_t(d)], uv)) args->valid[i] = 0;
    }
}

} // namespace

EmbreeScene::EmbreeScene(const Scene& scene) : source_(&scene) {
    const auto t0 = std::chrono::steady_clock::now();
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw Error("reference: cannot create an Embree device (CPU without SSE2?)");
    rtcSetDeviceErrorFunction(device_, onEmbreeError, &error_);
    scene_ = rtcNewScene(device_);
    // ROBUST: no arithmetic shortcuts, so rays do not leak through shared edges; HIGH: a static
    // scene traced millions of times is worth the slower (SAH spatial split) build.
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    if (!scene.vertices.empty() && scene.indices.size() >= 3) {
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), scene.vertices.size()));
        auto* idx = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), scene.triangleCount()));
        if (!v || !idx) {
            rtcReleaseGeometry(g);
            throw Error("reference: " + (error_.empty() ? std::string("out of memory") : error_));
        }
        for (size_t i = 0; i < scene.vertices.size(); ++i)
            std::memcpy(v + 3 * i, &scene.vertices[i].position, 3 * sizeof(float));
        std::memcpy(idx, scene.indices.data(), scene.triangleCount() * 3 * sizeof(uint32_t));
        bool anyMask = false;
        for (const Draw& d : scene.draws)
            anyMask = anyMask || d.mask;
        if (anyMask && scene.uvs.size() == scene.vertices.size()) {
            mask_ = std::make_unique<MaskData>();
            mask_->scene = &scene;
            mask_->drawOf.assign(scene.triangleCount(), -1);
            for (size_t k = 0; k < scene.draws.size(); ++k)
                if (scene.draws[k].mask)
                    for (uint32_t t = scene.draws[k].firstIndex / 3; t < (scene.draws[k].firstIndex + scene.draws[k].indexCount) / 3; ++t)
                        mask_->drawOf[t] = int32_t(k);
            rtcSetGeometryUserData(g, mask_.get());
            rtcSetGeometryIntersectFilterFunction(g, maskFilter);
            rtcSetGeometryOccludedFilterFunction(g, maskFilter);
        }
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(scene_, g, 0);
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(scene_);
    if (!error_.empty()) {
        std::string msg = "reference: " + error_;
        rtcReleaseScene(scene_);
        rtcReleaseDevice(device_);
        throw Error(msg);
    }
    buildMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

EmbreeScene::~EmbreeScene() {
    if (scene_) rtcReleaseScene(scene_);
    if (device_) rtcReleaseDevice(device_);
}

} // namespace ssao
