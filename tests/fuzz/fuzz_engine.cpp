// libFuzzer target: the two readers and the one writer of the web engines' settings. The first
// byte chooses: even - the rest is a `tune --engine --out` file (engines/engine_settings_file.h),
// whose accepted values must lie inside their rows' ranges and resolve to finite job values; odd -
// the rest is split at NUL bytes into notes, names and values for the snippet writer
// (engines/engine_snippet.h), whose code must be printable ASCII lines, each a comment, the one
// line of names as string literals, or a statement it writes. Any ssao::Error is a correct answer;
// a crash, a sanitizer report, another exception type or a broken invariant is not.
#include "engines/engine_settings_file.h"
#include "engines/engine_snippet.h"
#include "engines/engine_table.h"
#include "util/error.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

const std::vector<ssao::EngineTable>& tables() {
    static const std::vector<ssao::EngineTable> t = [] {
        std::vector<ssao::EngineTable> out;
        for (const std::string& n : ssao::engineNames())
            out.push_back(ssao::findEngine(n));
        return out;
    }();
    return t;
}

void settingsFile(const std::string& text) {
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded()) return;
    try {
        const ssao::TunedEngine t = ssao::parseTunedEngine(j, "fuzz.json");
        for (const auto& [name, v] : t.values) {
            const ssao::EngineParam* p = t.table.find(name);
            if (!p || !std::isfinite(v) || (p->range && (v < p->range->first || v > p->range->second))) std::abort();
        }
        for (double radius : {1e-6, 1.0, 1e6})
            for (const auto& [name, v] : ssao::tunedJobValues(t, radius))
                if (!std::isfinite(v)) std::abort();
    } catch (const ssao::Error&) {
    }
}

void snippet(const std::string& text) {
    std::vector<std::string> parts;
    for (size_t at = 0;;) {
        const size_t nul = text.find('\0', at);
        parts.push_back(text.substr(at, nul == std::string::npos ? std::string::npos : nul - at));
        if (nul == std::string::npos) break;
        at = nul + 1;
    }
    const ssao::EngineTable& t = tables()[parts[0].size() % tables().size()];
    ssao::SnippetFacts facts;
    std::vector<std::pair<std::string, double>> values;
    for (size_t i = 1; i < parts.size(); ++i) {
        if (i % 3 == 0) facts.notes.push_back(parts[i]);
        if (i % 3 == 1) facts.names.emplace_back("name" + std::to_string(i), parts[i]);
        if (i % 3 == 2 && parts[i].size() >= 8) {
            double v;
            std::memcpy(&v, parts[i].data(), sizeof v);
            values.emplace_back(t.params[parts[i].size() % t.params.size()].name, v);
        }
    }
    std::string code;
    try {
        code = ssao::engineSnippet(t, values, facts);
    } catch (const ssao::Error&) {
        return;
    }
    size_t start = 0;
    while (start < code.size()) {
        const size_t end = code.find('\n', start);
        if (end == std::string::npos) std::abort(); // every line ends
        const std::string line = code.substr(start, end - start);
        for (unsigned char c : line)
            if (c < 0x20 || c >= 0x7f) std::abort();
        const bool comment = line.rfind("// ", 0) == 0, names = line.rfind("void { ", 0) == 0,
                   statement = line.rfind(t.variable + ".", 0) == 0;
        if (!comment && !names && !statement) std::abort();
        start = end + 1;
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    if (data[0] % 2 == 0)
        settingsFile(text);
    else
        snippet(text);
    return 0;
}
