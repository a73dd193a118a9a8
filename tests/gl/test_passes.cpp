// The frame graph on the GPU: it re-runs exactly the passes an input change invalidates, shares
// the G-buffer (and any identical work) between chains A and B, and carries resolution scales.
#include "gl_fixture.h"
#include "scene/load/load_scene.h"
#include "gl/readback.h"

#include "scene/scene.h"
#include "techniques/technique.h"
#include "util/error.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <map>
#include <set>

using namespace ssao;
using namespace ssaotest;

namespace {
class Passes : public GlTest {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        scene_ = loadScene("builtin:showcase");
        r_ = makeRenderer(scene_, defaultSettings(), 160, 90);
    }
    void TearDown() override {
        r_.reset();
        GlTest::TearDown();
    }
    std::vector<std::string> ranAfter(const std::string& assignment) {
        Settings s = r_->settings();
        applyAssignment(s, assignment);
        r_->setSettings(s);
        return r_->render().ran();
    }
    Scene scene_;
    std::unique_ptr<Renderer> r_;
};
using V = std::vector<std::string>;
} // namespace

TEST_F(Passes, FirstFrameRunsAllInDeclaredOrderThenNothingUntilSomethingChanges) {
    FrameReport first = r_->render();
    EXPECT_EQ(first.ran(), (V{"gbuffer", "ao", "denoise", "composite"}));
    for (auto& p : first.passes) {
        EXPECT_GE(p.gpuMs, 0.0) << p.name;     // timer queries answered...
        EXPECT_LT(p.gpuMs, 10000.0) << p.name; // ...with a real time (llvmpipe first-query guard)
    }
    EXPECT_EQ(r_->render().ran(), V{});
}

TEST_F(Passes, EveryBufferIsListedFromTheGraph) {
    r_->render();
    V names;
    for (const Resource* res : r_->buffers())
        names.push_back(res->desc.name);
    EXPECT_EQ(names, (V{"gbuffer.position", "gbuffer.normal", "gbuffer.albedo", "gbuffer.depth",
                        "gbuffer.zbuffer", "ao.raw", "ao.denoised", "composite"}));
    EXPECT_NE(r_->graph().find("denoise.tmp"), nullptr); // internal scratch exists but is not listed
}

TEST_F(Passes, DenoiseSettingRerunsOnlyDenoiseAndComposite) {
    r_->render();
    Image rawBefore = readBack(r_->texture("ao.raw"), 1), aoBefore = readBack(r_->texture("ao.denoised"), 1);
    EXPECT_EQ(ranAfter("denoise.kind=gaussian"), (V{"denoise", "composite"}));
    EXPECT_EQ(ranAfter("denoise.sigma=3"), (V{"denoise", "composite"}));
    Image rawAfter = readBack(r_->texture("ao.raw"), 1), aoAfter = readBack(r_->texture("ao.denoised"), 1);
    EXPECT_EQ(rawBefore.data, rawAfter.data); // not recomputed, so bit-identical
    EXPECT_NE(aoBefore.data, aoAfter.data);   // and the denoiser did change the result
}

TEST_F(Passes, EachSettingGroupInvalidatesItsPassAndWhatFollows) {
    r_->render();
    EXPECT_EQ(ranAfter("ao.radius_scene=0.03"), (V{"ao", "denoise", "composite"}));
    EXPECT_EQ(ranAfter("kernel.samples=16"), (V{"ao", "denoise", "composite"}));
    EXPECT_EQ(ranAfter("composite.ambient=0.5"), (V{"composite"}));
    EXPECT_EQ(ranAfter("gbuffer.normal_format=rgba8"), (V{"gbuffer", "ao", "denoise", "composite"}));
    EXPECT_EQ(ranAfter("ao.radius_scene=0.03"), V{}); // same value: nothing changed
}

TEST_F(Passes, ARowThatDoesNotApplyReRunsNothing) {
    r_->render();
    ASSERT_EQ(r_->settings().denoise.kind, DenoiseKind::Auto);
    EXPECT_EQ(ranAfter("denoise.sigma=5"), V{}); // no effect under auto (the technique's own denoiser)
    EXPECT_EQ(ranAfter("denoise.kind=box4"), (V{"denoise", "composite"}));
    EXPECT_EQ(ranAfter("denoise.sigma=4"), V{}); // nor under box4
    EXPECT_EQ(ranAfter("ao.radius=3"), V{});     // the world radius, while the radius is in scene units
    EXPECT_EQ(ranAfter("ao.radius_mode=world"), (V{"ao", "denoise", "composite"}));
    EXPECT_EQ(ranAfter("ao.radius=2"), (V{"ao", "denoise", "composite"}));
}

namespace {
// The chain's outputs, read back: what a stale pass would leave wrong.
std::vector<Image> outputs(Renderer& r) {
    std::vector<Image> out;
    for (const char* name : {"gbuffer.position", "gbuffer.normal", "ao.raw", "ao.denoised", "composite"})
        out.push_back(readBack(r.texture(name), name[0] == 'a' ? 1 : 3));
    return out;
}
} // namespace

TEST_F(Passes, EveryRowOnEveryTechniqueReRunsExactlyThePassesWhoseConfigChanged) {
    // By construction a pass's key is its config (graph/pass_config.h), so the passes that run after
    // a change are those whose config changed and those reading what they wrote. Every row of the
    // table is moved to the other end of its range (or to another choice) on every technique:
    // exactly the expected passes run, the incremental frame equals a fully re-run one (no value a
    // pass uses is missing from its config), and setting the same settings again runs nothing.
    int rows = 0, reRuns = 0;
    for (const auto& t : techniques()) {
        Settings base = defaultSettings();
        base.ao.technique = t.id;
        r_->setSettings(base);
        r_->render();
        for (const Param& p : paramTable()) {
            Settings s = base;
            const double v = p.get(s);
            p.set(s, v != p.max ? p.max : p.min);
            if (!p.applies(s) || s == base || p.key == "ao.technique") continue;
            if (p.group() == "temporal") continue; // accumulation re-runs by design: TemporalRestartsAndEnds
            // Expected from the configs alone: a pass runs when its config differs, when it is new or
            // its topology changed, or when it reads a resource a running pass writes.
            const FrameInfo frame = r_->frame();
            std::map<std::string, ConfigKey> before;
            std::map<std::string, PassDecl> declBefore;
            for (const auto& name : r_->graph().passOrder()) {
                before[name] = r_->graph().pass(name)->configure(base, frame);
                declBefore[name] = *r_->graph().declaration(name);
            }
            r_->setSettings(s);
            const V ran = r_->render().ran();
            std::set<std::string> expected, written;
            for (const auto& name : r_->graph().passOrder()) {
                const PassDecl& d = *r_->graph().declaration(name);
                bool runs = !before.count(name) || r_->graph().pass(name)->configure(s, r_->frame()) != before[name];
                if (before.count(name)) {
                    const PassDecl& o = declBefore[name];
                    runs = runs || o.reads != d.reads || o.writes.size() != d.writes.size();
                    for (size_t w = 0; !runs && w < d.writes.size(); ++w)
                        runs = o.writes[w].format != d.writes[w].format || o.writes[w].scale != d.writes[w].scale;
                }
                for (const auto& in : d.reads)
                    runs = runs || written.count(r_->graph().resolve(in));
                if (!runs) continue;
                expected.insert(name);
                for (const auto& w : d.writes)
                    written.insert(w.name);
            }
            EXPECT_EQ(std::set<std::string>(ran.begin(), ran.end()), expected) << t.id << " " << p.key;
            const std::vector<Image> incremental = outputs(*r_);
            r_->invalidate();
            r_->render();
            const std::vector<Image> forced = outputs(*r_);
            for (size_t i = 0; i < forced.size(); ++i)
                EXPECT_EQ(incremental[i].data, forced[i].data) << t.id << " " << p.key << " output " << i;
            r_->setSettings(s); // identical settings: identical configs, nothing runs
            EXPECT_EQ(r_->render().ran(), V{}) << t.id << " " << p.key;
            r_->setSettings(base);
            r_->render();
            ++rows;
            reRuns += int(ran.size());
        }
    }
    std::printf("%d row changes over %zu techniques, %d pass runs\n", rows, techniques().size(), reRuns);
    EXPECT_GT(rows, 100);
}

TEST_F(Passes, TemporalRestartsAndEnds) {
    // Accumulation: each frame until `frames` has a new frame index, so the AO (new noise) and the
    // denoiser (the blend) run, the G-buffer (which does not read the index) does not; then the
    // image is final and nothing runs. Its first frame has index 0, the noise the AO already drew
    // without accumulation: only the denoiser (a new history) and what follows run.
    r_->render();
    Settings s = r_->settings();
    s.temporal.enabled = true;
    s.temporal.frames = 3;
    r_->setSettings(s);
    EXPECT_EQ(r_->render().ran(), (V{"denoise", "composite"}));
    EXPECT_EQ(r_->render().ran(), (V{"ao", "denoise", "composite"}));
    EXPECT_EQ(r_->render().ran(), (V{"ao", "denoise", "composite"}));
    EXPECT_FALSE(r_->accumulating());
    EXPECT_EQ(r_->render().ran(), V{});
}

TEST_F(Passes, CameraSceneAndSizeInvalidateEverything) {
    r_->render();
    Camera c = r_->userCamera();
    c.eye.x += 0.1f;
    r_->setCamera(c);
    EXPECT_EQ(r_->render().ran().size(), 4u);
    r_->setSize(100, 50);
    EXPECT_EQ(r_->render().ran().size(), 4u);
    EXPECT_EQ(r_->texture("ao.raw").width(), 100);
    r_->setScene(scene_);
    EXPECT_EQ(r_->render().ran().size(), 4u);
}

TEST_F(Passes, ChainBSharesTheGBufferAndWhateverItsSettingsDoNotChange) {
    r_->render();
    // AO on | off: B differs only in the composite, so only b.composite runs.
    Settings off = r_->settings();
    off.composite.useAo = false;
    r_->setSettingsB(off);
    EXPECT_EQ(r_->render().ran(), V{"b.composite"});
    EXPECT_EQ(r_->graph().resolve("b.ao.raw"), "ao.raw"); // B's AO is A's, not a second computation
    // A B preset that changes only the denoiser shares the raw AO.
    Settings gauss = r_->settings();
    gauss.denoise.kind = DenoiseKind::Gaussian;
    r_->setSettingsB(gauss);
    EXPECT_EQ(r_->render().ran(), (V{"b.denoise", "b.composite"}));
    // A different kernel needs its own AO pass, still on the shared G-buffer.
    Settings sphere = r_->settings();
    sphere.kernel.shape = KernelShape::Sphere;
    r_->setSettingsB(sphere);
    EXPECT_EQ(r_->render().ran(), (V{"b.ao", "b.denoise", "b.composite"}));
    Image mask = readBack(r_->texture("gbuffer.position"), 4).channel(3);
    const double a = stats(readBack(r_->texture("ao.raw"), 1), &mask).mean;
    const double b = stats(readBack(r_->texture("b.ao.raw"), 1), &mask).mean;
    EXPECT_LT(b, a - 0.2) << "B really renders its own settings (the sphere kernel's false occlusion)";
    // Chain B off: its passes leave the graph.
    r_->setSettingsB(std::nullopt);
    EXPECT_EQ(r_->render().ran(), V{});
    EXPECT_EQ(r_->graph().find("b.ao.raw"), nullptr);
}

TEST_F(Passes, AoAtHalfAndQuarterResolutionFlowsThroughTheGraph) {
    Rendered full = render("builtin:showcase", defaultSettings(), 320, 180);
    for (const char* res : {"half", "quarter"}) {
        Settings s = defaultSettings();
        setParam(s, "ao.resolution", res);
        auto r = makeRenderer(scene_, s, 320, 180);
        r->render();
        const int div = std::string(res) == "half" ? 2 : 4;
        EXPECT_EQ(r->texture("ao.raw").width(), 320 / div) << res;
        EXPECT_EQ(r->resource("ao.raw").desc.scale, 1.0f / float(div)) << res;
        EXPECT_EQ(r->texture("ao.denoised").width(), 320) << res; // the denoiser brings it back to full size
        Rendered out = readAll(*r);
        EXPECT_TRUE(finiteInRange(out.aoRaw, 0.0f, 1.0f)) << res;
        EXPECT_TRUE(finiteInRange(out.ao, 0.0f, 1.0f)) << res;
        // The same AO, only coarser: close to full resolution on average.
        EXPECT_NEAR(geometryMean(out, out.ao), geometryMean(full, full.ao), 0.02) << res;
    }
}

// Denoise `none` at full resolution copies ao.raw instead of running the identity tap: that is
// exact only because every technique's raw AO is already <= 1 and 1 on the sky, at every power.
TEST_F(Passes, NoDenoiserAtFullResolutionIsAnExactCopyOfTheRawAo) {
    for (const auto& t : techniques())
        for (const char* power : {"1", "3"})
            for (const char* sky : {"true", "false"}) {
                Settings s = defaultSettings();
                s.ao.technique = t.id;
                setParam(s, "denoise.kind", "none");
                setParam(s, "ao.power", power);
                setParam(s, "skip.sky", sky);
                auto r = makeRenderer(scene_, s, 160, 90);
                const std::vector<std::string> ran = r->render().ran();
                EXPECT_NE(std::find(ran.begin(), ran.end(), "denoise"), ran.end()) << t.id;
                // A copy: no scratch target, no depth read for the sky (the raw AO is 1 there).
                EXPECT_EQ(r->graph().find("denoise.tmp"), nullptr) << t.id;
                const PassDecl* d = r->graph().declaration("denoise");
                ASSERT_NE(d, nullptr);
                EXPECT_EQ(std::find(d->reads.begin(), d->reads.end(), "gbuffer.depth"), d->reads.end()) << t.id;
                Rendered out = readAll(*r);
                ASSERT_EQ(out.ao.data.size(), out.aoRaw.data.size()) << t.id;
                EXPECT_TRUE(finiteInRange(out.aoRaw, 0.0f, 1.0f)) << t.id << " power " << power;
                size_t differ = 0, skyNotOne = 0;
                for (size_t i = 0; i < out.ao.data.size(); ++i) {
                    differ += out.ao.data[i] != out.aoRaw.data[i];
                    skyNotOne += out.depth.data[i] == 0.0f && out.ao.data[i] != 1.0f;
                }
                EXPECT_EQ(differ, 0u) << t.id << " power " << power << " skip.sky " << sky;
                EXPECT_EQ(skyNotOne, 0u) << t.id << " power " << power << " skip.sky " << sky;
            }
}

// The optional AO inputs are compiled in only where their settings enable them (AO_* defines,
// ao_pass.cpp aoFeatureDefines): each one, switched on, must reach the AO.
TEST_F(Passes, EachOptionalAoInputReachesTheAoWhenSwitchedOn) {
    int banded = 0;
    for (const auto& info : techniques()) {
        const std::string& t = info.id;
        // {settings both frames share, the input switched on in the second}
        std::vector<std::pair<std::string, std::string>> cases = {{"ao.radius_scene=0.15", "ao.normals=depth"}};
        // The guard band, where the technique's pass declares it reads it.
        Settings band = defaultSettings();
        setParam(band, "ao.technique", t);
        applyAssignment(band, "gbuffer.guard_band_px=32");
        r_->setSettings(band);
        r_->render();
        bool readsBand = false;
        for (const auto& pass : r_->graph().passOrder())
            if (const PassDecl* d = r_->graph().declaration(pass))
                readsBand |= std::count(d->reads.begin(), d->reads.end(), "gbuffer.guard_band") > 0;
        if (readsBand) cases.push_back({"ao.radius_scene=0.15", "gbuffer.guard_band_px=32"}), ++banded;
        // Far taps: the pyramid's coarser levels.
        if (findParam(t + ".pyramid")) cases.push_back({"ao.radius_scene=0.15", t + ".pyramid=true"});
        // A technique with an assumed thickness refines it from the back-face layer; a thin assumed
        // one lets the true one show.
        if (findParam(t + ".thickness")) cases.push_back({t + ".thickness=0.1", "gbuffer.back_faces=true"});
        for (const auto& [common, on] : cases) {
            Settings base = defaultSettings();
            setParam(base, "ao.technique", t);
            applyAssignment(base, common);
            const Rendered ref = render("builtin:showcase", base, 320, 180);
            Settings s = base;
            applyAssignment(s, on);
            const Rendered out = render("builtin:showcase", s, 320, 180);
            size_t differ = 0;
            for (size_t i = 0; i < out.aoRaw.data.size(); ++i)
                differ += out.aoRaw.data[i] != ref.aoRaw.data[i];
            EXPECT_GT(differ, 0u) << t << " " << on;
        }
    }
    EXPECT_GT(banded, 0) << "no technique reads the guard band";
}

TEST_F(Passes, ChainBOffAndOnAgainRendersIntoItsNewBuffers) {
    // Turning B off frees its buffers; turning it on again must render into the new ones (a stale
    // framebuffer of the freed texture would leave b.ao.raw unwritten).
    Settings sphere = r_->settings();
    sphere.kernel.shape = KernelShape::Sphere;
    for (int round = 0; round < 3; ++round) {
        r_->setSettingsB(sphere);
        r_->render();
        Image mask = readBack(r_->texture("gbuffer.position"), 4).channel(3);
        const double a = stats(readBack(r_->texture("ao.raw"), 1), &mask).mean;
        const double b = stats(readBack(r_->texture("b.ao.raw"), 1), &mask).mean;
        EXPECT_LT(b, a - 0.2) << "round " << round;
        r_->setSettingsB(std::nullopt);
        r_->render();
        EXPECT_EQ(r_->graph().find("b.ao.raw"), nullptr);
    }
}

TEST_F(Passes, APassThatThrowsLeavesNoGlStateBehind) {
    // A shader folder whose G-buffer shader breaks only in the 8-bit-normal variant: switching to
    // it throws from inside the pass. The next frames (back on rgba16f) must render cleanly: no
    // open timer query or debug group, no GL error, everything re-run.
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/variant_shaders";
    std::filesystem::remove_all(dir);
    std::filesystem::copy(SSAOLAB_SHADER_DIR, dir, std::filesystem::copy_options::recursive);
    {
        std::ofstream(dir + "/passes/gbuffer.frag", std::ios::app)
            << "\n#ifdef NORMAL_UNORM\nbroken;\n#endif\n";
    }
    auto r = std::make_unique<Renderer>(dir);
    r->setSize(64, 36);
    r->setScene(scene_);
    r->setCamera(*scene_.camera);
    r->render();
    Settings s = r->settings();
    s.gbuffer.normalFormat = TargetFormat::RGBA8;
    r->setSettings(s);
    EXPECT_THROW(r->render(), Error);
    s.gbuffer.normalFormat = TargetFormat::RGBA16F;
    r->setSettings(s);
    const FrameReport rep = r->render();
    EXPECT_EQ(rep.ran().size(), 4u);
    for (const auto& p : rep.passes)
        EXPECT_GE(p.gpuMs, 0.0) << p.name;
    EXPECT_TRUE(finiteInRange(readBack(r->texture("ao.raw"), 1), 0.0f, 1.0f));
}
