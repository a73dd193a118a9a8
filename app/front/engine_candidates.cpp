#include "front/engine_candidates.h"

#include "engines/engine_settings_file.h"

#include "engines/engine_snippet.h"
#include "util/error.h"
#include "util/files.h"
#include "util/json_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

namespace fs = std::filesystem;

namespace ssao {

namespace {
constexpr size_t kMaxTunedFiles = 256;
} // namespace

std::string engineShortTitle(const EngineTable& t) {
    const size_t paren = t.title.find(" (");
    return paren == std::string::npos ? t.title : t.title.substr(0, paren);
}

std::vector<EngineCandidate> engineDefaultCandidates(const std::vector<std::string>& engines) {
    std::vector<EngineCandidate> out;
    for (const std::string& e : engines) {
        const EngineTable t = findEngine(e);
        out.push_back({e, engineShortTitle(t) + " defaults", "", {}, {}, {}});
        out.push_back({e, engineShortTitle(t) + " as shipped", "", {}, {}, shippedValues(t), true});
    }
    return out;
}

EngineCandidate tunedEngineCandidate(const std::string& file) {
    TunedEngine t = readTunedEngine(file);
    return {t.table.engine, engineShortTitle(t.table) + " tuned (" + fs::path(file).stem().string() + ")", file,
            std::move(t.scale), std::move(t.perRadius), std::move(t.values)};
}

std::vector<EngineCandidate> tunedEnginesIn(const std::string& dir, const std::vector<std::string>& engines,
                                            std::vector<std::string>& errors) {
    std::vector<std::string> files;
    try {
        for (const std::string& f : listFilesInside(dir, "", "tuned engine settings folder", kMaxTunedFiles))
            if (fs::path(f).extension() == ".json" && fs::path(f).parent_path().empty()) files.push_back(f);
    } catch (const std::exception& e) {
        errors.push_back(oneLine(e.what()));
    }
    std::sort(files.begin(), files.end());
    std::vector<EngineCandidate> out;
    for (const std::string& f : files) {
        try {
            EngineCandidate c = tunedEngineCandidate((fs::path(dir) / f).string());
            if (std::find(engines.begin(), engines.end(), c.engine) != engines.end()) out.push_back(std::move(c));
        } catch (const std::exception& e) {
            errors.push_back(oneLine(e.what()));
        }
    }
    return out;
}

std::map<std::string, double> engineJobValues(const EngineCandidate& c, const EngineTable& t, double radius) {
    return jobValues(t, c.perRadius, c.values, radius);
}

} // namespace ssao
