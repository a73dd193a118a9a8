// What the tests of the web engines share (test_cli_engines.cpp, test_cli_bench_engines.cpp,
// test_cli_engine_babylon.cpp, test_cli_engine_filament.cpp): where the peers' scripts and the pinned npm packages are, whether
// Node.js runs, a snippet run against a recording mock, and a small glTF corner.
#pragma once
#include "cli_run.h"
#include "cli/headless_runner.h"
#include "reference/reference_cache.h"
#include "scene/scene.h"
#include "scene/view_fit.h"
#include "settings/preset.h"
#include "util/process.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace ssaotest {

inline const std::string kPeers = std::string(SSAOLAB_SOURCE_DIR) + "/tools/peers";
inline const std::string kModules = std::string(SSAOLAB_BUILD_DIR) + "/peers/node_modules";

inline bool modulesInstalled() {
    namespace fs = std::filesystem;
    for (const char* m : {"three", "n8ao", "postprocessing", "playwright-core", "babylonjs", "babylonjs-loaders", "playcanvas", "filament"})
        if (!fs::is_regular_file(kModules + "/" + m + "/package.json")) return false;
    return true;
}

inline bool nodeRuns() {
    return ssao::runProgram({"node", "--version"}, ssao::ChildStream::Discard, ssao::ChildStream::Discard).exitCode == 0;
}

// `make test` and `make test-sanitize` install them first: missing, the test fails and says how.
#define NEED_MODULES()                                                                                             \
    ASSERT_TRUE(nodeRuns() && modulesInstalled())                                                                  \
        << "Node.js or the pinned npm packages are not installed in " << kModules                                 \
        << " (make engine-modules installs them from tools/peers/package-lock.json)"

// Runs the snippet after a mock of the pass that records every assignment ("configuration.aoRadius")
// and every update call's keys ("updateGtaoMaterial(radius)"); returns the record.
inline nlohmann::json runSnippet(const std::string& variable, const std::string& snippet, const std::string& tag) {
    const std::string mock =
        "const recorded = {};\n"
        "function mock(at) {\n"
        "  return new Proxy(function () {}, {\n"
        "    get: (t, k) => mock(at ? at + '.' + String(k) : String(k)),\n"
        "    set: (t, k, v) => { recorded[at ? at + '.' + String(k) : String(k)] = v; return true; },\n"
        "    apply: (t, self, args) => { for (const [k, v] of Object.entries(args[0])) recorded[at + '(' + k + ')'] = v; },\n"
        "  });\n"
        "}\n"
        "const " + variable + " = mock('');\n";
    // Nothing but the recorded writes may leave the snippet: a global it made is reported too.
    const std::string tail = "\nconst extra = ['pwned', 'alert'].filter((k) => k in globalThis);\n"
                             "if (extra.length) recorded['globals: ' + extra.join(',')] = 1;\n"
                             "console.log(JSON.stringify(recorded));\n";
    nlohmann::json got;
    for (const char* ext : {".js", ".mjs"}) { // a script, then a module
        const std::string file = writeTemp("snippet_" + tag + ext, mock + snippet + tail);
        const ssao::ProgramRun r = ssao::runProgram({"node", file}, ssao::ChildStream::Capture, ssao::ChildStream::Capture);
        EXPECT_EQ(r.exitCode, 0) << ext << ":\n" << snippet << r.out;
        if (r.exitCode != 0) return nlohmann::json();
        const nlohmann::json j = nlohmann::json::parse(r.out);
        if (!got.is_null()) {
            EXPECT_EQ(j, got) << "the script and the module set different values";
        }
        got = j;
    }
    return got;
}

// A corner: floor, back wall and left wall, 2 units a side, with normals; buffer as a data URI.
inline std::string writeCornerGltf(const std::string& name) {
    const float q[3][4][6] = {
        {{-1, 0, -1, 0, 1, 0}, {1, 0, -1, 0, 1, 0}, {1, 0, 1, 0, 1, 0}, {-1, 0, 1, 0, 1, 0}},
        {{-1, 0, -1, 0, 0, 1}, {1, 0, -1, 0, 0, 1}, {1, 2, -1, 0, 0, 1}, {-1, 2, -1, 0, 0, 1}},
        {{-1, 0, -1, 1, 0, 0}, {-1, 2, -1, 1, 0, 0}, {-1, 2, 1, 1, 0, 0}, {-1, 0, 1, 1, 0, 0}}};
    std::vector<float> pos, nrm;
    std::vector<uint16_t> idx;
    for (int f = 0; f < 3; ++f) {
        for (int v = 0; v < 4; ++v)
            pos.insert(pos.end(), q[f][v], q[f][v] + 3), nrm.insert(nrm.end(), q[f][v] + 3, q[f][v] + 6);
        for (int i : {0, 1, 2, 0, 2, 3})
            idx.push_back(uint16_t(f * 4 + i));
    }
    std::vector<unsigned char> bin(pos.size() * 4 + nrm.size() * 4 + idx.size() * 2);
    std::memcpy(bin.data(), pos.data(), pos.size() * 4);
    std::memcpy(bin.data() + pos.size() * 4, nrm.data(), nrm.size() * 4);
    std::memcpy(bin.data() + pos.size() * 8, idx.data(), idx.size() * 2);
    const std::string pb = std::to_string(pos.size() * 4);
    const std::string text = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2}]}],
 "buffers": [{"byteLength": )" + std::to_string(bin.size()) + R"(, "uri": "data:application/octet-stream;base64,)" + base64(bin) + R"("}],
 "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )" + pb + R"(},
                 {"buffer": 0, "byteOffset": )" + pb + R"(, "byteLength": )" + pb + R"(},
                 {"buffer": 0, "byteOffset": )" + std::to_string(pos.size() * 8) + R"(, "byteLength": )" + std::to_string(idx.size() * 2) + R"(}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 12, "type": "VEC3", "min": [-1, 0, -1], "max": [1, 2, 1]},
               {"bufferView": 1, "componentType": 5126, "count": 12, "type": "VEC3"},
               {"bufferView": 2, "componentType": 5123, "count": 18, "type": "SCALAR"}]})";
    return writeTemp(name, text);
}

// The corner as every engine's round trip sees it at 96x54: the scene, the camera ssaolab's renderer
// fits, R (5 % of the diagonal), the camera as the runner takes it, and the reference (64 rays).
struct CornerView {
    std::string file;
    ssao::Scene scene;
    ssao::Camera camera;
    float radius = 0;
    nlohmann::json cameraJson;
    ssao::ReferenceImage reference() const {
        ssao::ReferenceProvider provider(scene, std::string(SSAOLAB_TEST_TMP) + "/cache");
        return provider.get(camera, 96, 54, {radius, 64});
    }
};

inline CornerView cornerView(const std::string& name) {
    CornerView v;
    v.file = writeCornerGltf(name);
    v.scene = ssao::loadNamedScene(v.file);
    v.camera = ssao::effectiveCamera(ssao::defaultCamera(v.scene), v.scene.bounds);
    v.radius = 0.05f * 2.0f * v.scene.bounds.radius();
    v.cameraJson = ssao::cameraToJson(ssao::cameraToFile(v.camera, v.scene));
    return v;
}

} // namespace ssaotest
