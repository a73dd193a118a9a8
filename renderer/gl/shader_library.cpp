#include "gl/shader_library.h"

#include "util/error.h"
#include "util/files.h"

#include <set>
#include <sstream>

namespace ssao::gl {

namespace {

std::string readFile(const std::string& path) {
    return readRegularFile(path, "shader file", size_t(4) << 20); // never waits on a FIFO in the folder
}

// `#include "name"` (spaces allowed around '#' and the keyword): the name, or "" when the line is
// not an include. A plain scan: std::regex recursed once per character and a 60 000-space line
// overflowed the stack (in the explorer, saving such a file killed the window).
std::string includeTarget(const std::string& line, const std::string& where) {
    size_t i = line.find_first_not_of(" \t");
    if (i == std::string::npos || line[i] != '#') return "";
    i = line.find_first_not_of(" \t", i + 1);
    if (i == std::string::npos || line.compare(i, 7, "include") != 0) return "";
    i = line.find_first_not_of(" \t", i + 7);
    if (i == std::string::npos || line[i] != '"') return "";
    const size_t end = line.find('"', i + 1);
    if (end == std::string::npos || line.find_first_not_of(" \t\r", end + 1) != std::string::npos) return "";
    if (end - i - 1 > 256) throw Error(where + ": #include name longer than 256 characters");
    return line.substr(i + 1, end - i - 1);
}

void expand(const std::string& dir, const std::string& file, std::vector<std::string>& files,
            std::set<std::string>& included, std::ostringstream& out, int depth, const Sources* sources) {
    if (depth > 16) throw Error("shader include depth exceeded at " + file);
    const int fileId = int(files.size());
    files.push_back(file);
    const auto source = sources ? sources->find(file) : Sources::const_iterator{};
    std::istringstream in(sources && source != sources->end() ? source->second : readFile(dir + "/" + file));
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        const std::string inc = includeTarget(line, "shaders/" + file + ":" + std::to_string(lineNo));
        if (!inc.empty()) {
            // Includes are relative to the shader root (like a -I path), e.g. "include/onb.glsl".
            if (included.insert(inc).second) {
                out << "#line 1 " << files.size() << "\n";
                expand(dir, inc, files, included, out, depth + 1, sources);
            }
            out << "#line " << lineNo + 1 << " " << fileId << "\n";
            continue;
        }
        out << line << "\n";
    }
}

} // namespace

std::string preprocessShader(const std::string& shaderDir, const std::string& file, const Defines& defines,
                             std::vector<std::string>& files, const Sources* sources) {
    files.clear();
    std::ostringstream body;
    std::set<std::string> included;
    expand(shaderDir, file, files, included, body, 0, sources);
    const std::string text = body.str();
    // The #version line must come first: pull it out, then inject defines and resync lines.
    const size_t start = text.find_first_not_of(" \t\r\n");
    const size_t hash = start == std::string::npos || text[start] != '#' ? std::string::npos : start;
    const size_t kw = hash == std::string::npos ? hash : text.find_first_not_of(" \t", hash + 1);
    if (kw == std::string::npos || text.compare(kw, 7, "version") != 0)
        throw Error((sources && sources->count(file) ? file : shaderDir + "/" + file) +
                    ":1: shader must start with #version");
    const size_t eol = text.find('\n', kw);
    const std::string version = text.substr(0, eol == std::string::npos ? text.size() : eol + 1);
    std::ostringstream out;
    out << version;
    for (auto& [k, v] : defines)
        out << "#define " << k << " " << v << "\n";
    out << "#line 2 0\n" << text.substr(version.size());
    return out.str();
}

namespace {
// Reads digits at `i`; false when there are none.
bool digits(const std::string& s, size_t& i, size_t& value) {
    const size_t from = i;
    value = 0;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9' && i - from < 9)
        value = value * 10 + size_t(s[i++] - '0');
    return i > from;
}
// The first "F:L(C)" (Mesa) or "F(L)" (NVIDIA) of a log line: file id, line, where it starts and ends.
bool logLocation(const std::string& s, size_t& id, size_t& line, size_t& at, size_t& end) {
    for (at = 0; at < s.size(); ++at) {
        if (s[at] < '0' || s[at] > '9' || (at > 0 && s[at - 1] >= '0' && s[at - 1] <= '9')) continue;
        size_t i = at, col = 0;
        if (!digits(s, i, id) || i >= s.size()) continue;
        if (s[i] == ':') {
            ++i;
            if (digits(s, i, line) && i < s.size() && s[i] == '(' && digits(s, ++i, col) && i < s.size() && s[i] == ')')
                return end = i + 1, true;
        } else if (s[i] == '(') {
            ++i;
            if (digits(s, i, line) && i < s.size() && s[i] == ')') return end = i + 1, true;
        }
    }
    return false;
}
} // namespace

namespace {
// mapLogToFiles with each file's name as given (a virtual source's) or under "shaders/".
std::string mapLog(const std::string& log, const std::vector<std::string>& files, const Sources* sources) {
    std::istringstream in(log);
    std::ostringstream out;
    std::string line;
    while (std::getline(in, line)) {
        size_t id = 0, no = 0, at = 0, end = 0;
        if (logLocation(line, id, no, at, end) && id < files.size()) {
            const bool virtualName = sources && sources->count(files[id]);
            line = line.substr(0, at) + (virtualName ? "" : "shaders/") + files[id] + ":" + std::to_string(no) +
                   line.substr(end);
        }
        out << line << "\n";
    }
    return out.str();
}

// The first line of a mapped log that names an error (else its first non-blank line), trimmed.
std::string firstError(const std::string& log) {
    std::istringstream in(log);
    std::string line, first;
    while (std::getline(in, line)) {
        const size_t from = line.find_first_not_of(" \t\r"), to = line.find_last_not_of(" \t\r");
        if (from == std::string::npos) continue;
        line = line.substr(from, to - from + 1);
        if (line.find("error") != std::string::npos) return line;
        if (first.empty()) first = line;
    }
    return first.empty() ? "shader compile failed" : first;
}
} // namespace

std::string mapLogToFiles(const std::string& log, const std::vector<std::string>& files) {
    return mapLog(log, files, nullptr);
}

namespace {

std::string infoLog(GLuint id, bool program) {
    GLint len = 0;
    program ? glGetProgramiv(id, GL_INFO_LOG_LENGTH, &len) : glGetShaderiv(id, GL_INFO_LOG_LENGTH, &len);
    std::string log(size_t(std::max(len, 1)), '\0');
    program ? glGetProgramInfoLog(id, len, nullptr, log.data())
            : glGetShaderInfoLog(id, len, nullptr, log.data());
    return log.c_str();
}

ShaderHandle compile(GLenum stage, const std::string& dir, const std::string& file, const Defines& defines,
                     const Sources& sources) {
    std::vector<std::string> files;
    std::string src = preprocessShader(dir, file, defines, files, &sources);
    ShaderHandle sh(glCreateShader(stage));
    const char* p = src.c_str();
    glShaderSource(sh.id(), 1, &p, nullptr);
    glCompileShader(sh.id());
    GLint ok = 0;
    glGetShaderiv(sh.id(), GL_COMPILE_STATUS, &ok);
    if (ok) return sh;
    const std::string log = mapLog(infoLog(sh.id(), false), files, &sources);
    // A source given as text (a user's file) fails with one line naming its file and line.
    if (sources.count(file)) throw Error(firstError(log));
    throw Error("shader compile failed: " + log);
}

// FNV-1a 64 of a virtual source's text: part of its programs' cache keys.
std::string textKey(const std::string& text) {
    unsigned long long h = 0xcbf29ce484222325ull;
    for (unsigned char c : text)
        h = (h ^ c) * 0x100000001b3ull;
    return std::to_string(h);
}

} // namespace

ShaderLibrary::ShaderLibrary(std::string shaderDir) : dir_(std::move(shaderDir)) {}

void ShaderLibrary::setSource(const std::string& name, const std::string& text) {
    auto it = sources_.find(name);
    if (it != sources_.end() && it->second == text) return;
    for (auto e = cache_.begin(); e != cache_.end();) // programs of the old text
        e = e->second.vert == name || e->second.frag == name ? cache_.erase(e) : std::next(e);
    sources_[name] = text;
}

namespace {
SourceGate& sourceGate() {
    static SourceGate gate;
    return gate;
}
} // namespace

void setSourceGate(SourceGate gate) {
    sourceGate() = std::move(gate);
}

ProgramHandle ShaderLibrary::build(const std::string& vert, const std::string& frag, const Defines& defines) const {
    if (const SourceGate& gate = sourceGate())
        if (auto src = sources_.find(frag); src != sources_.end()) gate(dir_, vert, frag, src->second, defines);
    ShaderHandle vs = compile(GL_VERTEX_SHADER, dir_, vert, defines, sources_);
    ShaderHandle fs = compile(GL_FRAGMENT_SHADER, dir_, frag, defines, sources_);
    ProgramHandle prog(glCreateProgram());
    glAttachShader(prog.id(), vs.id());
    glAttachShader(prog.id(), fs.id());
    glLinkProgram(prog.id());
    GLint ok = 0;
    glGetProgramiv(prog.id(), GL_LINK_STATUS, &ok);
    if (!ok) throw Error("shader link failed (" + vert + " + " + frag + "): " + infoLog(prog.id(), true));
    label(GL_PROGRAM, prog.id(), frag);
    return prog;
}

GLuint ShaderLibrary::program(const std::string& vert, const std::string& frag, const Defines& defines) {
    std::string key = vert + "|" + frag;
    for (auto& [k, v] : defines)
        key += "|" + k + "=" + v;
    for (const std::string* stage : {&vert, &frag}) {
        auto src = sources_.find(*stage);
        if (src != sources_.end()) key += "#" + textKey(src->second);
    }
    auto it = cache_.find(key);
    if (it != cache_.end()) return it->second.program.id();
    Entry e{build(vert, frag, defines), vert, frag, defines};
    GLuint id = e.program.id();
    cache_.emplace(key, std::move(e));
    return id;
}

std::vector<ShaderLibrary::Variant> ShaderLibrary::variants() const {
    std::vector<Variant> out;
    for (const auto& [key, e] : cache_)
        if (!sources_.count(e.vert) && !sources_.count(e.frag)) out.push_back({e.vert, e.frag, e.defines});
    return out;
}

void ShaderLibrary::reload() {
    std::map<std::string, Entry> fresh;
    for (auto& [key, e] : cache_)
        fresh.emplace(key, Entry{build(e.vert, e.frag, e.defines), e.vert, e.frag, e.defines});
    cache_.swap(fresh); // only reached when every program compiled and linked
}

std::filesystem::file_time_type ShaderLibrary::newestSourceTime() const {
    auto newest = std::filesystem::file_time_type::min(); // libstdc++ file times before 2174 are negative
    std::error_code ec;
    for (auto it = std::filesystem::recursive_directory_iterator(dir_, ec);
         !ec && it != std::filesystem::end(it); it.increment(ec))
        if (it->is_regular_file(ec)) newest = std::max(newest, it->last_write_time(ec));
    return newest;
}

} // namespace ssao::gl
