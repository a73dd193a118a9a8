#include "engines/engine_snippet.h"

#include "output/escape.h"
#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

namespace ssao {

namespace {

std::string commentLine(const std::string& text) {
    return "// " + jsCommentText(text) + "\n";
}

// `void { scene: "...", view: "..." };`: the names as data that sets nothing. `void` cannot
// continue a line above that lacks its semicolon, so the statement stands alone when pasted.
std::string namesLine(const std::vector<std::pair<std::string, std::string>>& names) {
    if (names.empty()) return "";
    std::string s = "void {";
    for (size_t i = 0; i < names.size(); ++i) {
        const std::string& k = names[i].first;
        const bool ident = !k.empty() && std::all_of(k.begin(), k.end(), [](char c) {
            return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
        }) && !(k[0] >= '0' && k[0] <= '9');
        if (!ident) throw Error("snippet: a fact's key must be an identifier");
        s += (i ? ", " : " ") + k + ": " + jsString(names[i].second);
    }
    return s + " }; // what the values were fitted on (names as strings: nothing here runs)\n";
}

} // namespace

double exportedValue(double v) {
    char b[64];
    std::snprintf(b, sizeof b, "%.6g", v);
    return std::strtod(b, nullptr);
}

std::string jsValue(const EngineParam& p, double v) {
    if (p.type == EngineParam::Type::Boolean) return v != 0.0 ? "true" : "false";
    if (!std::isfinite(v)) throw Error("a non-finite value for " + p.name);
    if (p.type == EngineParam::Type::Integer) {
        if (std::fabs(v) > 9007199254740992.0) throw Error(p.name + " is beyond the integers JavaScript holds exactly");
        return std::to_string(std::llround(v));
    }
    char b[64];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}

std::string engineSnippet(const EngineTable& t, const std::vector<std::pair<std::string, double>>& values,
                          const SnippetFacts& facts) {
    std::string out;
    for (const std::string& c : facts.notes)
        out += commentLine(c);
    out += namesLine(facts.names);
    for (const std::string& line : t.setup)
        out += commentLine(line);
    std::vector<std::string> callOrder;
    std::map<std::string, std::string> calls; // setter -> "key: value, ..."
    for (const auto& [call, args] : t.callAlways) {
        callOrder.push_back(call);
        for (const auto& [key, literal] : args)
            calls[call] += (calls[call].empty() ? "" : ", ") + key + ": " + literal;
    }
    std::string body;
    for (const auto& [name, v] : values) {
        const EngineParam* p = t.find(name);
        if (!p) throw Error(t.engine + " has no parameter " + name);
        if (p->constructorArg >= 0) {
            out += commentLine("construct with " + name + " = " + jsValue(*p, v) + " (constructor argument " +
                               std::to_string(p->constructorArg + 1) + ")");
        } else if (!p->writeCall.empty()) {
            if (!calls.count(p->writeCall)) callOrder.push_back(p->writeCall);
            std::string& args = calls[p->writeCall];
            args += (args.empty() ? "" : ", ") + p->writeKey + ": " + jsValue(*p, v);
        } else {
            body += t.variable + "." + p->writePath + " = " + jsValue(*p, v) + ";\n";
        }
    }
    for (const std::string& c : callOrder)
        body += t.variable + "." + c + "({ " + calls[c] + " });\n";
    return out + body;
}

} // namespace ssao
