#include "util/json_file.h"

#include "util/error.h"
#include "util/file_kind.h"

#include <algorithm>

namespace ssao {

size_t jsonNestingDepth(const char* text, size_t size) {
    size_t depth = 0, deepest = 0;
    bool inString = false;
    for (size_t i = 0; i < size; ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\') ++i; // the escaped character is never a quote that ends the string
            else if (c == '"') inString = false;
            continue;
        }
        if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

void checkJsonNesting(const std::string& text, const std::string& what) {
    if (jsonNestingDepth(text.data(), text.size()) > kMaxJsonDepth)
        throw Error(what + " nests arrays or objects deeper than " + std::to_string(kMaxJsonDepth) + " levels");
}

nlohmann::json parseJsonText(const std::string& text, const std::string& label) {
    checkJsonNesting(text, label);
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) { // syntax, or a number that overflows a double
        std::string msg = e.what();
        const size_t bracket = msg.find("] ");
        if (bracket != std::string::npos) msg = msg.substr(bracket + 2); // drop "[json.exception...]"
        const size_t quoted = msg.find("; last read");
        if (quoted != std::string::npos) msg = msg.substr(0, quoted); // never echo a file's bytes (a link to a private file)
        throw Error(label + " is not valid JSON (" + msg + ")");
    }
}

nlohmann::json readJsonFile(const std::string& path, const std::string& what) {
    const std::string text = readRegularFile(path, what);
    // An image or other binary file named by mistake: said so, before a parser reads its bytes.
    if (const std::string kind = binaryFileKind(text); !kind.empty())
        throw Error(what + " " + path + " is " + kind + ", not a " + what + " (JSON text)");
    return parseJsonText(text, what + " " + path);
}

std::string dumpJson(const nlohmann::json& j, int indent) {
    return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

} // namespace ssao
