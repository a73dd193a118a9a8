#include "engines/engine_snippet.h"

#include "util/error.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

namespace ssao {

namespace {

std::string commentLine(const std::string& text) {
    std::string s = "// ";
    for (char c : text)
        s += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? ' ' : c; // a newline would end the comment
    return s + "\n";
}

} // namespace

double exportedValue(double v) {
    char b[64];
    std::snprintf(b, sizeof b, "%.6g", v);
    return std::strtod(b, nullptr);
}

std::string jsValue(const EngineParam& p, double v) {
    if (p.type == EngineParam::Type::Boolean) return v != 0.0 ? "true" : "false";
    if (p.type == EngineParam::Type::Integer) return std::to_string(std::llround(v));
    if (!std::isfinite(v)) throw Error("a non-finite value for " + p.name);
    char b[64];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}

std::string engineSnippet(const EngineTable& t, const std::vector<std::pair<std::string, double>>& values,
                          const std::vector<std::string>& comments) {
    std::string out;
    for (const std::string& c : comments)
        out += commentLine(c);
    for (const std::string& line : t.setup)
        out += commentLine(line);
    std::vector<std::string> callOrder;
    std::map<std::string, std::string> calls; // setter -> "key: value, ..."
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
