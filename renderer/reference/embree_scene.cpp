#include "reference/embree_scene.h"

#include "util/error.h"

#include <chrono>
#include <cstring>

namespace ssao {

namespace {
void onEmbreeError(void* user, RTCError code, const char* msg) {
    auto* first = static_cast<std::string*>(user);
    if (first->empty()) first->assign("embree error " + std::to_string(int(code)) + ": " + (msg ? msg : "?"));
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
