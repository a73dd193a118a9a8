// Whole program: the ssaolab binary on real scenes and on bad input.
#include "cli_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <sys/wait.h>

#include <regex>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

using namespace ssaotest;

TEST(Cli, EveryHeadlessCommandFailsOnAGlError) {
    // One headless runner under every command (app/cli/headless_runner.h): a GL error raised during the
    // run (the runner's test hook) ends each with exit 1 and one `ssaolab: error:` line naming it.
    const std::string sweep = writeTemp("gl_error_sweep.json", R"({"groups": [{"name": "one", "set": {"ao.technique": "sao"}}]})");
    const std::string out = outDir("gl_error");
    const std::vector<std::string> commands = {
        "render --scene builtin:corner --size 64x36 --timing-frames 1 --quiet --out " + out,
        "bench --scene builtin:corner --size 64x36 --views 1 --frames 1 --warmup 0 --reference-rays 4 --no-plot "
        "--quiet --sweep " + sweep + " --out " + out,
        "tune --technique sao --scene builtin:corner --size 64x36 --views 2 --rounds 1 --grid 3 "
        "--reference-rays 4 --knob sao.bias --quiet --out " + out + "/tuned.json",
        "stress --scene builtin:corner --technique sao --size 64x36 --quiet --out " + out,
        "skips --scene builtin:corner --size 64x36 --frames 1 --reference-rays 4 --quiet --out " + out};
    for (const std::string& c : commands) {
        const CliRun r = ssaolab(c, "SSAOLAB_TEST_GL_ERROR=1");
        EXPECT_FALSE(r.signaled) << c;
        EXPECT_EQ(r.exitCode, 1) << c << "\n" << r.err;
        size_t lines = 0;
        for (size_t at = r.err.find("ssaolab: error: "); at != std::string::npos; at = r.err.find("ssaolab: error: ", at + 1))
            ++lines;
        EXPECT_EQ(lines, 1u) << c << "\n" << r.err;
        EXPECT_NE(r.err.find("ssaolab: error: OpenGL reported"), std::string::npos) << c << "\n" << r.err;
        // And without the hook the same command runs through.
        EXPECT_EQ(ssaolab(c).exitCode, 0) << c;
    }
}

TEST(Cli, HelpDescribesCommands) {
    CliRun r = ssaolab("--help");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("render"), std::string::npos);
    EXPECT_NE(r.out.find("params"), std::string::npos);
    r = ssaolab("render --help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* opt : {"--scene", "--preset", "--set", "--size", "--camera", "--out"})
        EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
    r = ssaolab("params");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("ao.radius_scene"), std::string::npos);
    EXPECT_NE(r.out.find("applies when denoise.kind = gaussian"), std::string::npos); // sigma's condition
}

TEST(Cli, RenderWritesEveryBufferAndMetrics) {
    const std::string out = outDir("showcase");
    std::filesystem::remove_all(out);
    CliRun r = ssaolab(
        "render --scene builtin:showcase --preset learnopengl --set ao.radius=0.8 --set kernel.shape=sphere "
        "--set denoise.kind=gaussian --size 320x180 --timing-frames 1 --out " +
        out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // One EXR per float buffer and one PNG per buffer, named after the frame graph's resources.
    for (const char* f :
         {"gbuffer.position.exr", "gbuffer.normal.exr", "gbuffer.depth.exr", "gbuffer.zbuffer.exr",
          "ao.raw.exr", "ao.denoised.exr", "gbuffer.position.png", "gbuffer.normal.png", "gbuffer.depth.png",
          "gbuffer.albedo.png", "ao.raw.png", "ao.denoised.png", "composite.png", "metrics.json"})
        EXPECT_TRUE(std::filesystem::exists(out + "/" + f)) << f;
    auto m = nlohmann::json::parse(slurp(out + "/metrics.json"));
    EXPECT_EQ(m["settings"]["ao"]["radius"], 0.8);
    EXPECT_EQ(m["settings"]["kernel"]["shape"], "sphere");
    EXPECT_EQ(m["settings"]["denoise"]["kind"], "gaussian");
    EXPECT_EQ(m["size"], nlohmann::json({320, 180}));
    EXPECT_EQ(m["passes_run"], nlohmann::json({"gbuffer", "ao", "denoise", "composite"}));
    for (auto& [name, b] : m["buffers"].items()) {
        EXPECT_EQ(b["nonfinite"], 0) << name;
        EXPECT_TRUE(b.contains("display_range")) << name;
    }
    EXPECT_EQ(m["buffers"]["ao.raw"]["size"], nlohmann::json({320, 180}));
    EXPECT_NEAR(m["radius"]["world_at_centre"].get<double>(), 0.8, 1e-6); // the preset's world radius
    for (const char* p : {"gbuffer", "ao", "denoise", "composite"})
        EXPECT_GE(m["gpu_ms"][p].get<double>(), 0.0) << p;
    EXPECT_FALSE(m["gl_renderer"].get<std::string>().empty());
    const double mn = m["ao"]["min"], mean = m["ao"]["mean"], mx = m["ao"]["max"];
    EXPECT_LE(0.0, mn);
    EXPECT_LE(mn, mean);
    EXPECT_LE(mean, mx);
    EXPECT_LE(mx, 1.0);
}

TEST(Cli, EveryThirdPartySceneRendersWithItsOwnCamera) {
    const auto files = ssaotest::sharedSceneFiles();
    for (const auto& f : files) {
        const std::string name = f.stem().string();
        const std::string out = outDir(name);
        // Default settings: the radius follows the scene; the point here is loading, cameras and finiteness.
        CliRun r =
            ssaolab("render --scene '" + f.string() + "' --size 256x144 --timing-frames 1 --out " + out);
        ASSERT_EQ(r.exitCode, 0) << name << ": " << r.err;
        auto m = nlohmann::json::parse(slurp(out + "/metrics.json"));
        // The file's first camera when it has one, else a view framing the bounds.
        const bool hasCamera = nlohmann::json::parse(slurp(f.string())).contains("cameras");
        EXPECT_EQ(m["camera"]["source"], hasCamera ? "file" : "framed") << name;
        for (auto& [k, b] : m["buffers"].items())
            EXPECT_EQ(b["nonfinite"], 0) << name << " " << k;
        EXPECT_GT(m["radius"]["pixels_at_centre"].get<double>(), 2.0)
            << name << ": the kernel is not sub-pixel";
        EXPECT_GT(m["geometry_pixels"].get<long>(), 256 * 144 / 100) << name << " is barely visible";
        EXPECT_GE(m["ao"]["min"].get<double>(), 0.0) << name;
        EXPECT_LE(m["ao"]["max"].get<double>(), 1.0) << name;
    }
    EXPECT_GE(files.size(), 8u);
}

TEST(Cli, BadInputGivesOneClearLineAndExitCodeOne) {
    const std::string out = " --out " + outDir("bad");
    expectCleanFailure(ssaolab("render --scene /nonexistent/missing.gltf" + out),
                       "scene file not found: /nonexistent/missing.gltf");
    expectCleanFailure(
        ssaolab("render --scene " + writeTemp("cli_corrupt.gltf", "{ \"asset\": [ broken") + out),
        "cannot load glTF");
    expectCleanFailure(ssaolab("render --scene builtin:nope" + out), "unknown built-in scene");
    expectCleanFailure(ssaolab("render --preset " + writeTemp("cli_bad.json", "{ not json") + out),
                       "is not valid JSON");
    expectCleanFailure(ssaolab("render --preset /nonexistent.json" + out), "preset file not found");
    expectCleanFailure(ssaolab("render --preset " + writeTemp("cli_unk.json", R"({"ao":{"radiu":1}})") + out),
                       "unknown key 'ao.radiu'");
    expectCleanFailure(ssaolab("render --set ao.bogus=1" + out), "unknown parameter 'ao.bogus'");
    expectCleanFailure(ssaolab("render --set ao.radius=-0.5" + out), "ao.radius: value -0.5 is out of range");
    expectCleanFailure(ssaolab("render --set kernel.samples=100000" + out), "kernel.samples");
    expectCleanFailure(ssaolab("render --set ao.technique=ssdo" + out), "'ssdo' is not one of kernel");
    expectCleanFailure(ssaolab("render --preset nonesuch" + out), "no preset named 'nonesuch'");
    expectCleanFailure(ssaolab("render --preset " + writeTemp("cli_size.json", R"({"size":[0,5]})") + out),
                       "size");
    expectCleanFailure(ssaolab("render --size 0x0" + out), "--size '0x0'");
    expectCleanFailure(ssaolab("render --size 16384x16384" + out),
                       "too large"); // refused before 9 GB of buffers
    expectCleanFailure(ssaolab("render --set ao.power=0x10" + out), "'0x10' is not a number");
    expectCleanFailure(ssaolab("render --set 'ao.power= 2'" + out), "is not a number");
    expectCleanFailure(ssaolab("render --depth standard --camera 0,0,5,0,0,0,0,1,0,60,0.1,inf" + out),
                       "an infinite far plane needs reversed depth");
    expectCleanFailure(ssaolab("render --camera 0,0,5,0,0,inf" + out), "'inf' is not a finite number");
    expectCleanFailure(ssaolab("render --projection fisheye" + out), "--projection");
    expectCleanFailure(ssaolab("render --depth logarithmic" + out), "--depth");
    expectCleanFailure(ssaolab("view --depth logarithmic"), "--depth");
    expectCleanFailure(
        ssaolab("render --preset " + writeTemp("cli_overflow.json", R"({"ao":{"power":1e999}})") + out),
        "is not valid JSON");
    expectCleanFailure(ssaolab("render --scene " + std::string(SSAOLAB_TEST_TMP) + out), "not a regular");
    // Option errors of the command line itself: the same one line and exit code 1.
    expectCleanFailure(ssaolab("render --timing-frames 0" + out), "--timing-frames");
    expectCleanFailure(ssaolab("render --clip weird" + out), "--clip");
    expectCleanFailure(ssaolab("render --bogus" + out), "--bogus");
    expectCleanFailure(ssaolab("bogus"), "bogus");
    expectCleanFailure(ssaolab("view --screenshot x.png"), "--screenshot needs --frames");
    expectCleanFailure(ssaolab("view --size 100000x100"), "--size '100000x100'");
    expectCleanFailure(ssaolab("render --size 640" + out), "--size '640'");
    expectCleanFailure(ssaolab("render --camera 1,2,3" + out), "--camera");
    expectCleanFailure(ssaolab("render --camera 0,0,0,0,0,0" + out), "eye and target coincide");
    // Issue 9's adversarial list: sscanf wrapped 4294967396 to 100; 1000 timing frames ran ~15 minutes;
    // near 1e-9 / far 1e9 rendered nothing and reported it as fully occluded; a shader error printed
    // the compiler's log over several lines; a scene that expands without bound exhausted memory.
    expectCleanFailure(ssaolab("render --size 4294967396x100" + out), "--size '4294967396x100'");
    expectCleanFailure(ssaolab("view --size 20000x20000"), "too large");
    expectCleanFailure(ssaolab("render --timing-frames 1000" + out), "--timing-frames");
    expectCleanFailure(ssaolab("render --depth standard --clip fixed --camera 0,0,5,0,0,0,0,1,0,60,1e-9,1e9" + out),
                       "far/near");
    {
        namespace fs = std::filesystem;
        const std::string bad = std::string(SSAOLAB_TEST_TMP) + "/broken_shaders_cli"; // not Robustness's folder
        fs::remove_all(bad);
        fs::copy(std::string(SSAOLAB_SOURCE_DIR) + "/shaders", bad, fs::copy_options::recursive);
        std::ofstream(bad + "/passes/composite.frag", std::ios::app) << "garbage(\n";
        expectCleanFailure(ssaolab("render --shaders " + bad + out), "composite.frag:");
    }
    expectCleanFailure(ssaolab("--max-triangles 10 render --scene '" + std::string(SSAOLAB_SCENES_DIR) +
                               "/CornellBox/cornellBox.gltf'" + out),
                       "budget of 10 triangles");
}

TEST(Cli, LensOptionsReachTheRenderAndItsMetrics) {
    // Reversed depth with an infinite far plane, and an orthographic view: rendered, finite, and
    // recorded in metrics.json's camera.
    const std::string a = outDir("lens_reversed"), b = outDir("lens_ortho");
    CliRun r = ssaolab("render --size 160x90 --timing-frames 1 --quiet --camera "
                       "3.2,2.4,3.6,-1.6,0.5,-3.2,0,1,0,60,0.01,inf --out " + a);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    nlohmann::json m = nlohmann::json::parse(slurp(a + "/metrics.json"));
    EXPECT_EQ(m["camera"]["depth"], "reversed");
    EXPECT_EQ(m["camera"]["far"], "inf");
    EXPECT_GT(m["geometry_pixels"].get<int>(), 160 * 90 / 4);
    EXPECT_GT(m["ao"]["mean"].get<double>(), 0.5);
    r = ssaolab("render --size 160x90 --timing-frames 1 --quiet --projection orthographic --out " + b);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    m = nlohmann::json::parse(slurp(b + "/metrics.json"));
    EXPECT_EQ(m["camera"]["projection"], "orthographic");
    EXPECT_LE(m["ao"]["max"].get<double>(), 1.0);
    EXPECT_GE(m["ao"]["min"].get<double>(), 0.0);
}

TEST(Cli, WarnsWhenNothingIsInViewOrTheRadiusIsSubPixel) {
    CliRun r =
        ssaolab("render --size 64x36 --timing-frames 1 --camera 0,0,-500,0,0,-1000 --out " + outDir("empty"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("no geometry in view"), std::string::npos) << r.out;
    // The article's 0.5 world units on the millimetre engine: under a pixel.
    r = ssaolab("render --size 320x180 --timing-frames 1 --preset learnopengl --scene '" +
                std::string(SSAOLAB_SCENES_DIR) + "/2CylinderEngine/2CylinderEngine.gltf' --out " +
                outDir("subpixel"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("flat grey"), std::string::npos) << r.out;
}

TEST(Cli, NoGlIsAClearError) {
    // Point EGL at a vendor library that does not exist: no platform can give a context.
    CliRun r = ssaolab("render --size 32x32 --out " + outDir("nogl") + " 2>&1");
    ASSERT_EQ(r.exitCode, 0) << r.out; // sanity: it works normally
    std::string env = "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json ";
    std::string cmd = env + "'" + SSAOLAB_BINARY + "' render --size 32x32 --out " + outDir("nogl") + " 2>" +
                      SSAOLAB_TEST_TMP + "/nogl.err";
    int status = std::system(cmd.c_str());
    EXPECT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 1);
    std::string err = slurp(std::string(SSAOLAB_TEST_TMP) + "/nogl.err");
    EXPECT_NE(err.find("no GL"), std::string::npos) << err;
}

TEST(Cli, WindowAppUnderXvfbRendersFramesAndExitsCleanly) {
    // The real window (GLFW + GLX on Xvfb, llvmpipe), as a user would start it.
    const std::string shot = std::string(SSAOLAB_TEST_TMP) + "/app_shot.png";
    std::filesystem::remove(shot);
    const std::string presets = std::string(SSAOLAB_TEST_TMP) + "/xvfb_presets";
    CliRun r = ssaolab("--help"); // sanity
    ASSERT_EQ(r.exitCode, 0);
    const std::string cmd = "'" + std::string(SSAOLAB_BINARY) + "' view --size 1200x700 --frames 6 --screenshot " + shot +
                            " --preset-dir " + presets + " >" + SSAOLAB_TEST_TMP + "/xvfb.out 2>&1";
    ASSERT_EQ(underXvfb(cmd, "shot"), 0) << slurp(std::string(SSAOLAB_TEST_TMP) + "/xvfb.out");
    ASSERT_TRUE(std::filesystem::exists(shot));
    // The screenshot shows a UI and rendered buffers: many distinct grey levels, not a blank frame.
    std::ifstream in(shot, std::ios::binary);
    std::string png((std::istreambuf_iterator<char>(in)), {});
    EXPECT_GT(png.size(), 20000u);
}

TEST(Cli, NoDisplayFallsBackToHeadlessWithAHint) {
    // `ssaolab` with no arguments and no display: says how to get a window, renders ./out/.
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/nodisplay";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string cmd =
        "cd " + dir + " && env -u DISPLAY -u WAYLAND_DISPLAY '" + SSAOLAB_BINARY + "' >run.out 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << slurp(dir + "/run.out");
    const std::string text = slurp(dir + "/run.out");
    EXPECT_NE(text.find("no display"), std::string::npos) << text;
    EXPECT_NE(text.find("xvfb-run"), std::string::npos) << text;
    EXPECT_TRUE(std::filesystem::exists(dir + "/out/composite.png"));
    EXPECT_TRUE(std::filesystem::exists(dir + "/out/metrics.json"));
    // `ssaolab view` without a display is one clear error line.
    const std::string cmd2 = "env -u DISPLAY -u WAYLAND_DISPLAY '" + std::string(SSAOLAB_BINARY) +
                             "' view --frames 1 >" + dir + "/view.out 2>&1";
    const int status = std::system(cmd2.c_str());
    EXPECT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 1);
    const std::string err = slurp(dir + "/view.out");
    EXPECT_NE(err.find("no display"), std::string::npos) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
}

TEST(Cli, RenderWithReferenceWritesTheErrorAndCachesTheTrace) {
    const std::string out = outDir("reference"), cache = std::string(SSAOLAB_TEST_TMP) + "/cli_refcache";
    std::filesystem::remove_all(out);
    std::filesystem::remove_all(cache);
    const std::string args = "render --scene " + std::string(SSAOLAB_SCENES_DIR) +
                             "/CornellBox/cornellBox.gltf --size 160x90 --timing-frames 1 --reference "
                             "--reference-rays 64 --out " +
                             out;
    // The cache goes to a folder of the test's own (ssaolab() has no environment hook).
    const std::string cmd =
        "SSAOLAB_CACHE_DIR=" + cache + " '" + SSAOLAB_BINARY + "' " + args + " >" + out + ".log 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(out + ".log");
    for (const char* f : {"ao_reference.exr", "ao_reference.png", "ao_reference_stderr.exr", "error.exr",
                          "error.png", "metrics.json"})
        EXPECT_TRUE(std::filesystem::exists(out + "/" + f)) << f;
    auto m = nlohmann::json::parse(slurp(out + "/metrics.json"));
    const auto& e = m["error"];
    EXPECT_GT(e["rmse"].get<double>(), 0.0);
    EXPECT_LT(e["rmse"].get<double>(), 0.5);
    EXPECT_GE(e["max_abs"].get<double>(), e["p99_abs"].get<double>());
    EXPECT_GT(e["psnr_full_srgb"].get<double>(), e["psnr_geometry_srgb"].get<double>()); // sky flatters
    EXPECT_EQ(e["nonfinite"], 0);
    EXPECT_EQ(e["reference"]["variant"], "visibility");
    EXPECT_EQ(e["reference"]["rays_per_pixel"], 64);
    EXPECT_FALSE(e["reference"]["cached"].get<bool>());
    EXPECT_GT(e["reference"]["noise_rms"].get<double>(), 0.0);
    EXPECT_TRUE(m.contains("error_raw"));
    EXPECT_NE(slurp(out + ".log").find("RMSE"), std::string::npos);
    // Second run: the same view comes from the cache, with the same numbers.
    ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(out + ".log");
    auto m2 = nlohmann::json::parse(slurp(out + "/metrics.json"));
    EXPECT_TRUE(m2["error"]["reference"]["cached"].get<bool>());
    EXPECT_EQ(m2["error"]["rmse"], e["rmse"]);
    // A bad variant is one clear line.
    expectCleanFailure(ssaolab("render --reference --reference-variant bent --out " + out), "bent");
}
