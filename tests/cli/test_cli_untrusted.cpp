// Untrusted input, round four: code ssaolab compiles (a user's GLSL), files a browser loads (a
// scene for the web engines), settings files of those engines, camera paths and the techniques
// folder. Each class has its refusal here, one `ssaolab: error:` line before any work, or its
// limit in a child process (the GLSL compiler).
#include "cli/untrusted_child.h"
#include "cli_run.h"
#include "engine_test_util.h"
#include "engines/engine_settings_file.h"
#include "scene/load/browser_assets.h"
#include "util/error.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <zlib.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <tuple>

using namespace ssaotest;
namespace fs = std::filesystem;

namespace {

// A folder of its own under the test folder, emptied.
std::string freshDir(const std::string& name) {
    const std::string d = std::string(SSAOLAB_TEST_TMP) + "/" + name;
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

void writeFile(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

std::string technique(const std::string& body) {
    return "/*ssaolab\ninterface = 1;\nlabel = \"t\";\n*/\n" + body;
}

// A PNG signature and IHDR chunk claiming w x h (8-bit RGBA), then an empty IEND: what a header
// check reads; nothing to decode.
std::string pngHeader(uint32_t w, uint32_t h) {
    auto be = [](uint32_t v) { return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; };
    std::string ihdr = "IHDR" + be(w) + be(h) + std::string{8, 6, 0, 0, 0};
    const uLong crc = crc32(0, reinterpret_cast<const Bytef*>(ihdr.data()), uInt(ihdr.size()));
    const std::string iend = "IEND";
    return std::string("\x89PNG\r\n\x1a\n", 8) + be(13) + ihdr + be(uint32_t(crc)) + be(0) + iend +
           be(uint32_t(crc32(0, reinterpret_cast<const Bytef*>(iend.data()), 4)));
}

// The corner scene in `dir` as scene.gltf with `images` (the JSON array) added.
std::string cornerWithImages(const std::string& dir, const nlohmann::json& images) {
    nlohmann::json j = nlohmann::json::parse(slurp(writeCornerGltf("untrusted_corner.gltf")));
    j["images"] = images;
    const std::string file = dir + "/scene.gltf";
    writeFile(file, j.dump());
    return file;
}

// An N8AO tune result the reader accepts, for mutation.
nlohmann::json tunedN8ao() {
    return {{"engine", "n8ao"}, {"version", ssao::findEngine("n8ao").version},
            {"settings", {{"aoRadius", 1.2}, {"distanceFalloff", 1.0}, {"intensity", 2.0}}},
            {"search", {{"aoRadius", {{"x_make_peers_value", 1.5}}}}},
            {"cost_settings", {{"values", {{"aoSamples", 16}, {"halfRes", false}}}}}};
}

std::string settingsRefusal(const nlohmann::json& j) {
    try {
        ssao::parseTunedEngine(j, "tuned.json");
    } catch (const ssao::Error& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(CliUntrusted, ShaderTextTheCompilerCannotHoldIsRefusedInItsChildProcess) {
    // A size the body's checks cannot fold (a float constant through int()): 3e8 floats. The
    // compile gate's child reaches its memory limit; the command compiles nothing itself.
    const std::string dir = freshDir("untrusted_techniques");
    writeFile(dir + "/huge.ao.glsl", technique("const float F = 3e8;\nfloat ssaoUserAo() {\n    float a[int(F)];\n"
                                               "    a[0] = 0.5;\n    return clamp(a[0], 0.0, 1.0);\n}\n"));
    const CliRun r = ssaolab("render --technique-dir " + dir + " --set ao.technique=user.huge --size 32x18 --timing-frames 1 "
                             "--quiet --out " + outDir("untrusted_huge"),
                             "MESA_SHADER_CACHE_DISABLE=true");
    expectCleanFailure(r, dir + "/huge.ao.glsl: the GLSL compiler or driver failed in a child process limited to 1024 MiB");
    EXPECT_FALSE(fs::exists(outDir("untrusted_huge") + "/metrics.json"));
}

TEST(CliUntrusted, ACompilerCrashEndsTheChildNeverTheCaller) {
    // Raw GLSL past the body's checks (compile-glsl is the gate's own command): 64 000 terms in one
    // expression crash the driver's compiler on its stack.
    std::string sum = "k";
    for (int i = 1; i < 64000; ++i)
        sum += "+k";
    const std::string text = "#version 450 core\nlayout(location = 0) out vec4 o;\nvoid main() {\n    float k = 0.5;\n"
                             "    o = vec4(" + sum + ");\n}\n";
    const ssao::ChildVerdict v = ssao::runUntrustedChild(SSAOLAB_BINARY, {"compile-glsl", "crash.frag"}, text, "crash.frag");
    EXPECT_FALSE(v.ok);
    EXPECT_NE(v.message.find("crash.frag: the GLSL compiler or driver failed in a child process"), std::string::npos) << v.message;
    const ssao::ChildVerdict fine = ssao::runUntrustedChild(
        SSAOLAB_BINARY, {"compile-glsl", "fine.frag"},
        "#version 450 core\nlayout(location = 0) out vec4 o;\nvoid main() { o = vec4(0.5); }\n", "fine.frag");
    EXPECT_TRUE(fine.ok) << fine.message;
}

TEST(CliUntrusted, BodyLimitsNameTheFileAndLineBeforeAnyCompile) {
    std::string chain = "#define A0 k\n";
    for (int i = 1; i <= 40; ++i)
        chain += "#define A" + std::to_string(i) + " (A" + std::to_string(i - 1) + " + A" + std::to_string(i - 1) + ")\n";
    const std::string bomb = freshDir("untrusted_body_bomb"), moved = freshDir("untrusted_body_moved");
    writeFile(bomb + "/bomb.ao.glsl", technique(chain + "float ssaoUserAo() {\n    float k = 0.5;\n    return A40;\n}\n"));
    writeFile(moved + "/moved.ao.glsl", technique("#line 5 1\nfloat ssaoUserAo() {\n    return 1.0 +;\n}\n"));
    const auto start = std::chrono::steady_clock::now();
    for (const auto& [dir, name, why] : {std::make_tuple(bomb, std::string("bomb"), std::string(":48: its macros expand")),
                                         std::make_tuple(moved, std::string("moved"), std::string(":5: #line is not available"))}) {
        const CliRun r = ssaolab("render --technique-dir " + dir + " --set ao.technique=user." + name +
                                 " --size 32x18 --quiet --out " + outDir("untrusted_" + name));
        EXPECT_EQ(r.exitCode, 1) << r.err;
        EXPECT_NE(r.err.find("ssaolab: error: technique user." + name + " was not loaded: " + dir + "/" + name + ".ao.glsl" + why),
                  std::string::npos)
            << r.err;
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
}

TEST(CliUntrusted, EngineSettingsAreCheckedAgainstTheirTable) {
    EXPECT_EQ(settingsRefusal(tunedN8ao()), "");
    struct Case {
        std::string field, key;
        nlohmann::json value;
        std::string why;
    };
    const std::vector<Case> cases = {
        {"cost_settings", "aoSamples", 1e9, "cost_settings.values.aoSamples = 1e+09 is outside aoSamples's range [1, 64]"},
        {"cost_settings", "aoSamples", -5, "is outside aoSamples's range [1, 64]"},
        {"cost_settings", "aoSamples", 1e308, "is outside aoSamples's range"},
        {"cost_settings", "aoSamples", 2.5, "must be an integer in [1, 64]"},
        {"cost_settings", "halfRes", 1, "must be true or false"},
        {"settings", "intensity", 1e308, "settings.intensity = 1e+308 is outside intensity's range [0, 10]"},
        {"settings", "intensity", "2", "must be a finite number in [0, 10]"},
        {"settings", "aoSamples", 0, "is outside aoSamples's range"},
    };
    for (const Case& c : cases) {
        nlohmann::json j = tunedN8ao();
        (c.field == "settings" ? j["settings"] : j["cost_settings"]["values"])[c.key] = c.value;
        const std::string e = settingsRefusal(j);
        EXPECT_NE(e.find("tuned engine settings tuned.json: " + c.field), std::string::npos) << c.key << ": " << e;
        EXPECT_NE(e.find(c.why), std::string::npos) << c.key << ": " << e;
    }
    nlohmann::json factor = tunedN8ao();
    factor["search"]["aoRadius"]["x_make_peers_value"] = 1e300;
    EXPECT_NE(settingsRefusal(factor).find("search.aoRadius.x_make_peers_value = 1e+300 is outside what a tune can fit, (0, 1000000]"),
              std::string::npos)
        << settingsRefusal(factor);
    factor["search"]["aoRadius"]["x_make_peers_value"] = 0; // a log search never reaches 0
    EXPECT_NE(settingsRefusal(factor).find("outside what a tune can fit"), std::string::npos) << settingsRefusal(factor);
    factor["search"]["aoRadius"]["x_make_peers_value"] = 9; // past the search range [0.25, 4]: a widened wall
    EXPECT_EQ(settingsRefusal(factor), "") << settingsRefusal(factor);

    // bench --engine-settings reads through the same function: one line, before any browser.
    nlohmann::json bad = tunedN8ao();
    bad["cost_settings"]["values"]["aoSamples"] = 1e9;
    const std::string file = writeTemp("untrusted_n8ao.json", bad.dump());
    const std::string scene = writeCornerGltf("untrusted_engine_scene.gltf");
    expectCleanFailure(ssaolab("bench --scene " + scene + " --engine-settings " + file + " --size 32x18 --out " +
                               outDir("untrusted_engine_settings")),
                       "cost_settings.values.aoSamples = 1e+09 is outside aoSamples's range [1, 64]");
}

TEST(CliUntrusted, WhatTheEnginesBrowserWouldLoadIsCheckedBeforeItStarts) {
    const std::string base = freshDir("untrusted_browser");
    fs::create_directories(base + "/scn");
    fs::create_directories(base + "/scn-private");
    writeFile(base + "/scn-private/secret.png", pngHeader(4, 4));
    writeFile(base + "/scn/big.png", pngHeader(16384, 16384));
    writeFile(base + "/scn/ok.png", pngHeader(64, 64));
    struct Case {
        std::string uri, why;
    };
    const std::vector<Case> cases = {
        {"http://127.0.0.1:1/x.png", "image 0: 'http://127.0.0.1:1/x.png' is a network or absolute URI"},
        {"//example.com/x.png", "is a network or absolute URI"},
        {"/etc/passwd", "is a network or absolute URI"},
        {"..%2Fscn-private%2Fsecret.png", "leaves the scene's folder"},
        {"%2e%2e/scn-private/secret.png", "leaves the scene's folder"},
        {"../scn-private/secret.png", "leaves the scene's folder"},
        {"big.png", "image 0 is 16384x16384 pixels: past the budget of 64 M pixels"},
        // Read as big.png by the browser and by the harness, as another file by a plain decode.
        {"big.png?x", "holds a '?', '#', '+' or a control character"},
        {"big.png#x", "holds a '?', '#', '+' or a control character"},
        {"ok+big.png", "holds a '?', '#', '+' or a control character"},
        {".\t./ok.png", "holds a '?', '#', '+' or a control character"},
        {".", "names the scene's folder"},
    };
    for (const Case& c : cases) {
        const std::string scene = cornerWithImages(base + "/scn", {{{"uri", c.uri}}});
        std::string e;
        try {
            ssao::checkBrowserAssets(scene);
        } catch (const ssao::Error& err) {
            e = err.what();
        }
        EXPECT_NE(e.find(c.why), std::string::npos) << c.uri << ": " << e;
        EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    }
    writeFile(base + "/scn/big.png?x", pngHeader(4, 4)); // the file a plain decode would budget
    for (const std::string uri : {"ok.png", "./ok.png", "%6Fk.png"}) {
        const std::string ok = cornerWithImages(base + "/scn", {{{"uri", uri}}});
        EXPECT_NO_THROW(ssao::checkBrowserAssets(ok)) << uri;
    }

    // tune --engine says so in one line, before it looks for a browser or traces a reference.
    const std::string hostile = cornerWithImages(base + "/scn", {{{"uri", "..%2Fscn-private%2Fsecret.png"}}});
    expectCleanFailure(ssaolab("tune --engine n8ao --scene " + hostile + " --size 32x18 --out " + base + "/t.json", "PATH=/nonexistent"),
                       "leaves the scene's folder");
    const std::string big = cornerWithImages(base + "/scn", {{{"uri", "big.png"}}});
    expectCleanFailure(ssaolab("bench --scene " + big + " --engines n8ao --size 32x18 --out " + base + "/b"),
                       "--max-mask-mpix");
}

TEST(CliUntrusted, ACameraPathIsBudgetedBeforeAnyWork) {
    const auto start = std::chrono::steady_clock::now();
    expectCleanFailure(ssaolab("render --motion --motion-frames 64 --size 2048x2048 --out " + outDir("untrusted_motion")),
                       "motion: 1 path of 64 frames at 2048x2048 keep 7168 MiB at once, over --motion-max-mib 2048");
    expectCleanFailure(ssaolab("tune --objective motion --views 4 --motion-frames 32 --size 1024x1024 --out " +
                               outDir("untrusted_motion_tune") + ".json"),
                       "4 paths of 32 frames");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
    EXPECT_FALSE(fs::exists(outDir("untrusted_motion") + "/metrics.json"));
}

TEST(CliUntrusted, TuneEngineRefusesAnOutputInAMissingFolderBeforeItTunes) {
    const std::string scene = writeCornerGltf("untrusted_missing_out.gltf");
    expectCleanFailure(ssaolab("tune --engine n8ao --scene " + scene + " --size 32x18 --out " + outDir("untrusted_no_such") +
                               "/sub/t.json"),
                       "the folder " + outDir("untrusted_no_such") + "/sub does not exist");
}

TEST(CliUntrusted, AFullTechniquesFolderLoadsItsFirstFilesAndEveryBuiltIn) {
    const std::string dir = freshDir("untrusted_full_folder");
    for (int i = 0; i < 300; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "t%03d", i);
        writeFile(dir + "/" + name + ".ao.glsl", technique("float ssaoUserAo() {\n    return 1.0;\n}\n"));
    }
    const CliRun builtin = ssaolab("render --technique-dir " + dir + " --size 32x18 --timing-frames 1 --quiet --out " +
                                   outDir("untrusted_full_builtin"));
    EXPECT_EQ(builtin.exitCode, 0) << builtin.err;
    EXPECT_EQ(std::count(builtin.err.begin(), builtin.err.end(), '\n'), 1) << builtin.err; // one warning for all 44
    EXPECT_NE(builtin.err.find("44 technique files past the first 256 by name are not loaded (t256.ao.glsl ... t299.ao.glsl)"),
              std::string::npos)
        << builtin.err;
    const CliRun first = ssaolab("render --technique-dir " + dir + " --set ao.technique=user.t255 --size 32x18 "
                                 "--timing-frames 1 --quiet --out " + outDir("untrusted_full_first"));
    EXPECT_EQ(first.exitCode, 0) << first.err;
    const CliRun extra = ssaolab("render --technique-dir " + dir + " --set ao.technique=user.t256 --size 32x18 --quiet --out " +
                                 outDir("untrusted_full_extra"));
    EXPECT_EQ(extra.exitCode, 1);
    EXPECT_NE(extra.err.find("t256.ao.glsl: not loaded: the technique folder holds more than 256 technique files"),
              std::string::npos)
        << extra.err;
}
