// User techniques (NAME.ao.glsl, renderer/techniques/user/): the examples give their built-in
// twins' ao.raw, a compile error names the user's file and line, and a parameter's value reaches
// the shader.
#include "closed_form.h"
#include "scene/load/load_scene.h"
#include "gl/readback.h"
#include "gl_fixture.h"

#include "scene/scene.h"
#include "techniques/technique.h"
#include "settings/params.h"
#include "techniques/user/user_technique.h"
#include "util/error.h"
#include "util/atomic_file.h"
#include "util/files.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

using namespace ssao;
using namespace ssaotest;

namespace {
class UserTechniques : public GlTest {};

std::vector<std::string> builtinIds() {
    return builtinTechniqueIds();
}

std::shared_ptr<const UserTechnique> example(const std::string& file) {
    const std::string path = std::string(SSAOLAB_SOURCE_DIR) + "/examples/techniques/" + file;
    const std::string text = readRegularFile(path, "user technique", kMaxUserFileBytes);
    return std::make_shared<UserTechnique>(loadUserTechnique(text, path, builtinIds()));
}

// `s` with `t` registered and chosen in place of its technique, at the header's defaults.
Settings useUser(Settings s, std::shared_ptr<const UserTechnique> t, AoNoise noise) {
    setUserTechniques({t});
    s.ao.technique = userTechniqueId(t->name);
    for (size_t i = 0; i < aoNoiseChoices().size(); ++i)
        if (aoNoiseChoices()[i].second == noise)
            setParam(s, s.ao.technique + "." + kUserNoiseRow, aoNoiseChoices()[i].first);
    return s;
}

Image aoRaw(Renderer& r) {
    r.render();
    return readBack(r.texture("ao.raw"), 1);
}

// ao.raw of the settings' built-in technique and of `t` standing in for it, on the same view.
void compare(const std::string& sceneSpec, const Settings& s, std::shared_ptr<const UserTechnique> t, AoNoise noise,
             Image& builtin, Image& user) {
    const Scene scene = loadScene(sceneSpec);
    auto r = makeRenderer(scene, s, 96, 72);
    builtin = aoRaw(*r);
    r->setSettings(useUser(s, t, noise));
    user = aoRaw(*r);
}

std::string cornell() { return std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/cornellBox.gltf"; }

} // namespace

TEST_F(UserTechniques, TheLearnOpenGlExampleGivesTheKernelTechniquesAoAtItsPreset) {
    const Settings s = preset("learnopengl");
    ASSERT_EQ(s.ao.technique, "kernel");
    for (const std::string& scene : {cornell(), std::string("builtin:showcase")}) {
        Image builtin, user;
        compare(scene, s, example("learnopengl.ao.glsl"), AoNoise::None, builtin, user);
        const double d = maxAbsDiff(builtin, user);
        std::printf("learnopengl.ao.glsl vs kernel @learnopengl on %s: max |diff| %.3g, mean AO %.4f\n",
                    scene.c_str(), d, stats(builtin).mean);
        EXPECT_LE(d, 1e-5) << scene;
        EXPECT_LT(stats(builtin).mean, 0.99) << scene; // something is occluded: the comparison means something
    }
}

TEST_F(UserTechniques, TheXeGtaoExampleGivesTheGtaoTechniquesAoAtHighQuality) {
    Settings s = defaultSettings();
    s.ao.technique = "gtao";
    s.gtao.quality = GtaoQuality::High;
    s.gtao.pyramid = false;
    for (const AoNoise noise : {AoNoise::Ign, AoNoise::Blue}) {
        s.gtao.noise = noise;
        for (const std::string& scene : {cornell(), std::string("builtin:showcase")}) {
            Image builtin, user;
            compare(scene, s, example("xegtao.ao.glsl"), noise, builtin, user);
            const double d = maxAbsDiff(builtin, user);
            std::printf("xegtao.ao.glsl vs gtao (high, noise %d) on %s: max |diff| %.3g, mean AO %.4f\n", int(noise),
                        scene.c_str(), d, stats(builtin).mean);
            EXPECT_LE(d, 1e-5) << scene << " noise " << int(noise);
            EXPECT_LT(stats(builtin).mean, 0.99) << scene;
        }
    }
}

TEST_F(UserTechniques, ACompileErrorIsOneLineNamingTheUsersFileAndLine) {
    const std::string text = "/*ssaolab\ninterface = 1;\nuniform float k < ui_min = 0; ui_max = 1; > = 0.5;\n*/\n"
                             "float ssaoUserAo() {\n"
                             "    return k * undeclared_thing;\n" // line 6
                             "}\n";
    auto t = std::make_shared<UserTechnique>(loadUserTechnique(text, "mine/broken.ao.glsl", builtinIds()));
    auto r = makeRenderer(loadScene("builtin:plane"), defaultSettings(), 64, 36);
    r->setSettings(useUser(defaultSettings(), t, AoNoise::Ign));
    try {
        r->render();
        FAIL() << "a body that does not compile rendered";
    } catch (const Error& e) {
        const std::string m = e.what();
        std::printf("%s\n", m.c_str());
        EXPECT_EQ(m.rfind("mine/broken.ao.glsl:6: ", 0), 0u) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
        EXPECT_NE(m.find("undeclared_thing"), std::string::npos) << m;
    }
}

TEST_F(UserTechniques, AParametersValueReachesTheShaderAndReRunsThePass) {
    auto t = example("xegtao.ao.glsl");
    Settings s = defaultSettings();
    s.ao.technique = "gtao";
    s = useUser(s, t, AoNoise::Ign);
    auto r = makeRenderer(loadScene("builtin:showcase"), s, 96, 72);
    const Image wide = aoRaw(*r);
    ASSERT_EQ(t->header.params[2].name, "radius_multiplier");
    setParam(s, "user.xegtao.radius_multiplier", "0.3"); // a shorter search: less occlusion
    r->setSettings(s);
    const Image narrow = aoRaw(*r);
    std::printf("xegtao radius_multiplier 1.457: mean AO %.4f; 0.3: %.4f\n", stats(wide).mean, stats(narrow).mean);
    EXPECT_GT(stats(narrow).mean, stats(wide).mean + 0.01);
}

TEST_F(UserTechniques, TheBodyMayNotIncludeNorNameAParameterAsAnInterfaceGlobal) {
    const std::string head = "/*ssaolab\ninterface = 1;\n";
    try {
        loadUserTechnique(head + "*/\n#include \"include/frame.glsl\"\nfloat ssaoUserAo() { return 1.0; }\n",
                          "a.ao.glsl", builtinIds());
        FAIL() << "an #include was accepted";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("a.ao.glsl:4: ", 0), 0u) << e.what();
    }
    try {
        loadUserTechnique(head + "uniform float frame < ui_min = 0; ui_max = 1; > = 0;\n*/\nfloat ssaoUserAo() { return 1.0; }\n",
                          "b.ao.glsl", builtinIds());
        FAIL() << "a parameter named frame was accepted";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("b.ao.glsl:3: ", 0), 0u) << e.what();
    }
}

TEST_F(UserTechniques, TheInspectorShowsTheUsersTapsAndSums) {
    const Settings s = preset("learnopengl");
    auto t = example("learnopengl.ao.glsl");
    auto r = makeRenderer(loadScene("builtin:showcase"), s, 96, 72);
    r->render();
    const auto builtin = r->inspect(0, {48, 50});
    r->setSettings(useUser(s, t, AoNoise::None));
    r->render();
    const auto user = r->inspect(0, {48, 50});
    ASSERT_TRUE(builtin && user);
    ASSERT_TRUE(user->geometry);
    EXPECT_EQ(user->taps.size(), 64u); // one per kernel point (ssaoRecordTap)
    EXPECT_EQ(user->taps.size(), builtin->taps.size());
    EXPECT_EQ(user->normaliser, 64.0f);
    EXPECT_FLOAT_EQ(user->occlusion, builtin->occlusion);
    EXPECT_FLOAT_EQ(user->ao, builtin->ao);
    EXPECT_FLOAT_EQ(user->radius, builtin->radius);
}

TEST_F(UserTechniques, TheExamplesAssembledCompileWithGlslang) {
    // Khronos' front end, as GlslValidator checks the built-ins: GLSL only Mesa accepts would fail elsewhere.
    ASSERT_EQ(std::system("glslangValidator --version > /dev/null 2>&1"), 0) << "install glslang-tools";
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/glslang_user";
    std::filesystem::create_directories(dir);
    for (const std::string file : {"learnopengl.ao.glsl", "xegtao.ao.glsl"})
        for (const bool inspect : {false, true}) {
            auto t = example(file);
            const gl::Sources sources{{t->path, userShaderSource(*t)}};
            gl::Defines defines{{"AO_NOISE", "0"}};
            if (inspect) defines.push_back({"INSPECT", "1"});
            std::vector<std::string> table;
            const std::string path = dir + "/" + file + (inspect ? ".inspect" : "") + ".frag";
            writeFileAtomically(path, gl::preprocessShader(SSAOLAB_SHADER_DIR, t->path, defines, table, &sources));
            const std::string cmd = "glslangValidator -S frag '" + path + "' > '" + path + ".log' 2>&1";
            EXPECT_EQ(std::system(cmd.c_str()), 0) << readRegularFile(path + ".log", "glslang log");
        }
}

TEST_F(UserTechniques, TheOwnTechniquePagesExampleHoldsThePhysics) {
    // docs/own-technique.md's first glsl block, as a reader saves it: it loads, compiles (both
    // variants, the inspector's too), keeps an open plane open and darkens toward a wall.
    const std::string page = readRegularFile(std::string(SSAOLAB_SOURCE_DIR) + "/docs/own-technique.md", "page");
    const size_t from = page.find("```glsl\n");
    ASSERT_NE(from, std::string::npos);
    const size_t to = page.find("\n```", from + 8);
    const std::string text = page.substr(from + 8, to - from - 8) + "\n";
    auto t = std::make_shared<UserTechnique>(loadUserTechnique(text, "mine.ao.glsl", builtinIds()));
    Settings s = useUser(defaultSettings(), t, AoNoise::Ign);
    s.ao.radiusMode = RadiusMode::World;
    s.ao.radius = 1.0f;
    Rendered plane = render("builtin:plane", s, 160, 120);
    ASSERT_TRUE(finiteInRange(plane.aoRaw, 0.0f, 1.0f));
    const double planeMean = geometryMean(plane, plane.ao);
    const CornerProfile corner = cornerProfile(s);
    std::printf("the page's example: plane AO %.4f; corner RMSE %.4f, at the wall %.3f, beyond R %.3f\n", planeMean,
                corner.rmse, corner.atWall, corner.far);
    EXPECT_GE(planeMean, 0.99);
    EXPECT_LT(corner.atWall, corner.far - 0.2);
    EXPECT_GE(corner.far, 0.95);
    EXPECT_LT(corner.rmse, 0.1);
    auto r = makeRenderer(loadScene("builtin:showcase"), s, 96, 72);
    r->render();
    const auto in = r->inspect(0, {48, 40});
    ASSERT_TRUE(in && in->geometry);
    EXPECT_FALSE(in->taps.empty()); // its ssaoRecordTap calls reach the inspector
}

TEST_F(UserTechniques, EveryDenoiserResolutionAndTheTemporalFilterApplyAsToItsTwin) {
    // The stages after the AO pass are the pipeline's: with the twin's AO, the user technique's
    // denoised frame is the twin's under each of them.
    const auto t = example("xegtao.ao.glsl");
    const Scene scene = loadScene("builtin:showcase");
    for (const std::string& stage : {"ao.resolution=half denoise.kind=bilateral", "ao.resolution=quarter denoise.kind=gaussian",
                                     "denoise.kind=box4 temporal.enabled=true temporal.frames=4"}) {
        Settings s = defaultSettings();
        s.ao.technique = "gtao";
        s.gtao.quality = GtaoQuality::High;
        s.gtao.pyramid = false;
        std::istringstream sets(stage);
        for (std::string a; sets >> a;) applyAssignment(s, a);
        auto r = makeRenderer(scene, s, 96, 72);
        for (int f = 0; f < 4; ++f) r->render();
        const Image builtin = readBack(r->texture("ao.denoised"), 1);
        r->setSettings(useUser(s, t, AoNoise::Ign));
        for (int f = 0; f < 4; ++f) r->render();
        const Image user = readBack(r->texture("ao.denoised"), 1);
        const double d = maxAbsDiff(builtin, user);
        std::printf("xegtao.ao.glsl vs gtao high, %s: max |diff| of ao.denoised %.3g, mean %.4f\n", stage.c_str(), d,
                    stats(user).mean);
        EXPECT_LE(d, 1e-5) << stage;
        EXPECT_TRUE(finiteInRange(user, 0.0f, 1.0f)) << stage;
        EXPECT_LT(stats(user).mean, 0.99) << stage;
    }
}
