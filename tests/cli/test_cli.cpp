// Whole program: the ssaolab binary on real scenes and on bad input.
#include "test_util.h"

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

using ssaotest::slurp;
using ssaotest::writeTemp;

namespace {

struct CliRun {
    int exitCode = -1;
    bool signaled = false;
    std::string out, err;
};

CliRun ssaolab(const std::string& args, const std::string& env = "") {
    std::filesystem::create_directories(SSAOLAB_TEST_TMP);
    // Reference traces are cached inside the build tree, not in the user's ~/.cache.
    ::setenv("SSAOLAB_CACHE_DIR", (std::string(SSAOLAB_TEST_TMP) + "/cache").c_str(), 0);
    const std::string base = std::string(SSAOLAB_TEST_TMP) + "/cli_" + std::to_string(::getpid());
    const std::string cmd = env + (env.empty() ? "" : " ") + std::string("'") + SSAOLAB_BINARY + "' " + args + " >" +
                            base + ".out 2>" + base + ".err </dev/null";
    int status = std::system(cmd.c_str());
    CliRun r;
    r.signaled = WIFSIGNALED(status);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(base + ".out");
    r.err = slurp(base + ".err");
    return r;
}

std::string outDir(const std::string& name) {
    return std::string(SSAOLAB_TEST_TMP) + "/out_" + name;
}

// One clear line naming the problem, exit code 1 (not a crash, not a hang).
void expectCleanFailure(const CliRun& r, const std::string& needle) {
    EXPECT_FALSE(r.signaled) << r.err;
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "expected one line, got:\n" << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << "expected '" << needle << "' in: " << r.err;
}

} // namespace

TEST(Cli, EveryHeadlessCommandFailsOnAGlError) {
    // One headless runner under every command (app/headless_runner.h): a GL error raised during the
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
    const std::string cmd = "xvfb-run -a -s '-screen 0 1280x800x24' '" + std::string(SSAOLAB_BINARY) +
                            "' view --size 1200x700 --frames 6 --screenshot " + shot + " --preset-dir " +
                            presets + " >" + SSAOLAB_TEST_TMP + "/xvfb.out 2>&1";
    const int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << slurp(std::string(SSAOLAB_TEST_TMP) + "/xvfb.out");
    ASSERT_EQ(WEXITSTATUS(status), 0) << slurp(std::string(SSAOLAB_TEST_TMP) + "/xvfb.out");
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

TEST(Cli, BenchWritesResultsTheFrontAndRatiosToTheBaseline) {
    const std::string out = outDir("bench");
    std::filesystem::remove_all(out);
    const std::string sweep = writeTemp("small_sweep.json", R"({
      "name": "small", "base": {"set": {"kernel.noise": "tex4x4"}},
      "groups": [{"name": "samples", "vary": {"kernel.samples": [4, 32]}},
                 {"name": "blur", "set": {"kernel.samples": 8}, "vary": {"denoise.kind": ["none", "gaussian"]}},
                 {"name": "temporal", "set": {"ao.technique": "gtao", "temporal.enabled": true, "temporal.frames": 4}}]})");
    CliRun r = ssaolab(
        "bench --scene " + std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/cornellBox.gltf --sweep " + sweep +
        " --size 160x90 --views 2 --frames 2 --warmup 0 --reference-rays 16 --quiet --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* f :
         {"results.csv", "summary.csv", "results.json", "report.md", "pareto.png", "pareto.svg"})
        EXPECT_TRUE(std::filesystem::exists(out + "/" + f)) << f;
    auto j = nlohmann::json::parse(slurp(out + "/results.json"));
    // baseline + 2 + 2 (+ every technique at its defaults, 64 samples: not a duplicate here).
    const auto& cfgs = j["configurations"];
    ASSERT_GE(cfgs.size(), 5u);
    EXPECT_EQ(cfgs[0]["label"], "learnopengl (baseline)");
    EXPECT_EQ(cfgs[0]["time_ratio"], 1.0);
    EXPECT_EQ(cfgs[0]["rmse_ratio"], 1.0);
    EXPECT_EQ(j["results"].size(), cfgs.size() * 2); // two views each
    for (const auto& v : j["results"]) {
        // Temporal accumulation blends its frames before it is judged; everything else is one frame.
        const bool temporal = v["label"].get<std::string>().find("temporal") != std::string::npos;
        EXPECT_EQ(v["frames"], temporal ? 4 : 1) << v["label"];
        if (!temporal) {
            EXPECT_EQ(v["rmse_first_frame"], v["rmse"]) << v["label"];
        }
    }
    int front = 0;
    for (const auto& c : cfgs) {
        EXPECT_GT(c["gpu_ms"].get<double>(), 0.0) << c["label"];
        EXPECT_LE(c["gpu_ms_min"].get<double>(), c["gpu_ms"].get<double>());
        EXPECT_GE(c["gpu_ms_max"].get<double>(), c["gpu_ms"].get<double>());
        EXPECT_GT(c["rmse"].get<double>(), 0.0);
        EXPECT_LT(c["rmse"].get<double>(), 0.6);
        EXPECT_EQ(c["nonfinite"], 0);
        front += c["pareto"].get<bool>();
    }
    EXPECT_GE(front, 1);
    // The front is consistent: no configuration is both faster and more accurate than a front member.
    for (const auto& a : cfgs) {
        if (!a["pareto"].get<bool>()) continue;
        for (const auto& b : cfgs) {
            EXPECT_FALSE(b["gpu_ms"].get<double>() < a["gpu_ms"].get<double>() &&
                         b["rmse"].get<double>() < a["rmse"].get<double>())
                << a["label"] << " is dominated by " << b["label"];
        }
    }
    for (const char* k : {"cpu", "gl_renderer", "build_type", "date", "git_revision"})
        EXPECT_TRUE(j.contains(k)) << k;
    const std::string md = slurp(out + "/report.md");
    EXPECT_NE(md.find("Pareto front"), std::string::npos);
    EXPECT_NE(md.find("learnopengl (baseline)"), std::string::npos);
    EXPECT_NE(slurp(out + "/results.csv").find("scene,viewpoint,label"), std::string::npos);
    // Bad sweeps: one clear line each.
    expectCleanFailure(ssaolab("bench --sweep " +
                               writeTemp("bad1.json", "{\"groups\": [{\"vary\": {\"kernel.nope\": [1]}}]}")),
                       "kernel.nope");
    expectCleanFailure(
        ssaolab("bench --sweep " + writeTemp("bad2.json", "{\"groups\": [{\"set\": {\"ao.radius\": 2}}]}")),
        "radius");
    expectCleanFailure(ssaolab("bench --sweep " + writeTemp("bad3.json", "{not json")), "not valid JSON");
    expectCleanFailure(ssaolab("bench --sweep /nonexistent.json"), "cannot open");
}

TEST(Cli, TuneFitsTheReferenceAndSavesAPresetThatRenders) {
    const std::string preset = std::string(SSAOLAB_TEST_TMP) + "/tuned.json";
    std::filesystem::remove(preset);
    CliRun r = ssaolab("tune --scene builtin:showcase --size 160x90 --views 2 --rounds 1 --grid 3 "
                       "--reference-rays 16 --out " +
                       preset);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("held-out"), std::string::npos) << r.out;
    // The search starts from the defaults and keeps the best, so training error never rises.
    double before = 0, after = 0;
    ASSERT_EQ(
        std::sscanf(r.out.substr(r.out.find("training")).c_str(), "training %lf -> %lf", &before, &after), 2)
        << r.out;
    EXPECT_LE(after, before);
    auto j = nlohmann::json::parse(slurp(preset));
    EXPECT_EQ(j["ao"]["radius_mode"], "scene");
    EXPECT_NE(j["description"].get<std::string>().find("held-out"), std::string::npos);
    CliRun again = ssaolab("render --preset " + preset + " --size 160x90 --timing-frames 1 --quiet --out " +
                           outDir("tuned"));
    EXPECT_EQ(again.exitCode, 0) << again.err;
    expectCleanFailure(ssaolab("tune --technique nope"), "nope");
}

TEST(Cli, SkipsMeasuresEverySkipAgainstTheSameFrameWithoutIt) {
    // `ssaolab skips` at a small size: a row per skip and dependency, exact skips change nothing,
    // the dirty rows re-run only the passes downstream of the change, and skips.md is written.
    const std::string out = outDir("skips");
    CliRun r = ssaolab("skips --quiet --size 96x54 --frames 1 --reference-rays 16 --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(slurp(out + "/skips.json"), nullptr, false);
    ASSERT_FALSE(j.is_discarded());
    std::map<std::string, int> count;
    for (const auto& row : j["rows"]) {
        const std::string skip = row["skip"];
        ++count[skip];
        EXPECT_GT(row["without_ms"].get<double>(), 0.0) << row.dump();
        if (skip != "adaptive") {
            EXPECT_EQ(row["error_change"].get<double>(), 0.0) << row.dump();
        }
        if (skip == "dirty") {
            const auto ran = row["extra"]["passes_run"];
            const std::string v = row["variant"];
            if (v.rfind("camera", 0) == 0) {
                EXPECT_EQ(ran.size(), 4u);
            }
            if (v.rfind("AO setting", 0) == 0) {
                EXPECT_EQ(ran, nlohmann::json({"ao", "denoise", "composite"}));
            }
            if (v.rfind("denoise", 0) == 0) {
                EXPECT_EQ(ran, nlohmann::json({"denoise", "composite"}));
            }
            if (v.rfind("composite", 0) == 0) {
                EXPECT_EQ(ran, nlohmann::json({"composite"}));
            }
            if (v.rfind("view switch", 0) == 0) {
                EXPECT_TRUE(ran.empty());
                EXPECT_EQ(row["with_ms"].get<double>(), 0.0); // idle: no GPU work at all
            }
        }
    }
    EXPECT_EQ(count["dirty"], 5);
    EXPECT_EQ(count["sky"], 5);
    EXPECT_EQ(count["adaptive"], 24); // 4 techniques x 3 views x 2 px/sample
    EXPECT_EQ(count["cull"], 2);
    EXPECT_EQ(count["targets"], 6);
    EXPECT_NE(slurp(out + "/skips.md").find("#### Frustum culling"), std::string::npos);
}

TEST(CliHostile, EveryAssimpTestModelRendersOrFailsWithOneLine) {
    // Debian's assimp-testmodels: 53 glTF 1.0/2.0 files, many broken on purpose (indices out of
    // range, recursive nodes, wrong JSON types, missing .bin, infinities, Draco, glTF 1.0). Each
    // must render with finite AO or fail with one `ssaolab: error:` line: no signal, no hang.
    namespace fs = std::filesystem;
    const fs::path root = "/usr/share/assimp/models";
    ASSERT_TRUE(fs::is_directory(root / "glTF2")) << "install assimp-testmodels (.ci/install-deps.sh)";
    int rendered = 0, refused = 0;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
        const std::string ext = e.path().extension().string();
        if (ext != ".gltf" && ext != ".glb") continue;
        const std::string out = outDir("assimp");
        const std::string base = std::string(SSAOLAB_TEST_TMP) + "/assimp";
        const std::string cmd = "timeout 60 '" + std::string(SSAOLAB_BINARY) + "' render --size 64x48 --quiet " +
                                "--timing-frames 1 --scene '" + e.path().string() + "' --out " + out + " >" +
                                base + ".out 2>" + base + ".err </dev/null";
        const int status = std::system(cmd.c_str());
        ASSERT_TRUE(WIFEXITED(status)) << e.path() << " was killed by a signal";
        const int rc = WEXITSTATUS(status);
        std::ifstream in(base + ".err");
        std::stringstream err;
        err << in.rdbuf();
        const std::string text = err.str();
        EXPECT_NE(rc, 124) << e.path() << " hung";
        if (rc == 0) {
            ++rendered;
            std::ifstream m(out + "/metrics.json");
            const auto j = nlohmann::json::parse(m, nullptr, false);
            ASSERT_FALSE(j.is_discarded()) << e.path();
            for (const auto& [name, st] : j["buffers"].items())
                EXPECT_EQ(st.value("nonfinite", 0), 0) << e.path() << " " << name;
        } else {
            ++refused;
            EXPECT_EQ(rc, 1) << e.path() << ": " << text;
            EXPECT_EQ(text.rfind("ssaolab: error: ", 0), 0u) << e.path() << ": " << text;
            EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << e.path() << ": " << text;
        }
    }
    std::printf("assimp-testmodels: %d rendered, %d refused with one line\n", rendered, refused);
    EXPECT_GE(rendered + refused, 50);
    EXPECT_GE(rendered, 20);
}

TEST(CliStress, EveryTechniqueStaysFiniteInRangeAndInvariantUnderScaleAndTranslation) {
    // `ssaolab stress` at a small size: no NaN/inf or out-of-range value in any case, scale and
    // translation (to 1e7 units, positions relative to the scene's double-precision origin) within
    // RMSE 0.02 of the benign render, and the depth-range guard
    // refuses far/near 1e9 in a standard depth buffer with its one-line message.
    const std::string out = outDir("stress");
    CliRun r = ssaolab("stress --quiet --size 128x72 --tolerance 0.02 --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    std::ifstream in(out + "/stress.json");
    const auto j = nlohmann::json::parse(in, nullptr, false);
    ASSERT_FALSE(j.is_discarded());
    std::set<std::string> techs;
    int refusedDepth = 0, invariant = 0;
    for (const auto& row : j["rows"]) {
        techs.insert(row["technique"].get<std::string>());
        EXPECT_EQ(row["nonfinite"].get<long>(), 0) << row.dump();
        EXPECT_EQ(row["outside"].get<long>(), 0) << row.dump();
        if (row["status"] == "refused" && row["message"].get<std::string>().find("far/near") != std::string::npos)
            ++refusedDepth;
        if (row["invariant"].get<bool>() && row["status"] == "ok") {
            ++invariant;
            EXPECT_LE(row["rmse"].get<double>(), 0.02) << row.dump();
        }
    }
    EXPECT_EQ(techs.size(), 5u);
    EXPECT_GE(refusedDepth, 5);   // far 1e5 x diag and the 1e9 pair, for every technique
    // 6 scales + 5 translations + 12 reversed-depth planes enclosing the scene + the infinite far
    // plane + degenerate triangles + normals scaled by 1e-6 and 1e6, per technique: reversed-Z
    // float depth draws what the fitted planes draw at every ratio up to 1e11.
    EXPECT_EQ(invariant, 5 * 27);
    std::ifstream md(out + "/stability.md");
    EXPECT_TRUE(md.good());
}

TEST(CliHostile, OutputsNeverOverwriteWhatTheyMustNot) {
    // A symlink planted at a staging name inside --out made a render overwrite a file outside it.
    const std::string out = outDir("planted");
    std::filesystem::remove_all(out);
    std::filesystem::create_directories(out);
    const std::string victim = writeTemp("victim.txt", "precious");
    for (const char* staged : {"ao.raw.exr.exr-staged", "metrics.json.tmp1", "ao.raw.png.tmp-1-0"})
        ASSERT_EQ(::symlink(victim.c_str(), (out + "/" + staged).c_str()), 0);
    CliRun r = ssaolab("render --scene builtin:corner --size 64x36 --timing-frames 1 --quiet --out " + out);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(slurp(victim), "precious");
    // tune --out a FIFO (or a device: /dev/null as root) replaced the node with a regular file.
    const std::string fifo = std::string(SSAOLAB_TEST_TMP) + "/tune_fifo";
    std::filesystem::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    r = ssaolab("tune --technique sao --scene builtin:corner --size 64x36 --views 2 --rounds 1 --grid 3 "
                "--reference-rays 4 --knob sao.bias --quiet --out " + fifo);
    expectCleanFailure(r, "is not a regular file (a FIFO)");
    struct stat st {};
    ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "the FIFO is still a FIFO";
    // Two renders into one --out at once: the EXR staging name had no process id ("truncated").
    const std::string shared = outDir("together");
    std::filesystem::remove_all(shared);
    const std::string cmd = std::string("'") + SSAOLAB_BINARY + "' render --scene builtin:showcase --size 160x90 "
                            "--timing-frames 1 --quiet --out " + shared;
    const std::string both = "(" + cmd + " & p1=$!; " + cmd + " & p2=$!; wait $p1; a=$?; wait $p2; b=$?; exit $((a + b)))";
    EXPECT_EQ(std::system(("bash -c '" + std::regex_replace(both, std::regex("'"), "'\\''") + "'").c_str()), 0);
    EXPECT_TRUE(std::filesystem::exists(shared + "/metrics.json"));
}

TEST(CliHostile, NanOptionsAndNonUtf8NamesGiveOneLineOrAReport) {
    // `nan` passed CLI11's range checks: --tolerance nan switched the invariance check off.
    expectCleanFailure(ssaolab("stress --scene builtin:corner --tolerance nan"), "not a finite number");
    expectCleanFailure(ssaolab("--max-triangles nan render --scene builtin:corner"), "not a finite number");
    // A scene file name that is not UTF-8 ended in a bare json exception after the images, with no
    // metrics.json: JSON output replaces the bytes instead.
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/latin1";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string src = std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/";
    std::filesystem::copy_file(src + "cornellBox.gltf", dir + "/caf\xe9.gltf");
    std::filesystem::copy_file(src + "cornellBox.bin", dir + "/cornellBox.bin");
    const std::string out = outDir("latin1");
    std::filesystem::remove_all(out);
    const CliRun r = ssaolab("render --scene '" + dir + "/caf\xe9.gltf' --size 64x36 --timing-frames 1 --quiet --out " + out);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json m = nlohmann::json::parse(slurp(out + "/metrics.json"));
    EXPECT_NE(m["scene"]["name"].get<std::string>().find("caf\xef\xbf\xbd.gltf"), std::string::npos); // U+FFFD
}
