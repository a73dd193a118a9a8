// The live ray-traced reference in the explorer: the background worker on its own (progressive,
// batch-invariant, cancellable), then through the app: reference.ao and reference.error appear as
// buffers, refine to the target, follow the AO, restart when the view changes, stop when turned
// off, and never hold up the app's destruction. Waits are bounded loops of frames, never timings.
#include "gl_fixture.h"
#include "scene/load/load_scene.h"
#include "gl/readback.h"
#include "ui_driver.h"

#include "scene/load/builtin_scenes.h"
#include "scene/view_fit.h"
#include "measure/reference_worker.h"

#include <chrono>
#include <cmath>
#include <functional>
#include <mutex>
#include <numeric>
#include <sched.h>
#include <thread>

using namespace ssao;
using namespace ssaotest;

namespace {

// Polls `done` (sleeping a little between tries) at most `tries` times.
bool eventually(const std::function<bool()>& done, int tries = 3000) {
    for (int i = 0; i < tries; ++i) {
        if (done()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return done();
}

ReferenceWorker::Job smallJob(const std::shared_ptr<const Scene>& scene, int rays, int w = 64, int h = 36) {
    ReferenceWorker::Job j;
    j.scene = scene;
    j.camera = effectiveCamera(scene->camera.value_or(frameBounds(scene->bounds)), scene->bounds);
    j.width = w;
    j.height = h;
    j.settings.radius = 0.1f * scene->bounds.radius();
    j.settings.samples = rays;
    j.settings.threads = 1;
    return j;
}

} // namespace

TEST(ReferenceWorker, BatchesStartSmallDoubleAndAddUpToTheTarget) {
    EXPECT_EQ(ReferenceWorker::batches(32), (std::vector<int>{4, 4, 8, 16}));
    const std::vector<int> b = ReferenceWorker::batches(512);
    EXPECT_EQ(std::accumulate(b.begin(), b.end(), 0), 512);
    EXPECT_EQ(*std::max_element(b.begin(), b.end()), 64); // a snapshot every 64 rays at most
    EXPECT_EQ(ReferenceWorker::batches(3), (std::vector<int>{3}));
}

TEST(ReferenceWorker, PublishesGrowingSnapshotsThatEndBitIdenticalToOneTrace) {
    auto scene = std::make_shared<const Scene>(loadScene("builtin:showcase"));
    std::mutex m;
    std::vector<int> seen; // rays per pixel of each snapshot, as the worker published them
    ReferenceWorker* self = nullptr;
    // wake() runs on the worker thread right after it publishes: nothing newer exists yet.
    ReferenceWorker w([&] {
        std::lock_guard<std::mutex> lock(m);
        const auto s = self->latest();
        if (s.image && (seen.empty() || seen.back() != s.image->samples)) seen.push_back(s.image->samples);
    });
    {
        std::lock_guard<std::mutex> lock(m);
        self = &w;
    }
    const ReferenceWorker::Job job = smallJob(scene, 32);
    const uint64_t id = w.start(job);
    ASSERT_TRUE(eventually([&] { return w.progress().phase == ReferenceWorker::Phase::Done; }));
    const ReferenceWorker::Snapshot s = w.latest();
    ASSERT_EQ(s.job, id);
    ASSERT_TRUE(s.image);
    {
        std::lock_guard<std::mutex> lock(m);
        EXPECT_EQ(seen, (std::vector<int>{4, 8, 16, 32}));
    }
    EmbreeScene bvh(*scene);
    const ReferenceImage one = traceReference(bvh, job.camera, job.width, job.height, job.settings);
    EXPECT_EQ(s.image->ao, one.ao) << "batches of 4, 4, 8, 16 give the 32-ray image exactly";
    EXPECT_EQ(s.image->samples, 32);
}

#ifdef __linux__
// The frames come first: the worker runs under SCHED_IDLE, and so do the row threads the tracer
// starts from it (Linux threads inherit their creator's policy).
TEST(ReferenceWorker, RunsUnderTheIdlePolicyAndSoDoTheThreadsItStarts) {
    auto scene = std::make_shared<const Scene>(loadScene("builtin:showcase"));
    std::mutex m;
    std::vector<int> policies; // of the worker thread, at each snapshot
    ReferenceWorker w([&] {
        std::lock_guard<std::mutex> lock(m);
        policies.push_back(sched_getscheduler(0));
    });
    w.start(smallJob(scene, 8));
    ASSERT_TRUE(eventually([&] { return w.progress().phase == ReferenceWorker::Phase::Done; }));
    {
        std::lock_guard<std::mutex> lock(m);
        ASSERT_FALSE(policies.empty());
        for (int p : policies) EXPECT_EQ(p, SCHED_IDLE);
    }
    EXPECT_NE(sched_getscheduler(0), SCHED_IDLE) << "the caller's own policy is untouched";
    int child = -1;
    std::thread([&] {
        lowerThisThreadsPriority();
        std::thread([&] { child = sched_getscheduler(0); }).join();
    }).join();
    EXPECT_EQ(child, SCHED_IDLE) << "a thread started by a lowered thread inherits the policy";
}
#endif

TEST(ReferenceWorker, ANewJobCancelsTheRunningOne) {
    auto scene = std::make_shared<const Scene>(loadScene("builtin:showcase"));
    ReferenceWorker w;
    w.start(smallJob(scene, 1 << 16, 160, 90)); // minutes of work if it were not cancelled
    ASSERT_TRUE(eventually([&] { return w.running(); }));
    const uint64_t second = w.start(smallJob(scene, 8));
    ASSERT_TRUE(eventually([&] { return w.progress().phase == ReferenceWorker::Phase::Done; }));
    EXPECT_EQ(w.latest().job, second);
    EXPECT_EQ(w.latest().image->samples, 8);
    w.start(smallJob(scene, 1 << 16, 160, 90));
    ASSERT_TRUE(eventually([&] { return w.running(); }));
    w.cancel();
    EXPECT_TRUE(eventually([&] { return !w.running(); })) << "cancel() stops the trace";
    EXPECT_EQ(w.progress().phase, ReferenceWorker::Phase::Idle);
}

namespace {

class AppReference : public GlTest {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        AppOptions o;
        o.userPresetDir = std::string(SSAOLAB_TEST_TMP) + "/reference_presets";
        o.scene = "builtin:showcase"; // has sky, corners, a crevice
        o.renderScale = 0.3f;         // a 1600x900 window: about 350x190 render pixels
        o.reference = false;          // turned on below with a small target, so the trace is short
        ui_ = std::make_unique<UiDriver>(o, 1600, 900);
        app().frames().referenceRays = 32;
        app().frames().referenceOn = true;
        ui_->settle();
    }
    void TearDown() override {
        ui_.reset();
        GlTest::TearDown();
    }
    AppCore& app() { return ui_->app(); }
    LiveReference::State state() { return app().frames().reference().status().state; }
    // UI frames until the reference reached its target, recording the rays shown after each.
    std::vector<int> framesUntilDone() {
        std::vector<int> rays;
        eventually([&] {
            ui_->frame();
            rays.push_back(app().frames().reference().status().rays);
            return state() == LiveReference::State::Done;
        });
        return rays;
    }
    Image read(const std::string& name) { return readBack(app().renderer().texture(name), 1); }
    std::unique_ptr<UiDriver> ui_;
};

} // namespace

TEST_F(AppReference, AppearsAsBuffersAndRefinesToItsTarget) {
    std::vector<std::string> names;
    for (const Resource* r : app().renderer().buffers())
        names.push_back(r->desc.name);
    EXPECT_NE(std::find(names.begin(), names.end(), "reference.ao"), names.end());
    EXPECT_NE(std::find(names.begin(), names.end(), "reference.error"), names.end());
    EXPECT_EQ(app().renderer().resource("reference.error").desc.display, Display::Signed);

    const std::vector<int> rays = framesUntilDone();
    ASSERT_EQ(state(), LiveReference::State::Done);
    EXPECT_TRUE(std::is_sorted(rays.begin(), rays.end())) << "the ray count only grows";
    EXPECT_EQ(rays.back(), 32);
    ui_->frame();
    ASSERT_TRUE(app().frames().views().find("reference.ao")) << "painted in the grid like any buffer";
    ASSERT_TRUE(app().frames().views().find("reference.error"));

    // The reference: finite, in [0, 1], 1 on sky; some occlusion in the box.
    const Image ref = read("reference.ao"), depth = read("gbuffer.depth");
    const Image ao = read("ao.denoised"), error = read("reference.error");
    long sky = 0, skyOne = 0;
    double geometrySum = 0;
    long geometry = 0, errorMatches = 0;
    for (size_t i = 0; i < ref.data.size(); ++i) {
        ASSERT_TRUE(std::isfinite(ref.data[i]) && ref.data[i] >= 0.0f && ref.data[i] <= 1.0f) << i;
        ASSERT_TRUE(std::isfinite(error.data[i])) << i;
        if (depth.data[i] > 0.0f) {
            geometrySum += ref.data[i], ++geometry;
            // The error is ao.denoised minus the reference, pixel for pixel (same size when still);
            // only silhouette pixels the rays and the raster see differently (error 0) may not match.
            errorMatches += std::abs(error.data[i] - (ao.data[i] - ref.data[i])) <= 1e-6f;
        } else {
            ++sky, skyOne += ref.data[i] == 1.0f;
        }
    }
    ASSERT_GT(geometry, 0);
    EXPECT_GE(double(errorMatches), 0.99 * double(geometry));
    const double mean = geometrySum / double(geometry);
    EXPECT_GT(mean, 0.3);
    EXPECT_LT(mean, 0.99);
    ASSERT_GT(sky, 0) << "the showcase has sky";
    EXPECT_GE(double(skyOne), 0.99 * double(sky)) << "sky is 1 (pixel-centre rays, as the raster's)";

    // The error view: error.png's diverging map, white at 0, red where the AO is too bright.
    // A grid cell is painted at its own size: each of its pixels shows the texel under its centre.
    const Image painted = readBack(app().frames().views().find("reference.error")->target.texture(), 3);
    int red = 0, white = 0;
    for (int y = 0; y < painted.height; ++y)
        for (int x = 0; x < painted.width; ++x) {
            const int glY = painted.height - 1 - y; // rows top first; the paint's uv counts from the bottom
            const int tx = int((x + 0.5) * error.width / painted.width);
            const int ty = error.height - 1 - int((glY + 0.5) * error.height / painted.height);
            const size_t i = size_t(ty) * size_t(error.width) + size_t(tx);
            if (!(depth.data[i] > 0.0f)) continue;
            const float r = painted.at(x, y, 0), g = painted.at(x, y, 1), b = painted.at(x, y, 2);
            if (error.data[i] > 0.2f) red += r > 0.9f && g < 0.3f && b < 0.3f;
            if (error.data[i] == 0.0f) white += r > 0.99f && g > 0.99f && b > 0.99f;
        }
    EXPECT_GT(red, 0);
    EXPECT_GT(white, 0);

    // The numbers beside the timings, and the hover readout.
    const auto& m = app().frames().reference().metrics();
    ASSERT_TRUE(m.has_value());
    for (double v : {m->rmse, m->bias, m->psnrGeometrySrgb, m->ssim, m->referenceNoise})
        EXPECT_TRUE(std::isfinite(v)) << v;
    EXPECT_GT(m->rmse, 0.0);
    EXPECT_EQ(m->nonFinite, 0);
    EXPECT_TRUE(ui_->has("reference#metrics"));
    const std::vector<float> hover = app().valueAt("reference.ao", {ref.width / 2, ref.height / 2});
    ASSERT_EQ(hover.size(), 1u);
    EXPECT_GE(hover[0], 0.0f);
    EXPECT_LE(hover[0], 1.0f);

    // Then the screen-space oracle of the same view, and the error split beside the total: the
    // screen's share (the oracle against the truth) is below the total on the showcase, whose
    // occluders are mostly on screen; both finite.
    ASSERT_TRUE(eventually([&] {
        ui_->frame();
        return app().frames().reference().split().has_value();
    }));
    const LiveReference::Split sp = *app().frames().reference().split();
    for (double v : {sp.technique.rmse, sp.technique.bias, sp.screen.rmse, sp.screen.bias})
        EXPECT_TRUE(std::isfinite(v)) << v;
    EXPECT_GT(sp.technique.rmse, 0.0);
    EXPECT_LT(sp.screen.rmse, app().frames().reference().metrics()->rmse);
    EXPECT_EQ(sp.technique.nonFinite + sp.screen.nonFinite, 0);
    // Their shares of the squared error add up (metrics/error_split.h), each the square of its RMSE.
    EXPECT_NEAR(sp.shares.technique + sp.shares.screen + sp.shares.interaction, 1.0, 1e-9);
    EXPECT_NEAR(sp.shares.mseTechnique, sp.technique.rmse * sp.technique.rmse, 1e-9);
    EXPECT_NEAR(sp.shares.mseScreen, sp.screen.rmse * sp.screen.rmse, 1e-9);
    ui_->frame();
    EXPECT_TRUE(ui_->has("reference#split"));

    // Converged: nothing left to do, the app may sleep again.
    ui_->frames(3);
    const int rendered = app().frames().framesRendered();
    ui_->frames(5);
    EXPECT_EQ(app().frames().framesRendered(), rendered);
    EXPECT_FALSE(app().frames().busy());
    ui_->save(std::string(SSAOLAB_TEST_TMP) + "/ui_reference.png");
}

TEST_F(AppReference, AnAoChangeUpdatesTheErrorAndKeepsTheReference) {
    framesUntilDone();
    const Image ref = read("reference.ao"), error = read("reference.error");
    const double rmse = app().frames().reference().metrics()->rmse;
    app().settings().kernel.samples = 4; // noisier AO, same radius: the reference stays valid
    app().frames().keepAwake();
    ui_->settle();
    // The error is evaluated off the UI thread: shown a frame or a few later.
    ASSERT_TRUE(eventually([&] {
        ui_->frame();
        return app().frames().reference().metrics()->rmse != rmse;
    }));
    EXPECT_EQ(state(), LiveReference::State::Done) << "no restart";
    EXPECT_EQ(read("reference.ao").data, ref.data);
    EXPECT_NE(read("reference.error").data, error.data) << "the error follows ao.denoised";
}

// The info strip's "where" line: the error of the same frame by place (metrics/error_places.h),
// whose places add up to the error shown beside it.
TEST_F(AppReference, TheErrorByPlaceAddsUpToTheErrorShown) {
    framesUntilDone();
    ASSERT_TRUE(eventually([&] {
        ui_->frame();
        return app().frames().reference().places().has_value();
    }));
    const ErrorByPlace& e = *app().frames().reference().places();
    long pixels = 0;
    double sq = 0;
    for (const PlaceStats& p : e.place) pixels += p.pixels, sq += p.sumSq;
    EXPECT_EQ(pixels, e.all.pixels);
    EXPECT_NEAR(sq, e.all.sumSq, 1e-9 * (1 + sq));
    ASSERT_GT(e.all.pixels, 0);
    EXPECT_NEAR(std::sqrt(e.all.sumSq / double(e.all.pixels)), app().frames().reference().metrics()->rmse, 1e-6);
}

TEST_F(AppReference, ACameraOrRadiusChangeCancelsAndRestarts) {
    framesUntilDone();
    const Image before = read("reference.ao");
    // A drag: while it lasts the trace waits, showing nothing of the old view.
    app().cameraController().rotate(40, 0);
    app().frames().noteInteraction();
    ui_->frame();
    EXPECT_EQ(state(), LiveReference::State::Waiting);
    EXPECT_EQ(app().frames().reference().status().rays, 0) << "the ray count drops back";
    EXPECT_FALSE(app().frames().reference().metrics().has_value());
    ui_->settle();
    EXPECT_NE(state(), LiveReference::State::Waiting) << "restarted once input settled";
    framesUntilDone();
    EXPECT_EQ(app().frames().reference().status().rays, 32);
    EXPECT_NE(read("reference.ao").data, before.data) << "the new view's reference";

    const float radius = app().frames().reference().status().radius;
    app().settings().ao.radiusScene *= 2.0f;
    app().frames().keepAwake();
    ui_->frame();
    EXPECT_LT(app().frames().reference().status().rays, 32);
    framesUntilDone();
    EXPECT_NEAR(app().frames().reference().status().radius, 2.0f * radius, 1e-3f * radius);
}

TEST_F(AppReference, TurningItOffStopsTheTraceAndRemovesItsBuffers) {
    app().frames().referenceRays = 1 << 16; // would trace for minutes
    ui_->frames(2);
    ASSERT_TRUE(eventually([&] {
        ui_->frame();
        return app().frames().reference().tracing() && state() == LiveReference::State::Tracing;
    }));
    ui_->click("reference#on", 0.1f);
    ui_->frame();
    EXPECT_FALSE(app().frames().referenceOn);
    EXPECT_EQ(state(), LiveReference::State::Off);
    EXPECT_FALSE(app().renderer().graph().find("reference.ao")) << "its buffers left the graph";
    EXPECT_TRUE(eventually([&] { return !app().frames().reference().tracing(); })) << "the worker stopped";
    ui_->click("reference#on", 0.1f); // and on again: a fresh trace
    ui_->frame();
    EXPECT_TRUE(app().renderer().graph().find("reference.ao"));
    EXPECT_NE(state(), LiveReference::State::Off);
}

TEST_F(AppReference, DestroyingTheAppWhileTracingReturns) {
    app().frames().referenceRays = 1 << 16;
    ASSERT_TRUE(eventually([&] {
        ui_->frame();
        return app().frames().reference().tracing();
    }));
    ui_.reset(); // cancels and joins the worker: no hang, no crash
    SUCCEED();
}
