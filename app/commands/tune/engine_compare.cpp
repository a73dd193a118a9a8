#include "commands/tune/engine_compare.h"

#include "measure/bench_run.h"
#include "measure/measurement.h"
#include "settings/preset_store.h"

namespace ssao {

std::vector<PresetPoint> measureShippedPresets(const HeadlessRunner& runner, const Scene& scene, const Camera& camera,
                                               const ReferenceImage& ref, float radius, int warmup, int frames) {
    const PresetStore store = PresetStore::standard();
    auto r = runner.makeRenderer(ref.width, ref.height);
    r->setScene(scene);
    r->setCamera(camera);
    std::vector<PresetPoint> out;
    for (const PresetEntry& e : store.entries()) {
        if (!e.builtin) continue;
        Measurement m(withRadius(store.load(e.name).settings, radius), warmup, frames);
        while (!m.step(*r, ref)) {
        }
        runner.checkGl("measuring preset " + e.name + " on " + scene.name);
        out.push_back({e.name, m.result().error.rmse, m.result().gpuMs, std::make_shared<Evaluation>(m.evaluation())});
    }
    return out;
}

const PresetPoint* mostAccurateWithin(const std::vector<PresetPoint>& points, double ms) {
    const PresetPoint* best = nullptr;
    for (const PresetPoint& p : points)
        if (p.ms <= ms && (!best || p.rmse < best->rmse)) best = &p;
    return best;
}

} // namespace ssao
