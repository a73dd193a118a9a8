// libFuzzer target: a user technique's file (NAME.ao.glsl, techniques/user/user_header.h). The
// header parser, then for every header it accepts the GLSL and the block's bytes at its defaults;
// the body's limits (user_source.h checkUserBody: macros measured under a work budget, never
// expanded); the first line also goes to the file-name rule. Any ssao::Error from the parser is a correct
// answer; a crash, a sanitizer report, another exception type, or an accepted header whose
// defaults do not pack or whose strings are not printable ASCII is not.
#include "techniques/technique.h"
#include "techniques/user/user_header.h"
#include "techniques/user/user_source.h"
#include "util/error.h"

#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

namespace {
bool printable(const std::string& s, bool items = false) {
    for (char c : s)
        if (!(c >= 0x20 && c <= 0x7e) && !(items && c == '\0')) return false;
    return true;
}

// What an accepted header must hold: the limits it was checked against, and defaults that pack.
void checkAccepted(const ssao::UserHeader& h) {
    if (h.params.size() > size_t(ssao::kMaxUserParams) || h.label.empty() || !printable(h.label) ||
        !printable(h.summary))
        std::abort();
    std::vector<double> defaults;
    for (const auto& p : h.params) {
        if (!(p.min <= p.def && p.def <= p.max) || !printable(p.label) || !printable(p.tooltip) || !printable(p.unit))
            std::abort();
        for (const auto& item : p.items)
            if (item.empty() || !printable(item)) std::abort();
        defaults.push_back(p.def);
    }
    const std::vector<unsigned char> bytes = ssao::packUserParams(h, defaults); // throws: a finding
    const std::string glsl = ssao::userParamsGlsl(h, 0), tail = "\n#line 1\n";
    if (bytes.size() % 16 || bytes.size() < 4 * h.params.size() || glsl.size() < tail.size() ||
        glsl.compare(glsl.size() - tail.size(), tail.size(), tail) != 0)
        std::abort();
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::vector<std::string> ids = [] {
        std::vector<std::string> out;
        for (const auto& t : ssao::techniques())
            out.push_back(t.id);
        return out;
    }();
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::optional<ssao::UserHeader> h;
    try {
        h = ssao::parseUserHeader(text, "fuzz.ao.glsl", ids);
    } catch (const ssao::Error&) {
    }
    if (h) checkAccepted(*h);
    try {
        ssao::checkUserBody(text, "fuzz.ao.glsl");
    } catch (const ssao::Error&) {
    }
    try {
        ssao::userTechniqueName(text.substr(0, text.find('\n')), ids);
    } catch (const ssao::Error&) {
    }
    return 0;
}
