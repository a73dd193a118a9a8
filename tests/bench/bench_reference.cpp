// Reference-tracer throughput (Google Benchmark): AO rays per second on CornellBox at 640x360 with
// the default radius (5 % of the scene's diagonal), on 1 thread and on every core. The figure the
// issue asks for is items_per_second of BM_ReferenceRays/threads:0 (0 = all cores).
//   ./build/tests/bench_reference --benchmark_min_time=2
#include "reference/reference_ao.h"
#include "scene/load/load_scene.h"
#include "scene/scene.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <memory>
#include <thread>

using namespace ssao;

namespace {
struct CornellBox {
    Scene scene = loadScene(SSAOLAB_SCENES_DIR "/CornellBox/cornellBox.gltf");
    EmbreeScene rt{scene};
    Camera camera = scene.camera ? *scene.camera : frameBounds(scene.bounds);
    float radius = 0.05f * 2.0f * scene.bounds.radius();
};
CornellBox& cornell() {
    static CornellBox c;
    return c;
}
} // namespace

// Adds 8 rays per pixel per iteration to one tracer; reports AO rays per second.
static void traceBatches(benchmark::State& state, ReferenceVariant variant, int threads) {
    CornellBox& c = cornell();
    ReferenceTracer tracer(c.rt, c.camera, 640, 360, {c.radius, 1 << 20, variant, threads});
    long long rays = 0;
    for (auto _ : state) {
        const long long before = tracer.image().aoRays;
        tracer.addSamples(8);
        rays += tracer.image().aoRays - before;
    }
    state.SetItemsProcessed(rays);
    state.counters["threads"] = threads > 0 ? threads : double(std::thread::hardware_concurrency());
    state.counters["Mrays/s"] = benchmark::Counter(double(rays) * 1e-6, benchmark::Counter::kIsRate);
}

static void BM_ReferenceRays(benchmark::State& state) {
    traceBatches(state, ReferenceVariant::Visibility, int(state.range(0)));
}
BENCHMARK(BM_ReferenceRays)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_ReferenceObscuranceRays(benchmark::State& state) {
    traceBatches(state, ReferenceVariant::Obscurance, 0);
}
BENCHMARK(BM_ReferenceObscuranceRays)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_BvhBuild(benchmark::State& state) {
    CornellBox& c = cornell();
    for (auto _ : state) {
        EmbreeScene rt(c.scene);
        benchmark::DoNotOptimize(rt.handle());
    }
}
BENCHMARK(BM_BvhBuild)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
