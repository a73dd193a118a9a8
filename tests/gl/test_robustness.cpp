// The numerical traps of SSAO (research-accuracy.md §4), each provoked on purpose.
#include "gl_fixture.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "util/error.h"

#include "../../shaders/include/bindings.h"

using namespace ssao;
using namespace ssaotest;

namespace {
class Robustness : public GlTest {};
} // namespace

TEST_F(Robustness, RandomVectorParallelToTheNormalGivesNoNaN) {
    // Look along the corner's wall: its normal (+z world) becomes view-space ±x, exactly the
    // fixed rotation vector (1,0,0) used with noise off, so Gram–Schmidt yields a zero tangent.
    Settings s = defaultSettings();
    s.kernel.noise = Noise::None;
    Camera cam{{6.0f, 1.5f, 0.0f}, {-6.0f, 1.0f, 0.0f}, {0, 1, 0}, 60.0f, 0.1f, 50.0f};
    Rendered r = render("builtin:corner", s, 200, 120, cam);
    long degenerate = 0;
    for (int y = 0; y < r.normal.height; ++y)
        for (int x = 0; x < r.normal.width; ++x)
            if (r.position.at(x, y, 3) > 0 && std::abs(r.normal.at(x, y, 0)) > 0.999f) ++degenerate;
    EXPECT_GT(degenerate, 1000) << "the wall must cover many pixels with n parallel to the random vector";
    EXPECT_TRUE(finiteInRange(r.aoRaw, 0.0f, 1.0f));
    EXPECT_TRUE(finiteInRange(r.ao, 0.0f, 1.0f));
}

TEST_F(Robustness, TinyRadiusWithoutBiasGivesNoNaN) {
    // radius → 0 with equal depths was 0/0 in the seeds' range check.
    for (const char* range : {"smoothstep", "hard", "off"}) {
        Settings s = defaultSettings();
        setParam(s, "ao.radius_mode", "world");
        setParam(s, "ao.radius", "0.0001");
        setParam(s, "kernel.bias", "0");
        setParam(s, "kernel.range_check", range);
        Rendered r = render("builtin:showcase", s, 160, 90);
        EXPECT_TRUE(finiteInRange(r.aoRaw, 0.0f, 1.0f)) << range;
        EXPECT_TRUE(finiteInRange(r.ao, 0.0f, 1.0f)) << range;
    }
}

TEST_F(Robustness, SamplesBehindTheCameraAndOffScreenAreGuarded) {
    // Eye 5 cm from the sphere with a 3 m radius: many samples project behind the eye (w <= 0)
    // or far off screen, for both off-screen policies.
    for (const char* off : {"skip", "clamp"}) {
        Settings s = defaultSettings();
        setParam(s, "ao.radius_mode", "world");
        setParam(s, "ao.radius", "3");
        setParam(s, "kernel.offscreen", off);
        setParam(s, "kernel.shape", "sphere");
        Camera cam{{-1.5f, 0.8f, -1.15f}, {-1.5f, 0.8f, -2.0f}, {0, 1, 0}, 90.0f, 0.01f, 60.0f};
        Rendered r = render("builtin:showcase", s, 160, 90, cam);
        EXPECT_TRUE(finiteInRange(r.aoRaw, 0.0f, 1.0f)) << off;
        EXPECT_TRUE(finiteInRange(r.ao, 0.0f, 1.0f)) << off;
    }
}

TEST_F(Robustness, EightBitNormalsAreRenormalised) {
    Settings a = defaultSettings(), b = defaultSettings();
    a.kernel.noise = b.kernel.noise = Noise::None;
    b.gbuffer.normalFormat = TargetFormat::RGBA8;
    Rendered ra = render("builtin:showcase", a, 160, 90), rb = render("builtin:showcase", b, 160, 90);
    // The decoded 8-bit normals are within quantisation of the float ones...
    double maxErr = 0;
    for (size_t p = 0; p < size_t(160 * 90); ++p) {
        if (ra.position.data[p * 4 + 3] == 0) continue;
        glm::vec3 na(ra.normal.data[p * 3], ra.normal.data[p * 3 + 1], ra.normal.data[p * 3 + 2]);
        glm::vec3 nb(rb.normal.data[p * 3], rb.normal.data[p * 3 + 1], rb.normal.data[p * 3 + 2]);
        maxErr = std::max(maxErr, double(glm::length(na - (nb * 2.0f - 1.0f))));
    }
    EXPECT_LT(maxErr, 0.01);
    // ...and the AO they produce is nearly the same.
    double sum = 0;
    for (size_t i = 0; i < ra.aoRaw.data.size(); ++i)
        sum += std::abs(ra.aoRaw.data[i] - rb.aoRaw.data[i]);
    EXPECT_LT(sum / double(ra.aoRaw.data.size()), 0.01);
}

TEST_F(Robustness, SkyPixelsAreUnoccludedAndCostNothing) {
    Rendered r = render("builtin:showcase", defaultSettings(), 160, 90);
    long sky = 0;
    for (size_t p = 0; p < size_t(160 * 90); ++p)
        if (r.position.data[p * 4 + 3] == 0) {
            ++sky;
            EXPECT_EQ(r.aoRaw.data[p], 1.0f);
        }
    EXPECT_GT(sky, 100) << "the showcase view includes some sky";
}

TEST_F(Robustness, ShaderCompileErrorsNameFileAndLine) {
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/broken_shaders";
    std::filesystem::create_directories(dir + "/include");
    std::ofstream(dir + "/include/util.glsl")
        << "float ok() { return 1.0; }\nfloat bad() { return undefined_symbol; }\n";
    std::ofstream(dir + "/main.frag") << "#version 450 core\n#include \"include/util.glsl\"\nout vec4 "
                                         "c;\nvoid main() { c = vec4(ok()); }\n";
    std::ofstream(dir + "/main.vert") << "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n";
    gl::ShaderLibrary lib(dir);
    try {
        lib.program("main.vert", "main.frag");
        FAIL() << "compile should fail";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("shaders/include/util.glsl:2"), std::string::npos) << e.what();
    }
    // The real shaders compile in every variant the passes use.
    gl::ShaderLibrary real(SSAOLAB_SHADER_DIR);
    EXPECT_NE(real.program("passes/gbuffer.vert", "passes/gbuffer.frag", {{"NORMAL_UNORM", "1"}}), 0u);
    EXPECT_NE(real.program("passes/fullscreen.vert", "techniques/kernel/kernel.frag"), 0u);
    EXPECT_NE(real.program("passes/fullscreen.vert", "techniques/kernel/kernel.frag", {{"INSPECT", "1"}}),
              0u);
    for (int mode : {SSAO_VIEW_COLOR, SSAO_VIEW_SCALAR, SSAO_VIEW_VECTOR, SSAO_VIEW_DIFF, SSAO_VIEW_SIGNED})
        EXPECT_NE(real.program("passes/fullscreen.vert", "display/view.frag", {{"VIEW_MODE", std::to_string(mode)}}), 0u);
    EXPECT_NE(real.program("passes/fullscreen.vert", "display/view.frag",
                           {{"VIEW_MODE", std::to_string(SSAO_VIEW_SCALAR)}, {"FALSE_COLOR", "1"}}),
              0u);
    // Without a mapping the view shader refuses to compile rather than guess one.
    EXPECT_THROW(real.program("passes/fullscreen.vert", "display/view.frag"), Error);
}

TEST_F(Robustness, DenoisedAoNeverRoundsPastOne) {
    // Seed 003's gaussian summed ones to 1.0000001-1.0000004 on every geometry pixel of
    // 2CylinderEngine (weights <= 1 in float, products rounded on the GPU). Every filter clamps.
    const char* scenes[] = {"/2CylinderEngine/2CylinderEngine.gltf", "/CornellBox/cornellBox.gltf"};
    for (const char* sc : scenes)
        for (const char* kind : {"gaussian", "box4", "box4c", "bilateral"}) {
            Settings s = preset("seed003");
            applyAssignment(s, std::string("denoise.kind=") + kind);
            Rendered r = render(std::string(SSAOLAB_SCENES_DIR) + sc, s, 320, 180);
            float hi = 0.0f;
            for (float v : r.ao.data)
                hi = std::max(hi, v);
            EXPECT_LE(hi, 1.0f) << sc << " " << kind;
            EXPECT_TRUE(finiteInRange(r.ao, 0.0f, 1.0f)) << sc << " " << kind;
        }
}
