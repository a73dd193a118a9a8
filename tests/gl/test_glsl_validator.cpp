// Every shader variant the program builds also compiles with Khronos' reference front end
// (Debian's glslangValidator, glslang-tools): GLSL that only Mesa accepts would fail on another
// driver, and no GPU is needed to find out. The variants are the ones the renderer really builds
// while every technique runs at each of its rows' limits, with every shared mode, the inspector's
// INSPECT replay and the display mapping of the previews.
#include "gl_fixture.h"
#include "scene/load/load_scene.h"

#include "display/capture.h"
#include "scene/scene.h"
#include "techniques/technique.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

using namespace ssao;
using namespace ssaotest;

namespace {
class GlslValidator : public GlTest {};

// Runs glslangValidator on one preprocessed stage; "" when it compiles, else its output.
std::string validate(const std::string& source, const std::string& stage, const std::string& name) {
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/glslang";
    std::filesystem::create_directories(dir);
    const std::string path = dir + "/" + name + "." + stage;
    std::ofstream(path) << source;
    const std::string log = path + ".log";
    const std::string cmd = "glslangValidator -S " + stage + " '" + path + "' > '" + log + "' 2>&1";
    const int rc = std::system(cmd.c_str());
    std::ifstream in(log);
    std::string out((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return rc == 0 ? "" : (out.empty() ? "glslangValidator failed to run (install glslang-tools)" : out);
}
} // namespace

TEST_F(GlslValidator, EveryVariantTheRendererBuildsCompilesWithGlslang) {
    ASSERT_EQ(std::system("glslangValidator --version > /dev/null 2>&1"), 0)
        << "glslangValidator is missing: .ci/install-deps.sh installs glslang-tools";
    const Scene scene = loadScene("builtin:showcase");
    auto r = makeRenderer(scene, defaultSettings(), 64, 36);
    for (const auto& t : techniques())
        for (const Param& p : paramTable()) {
            if (p.group() != t.id && p.group() != "ao" && p.group() != "gbuffer" && p.group() != "denoise" &&
                p.group() != "temporal" && p.group() != "composite")
                continue;
            if (p.key == "ao.technique") continue;
            for (double v = p.min; v <= p.max; v += (p.type == Param::Type::Float || p.type == Param::Type::Int)
                                                       ? std::max(p.max - p.min, 1e-9)
                                                       : 1.0) {
                Settings s = defaultSettings();
                s.ao.technique = t.id;
                p.set(s, v);
                r->setSettings(s);
                r->render();
            }
            r->inspect(0, {20, 10}); // the INSPECT variant of the current technique
        }
    // The G-buffer variants that leave out what nothing reads (skip.unused_targets).
    for (const bool depthNormals : {false, true}) {
        Settings s = defaultSettings();
        if (depthNormals) s.ao.normals = NormalSource::Depth;
        r->setSettings(s);
        r->setWanted(std::set<std::string>{"ao.denoised"});
        r->invalidate(); // a clean G-buffer would keep its earlier targets
        r->render();
    }
    r->setWanted(std::nullopt);
    r->setSettings(defaultSettings());
    r->render();
    captureFrame(*r); // the display mapping of every buffer kind
    const std::vector<gl::ShaderLibrary::Variant> variants = r->shaders().variants();
    std::set<std::string> files;
    int n = 0;
    for (const auto& v : variants) {
        std::vector<std::string> table;
        const std::string vs = gl::preprocessShader(r->shaders().dir(), v.vert, v.defines, table);
        const std::string fs = gl::preprocessShader(r->shaders().dir(), v.frag, v.defines, table);
        std::string tag = std::to_string(n++);
        std::string defs;
        for (const auto& [k, val] : v.defines)
            defs += " " + k + "=" + val;
        EXPECT_EQ(validate(vs, "vert", tag), "") << v.vert << defs;
        EXPECT_EQ(validate(fs, "frag", tag), "") << v.frag << defs;
        files.insert(v.frag);
    }
    std::printf("%zu program variants (%zu fragment shaders) compile with glslangValidator\n", variants.size(),
                files.size());
    EXPECT_GT(variants.size(), 20u); // 5 techniques x (plain, INSPECT), G-buffer targets and encodings, ...
    EXPECT_GE(files.size(), 11u); // gbuffer, five techniques, denoise x2, temporal, composite, view, pyramid
}
