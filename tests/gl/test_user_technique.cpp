// User techniques (NAME.ao.glsl, renderer/techniques/user/): the examples give their built-in
// twins' ao.raw, a compile error names the user's file and line, and a parameter's value reaches
// the shader.
#include "gl/readback.h"
#include "gl_fixture.h"

#include "scene/scene.h"
#include "techniques/technique.h"
#include "techniques/user/user_pass.h"
#include "util/error.h"
#include "util/atomic_file.h"
#include "util/files.h"

#include <cstdio>
#include <filesystem>
#include <memory>

using namespace ssao;
using namespace ssaotest;

namespace {
class UserTechniques : public GlTest {};

std::vector<std::string> builtinIds() {
    std::vector<std::string> ids;
    for (const auto& t : techniques()) ids.push_back(t.id);
    return ids;
}

std::shared_ptr<const UserTechnique> example(const std::string& file) {
    const std::string path = std::string(SSAOLAB_SOURCE_DIR) + "/examples/techniques/" + file;
    const std::string text = readRegularFile(path, "user technique", kMaxUserFileBytes);
    return std::make_shared<UserTechnique>(loadUserTechnique(text, path, builtinIds()));
}

std::vector<double> defaults(const UserTechnique& t) {
    std::vector<double> v;
    for (const auto& p : t.header.params) v.push_back(p.def);
    return v;
}

void useUser(Renderer& r, std::shared_ptr<const UserTechnique> t, std::vector<double> values, AoNoise noise) {
    r.setTechniquePasses([t, values, noise](const Chain& c) {
        std::vector<std::unique_ptr<Pass>> passes;
        passes.push_back(std::make_unique<UserAoPass>(c, t, values, noise));
        return passes;
    });
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
    useUser(*r, t, defaults(*t), noise);
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
    useUser(*r, t, defaults(*t), AoNoise::Ign);
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
    auto r = makeRenderer(loadScene("builtin:showcase"), s, 96, 72);
    std::vector<double> values = defaults(*t);
    useUser(*r, t, values, AoNoise::Ign);
    const Image wide = aoRaw(*r);
    ASSERT_EQ(t->header.params[2].name, "radius_multiplier");
    values[2] = 0.3; // a shorter search: less occlusion
    useUser(*r, t, values, AoNoise::Ign);
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
    useUser(*r, t, defaults(*t), AoNoise::None);
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
