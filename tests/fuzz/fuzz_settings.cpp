// libFuzzer target: everything a user types or a JSON file says about settings: preset JSON,
// sweep JSON, --set KEY=VALUE, --camera and --size. The first byte picks the parser. Any
// ssao::Error is a correct answer; a crash, a sanitizer report or another exception type is not.
#include "measure/sweep.h"
#include "cli/scene_options.h"
#include "scene/camera.h"
#include "settings/params.h"
#include "settings/preset.h"
#include "util/error.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    try {
        switch (data[0] % 5) {
        case 0: {
            const auto j = nlohmann::json::parse(text, nullptr, false);
            if (!j.is_discarded()) ssao::presetFromJson(j, "fuzz");
            break;
        }
        case 1: {
            const auto j = nlohmann::json::parse(text, nullptr, false);
            if (!j.is_discarded()) ssao::parseSweep(j, "fuzz", "", 64);
            break;
        }
        case 2: {
            ssao::Settings s = ssao::defaultSettings();
            ssao::applyAssignment(s, text);
            break;
        }
        case 3:
            ssao::parseCamera(text, ssao::Camera{});
            break;
        case 4: {
            int w = 0, h = 0;
            ssao::parseSizeOption(text, w, h);
            break;
        }
        }
    } catch (const ssao::Error&) {
    }
    return 0;
}
