#include "gl/shader_library.h"

#include "util/error.h"

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace ssao::gl {

namespace {

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("shader file not found: " + path);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void expand(const std::string& dir, const std::string& file, std::vector<std::string>& files,
            std::set<std::string>& included, std::ostringstream& out, int depth) {
    if (depth > 16) throw Error("shader include depth exceeded at " + file);
    const int fileId = int(files.size());
    files.push_back(file);
    std::istringstream in(readFile(dir + "/" + file));
    static const std::regex includeRe(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        std::smatch m;
        if (std::regex_match(line, m, includeRe)) {
            std::string inc = m[1];
            // Includes are relative to the shader root (like a -I path), e.g. "include/onb.glsl".
            if (included.insert(inc).second) {
                out << "#line 1 " << files.size() << "\n";
                expand(dir, inc, files, included, out, depth + 1);
            }
            out << "#line " << lineNo + 1 << " " << fileId << "\n";
            continue;
        }
        out << line << "\n";
    }
}

} // namespace

std::string preprocessShader(const std::string& shaderDir, const std::string& file, const Defines& defines,
                             std::vector<std::string>& files) {
    files.clear();
    std::ostringstream body;
    std::set<std::string> included;
    expand(shaderDir, file, files, included, body, 0);
    std::string text = body.str();
    // The #version line must come first: pull it out, then inject defines and resync lines.
    static const std::regex versionRe(R"(^\s*#\s*version[^\n]*\n)");
    std::smatch m;
    if (!std::regex_search(text, m, versionRe) || m.position(0) != 0)
        throw Error(shaderDir + "/" + file + ":1: shader must start with #version");
    std::ostringstream out;
    out << m.str(0);
    for (auto& [k, v] : defines)
        out << "#define " << k << " " << v << "\n";
    out << "#line 2 0\n" << text.substr(m.length(0));
    return out.str();
}

std::string mapLogToFiles(const std::string& log, const std::vector<std::string>& files) {
    static const std::regex mesaRe(R"((\d+):(\d+)\(\d+\))");
    static const std::regex nvRe(R"((\d+)\((\d+)\))");
    std::istringstream in(log);
    std::ostringstream out;
    std::string line;
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_search(line, m, mesaRe) || std::regex_search(line, m, nvRe)) {
            size_t id = std::stoul(m[1]);
            if (id < files.size())
                line = "shaders/" + files[id] + ":" + m[2].str() + line.substr(m.position(0) + m.length(0));
        }
        out << line << "\n";
    }
    return out.str();
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

ShaderHandle compile(GLenum stage, const std::string& dir, const std::string& file, const Defines& defines) {
    std::vector<std::string> files;
    std::string src = preprocessShader(dir, file, defines, files);
    ShaderHandle sh(glCreateShader(stage));
    const char* p = src.c_str();
    glShaderSource(sh.id(), 1, &p, nullptr);
    glCompileShader(sh.id());
    GLint ok = 0;
    glGetShaderiv(sh.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) throw Error("shader compile failed: " + mapLogToFiles(infoLog(sh.id(), false), files));
    return sh;
}

} // namespace

ShaderLibrary::ShaderLibrary(std::string shaderDir) : dir_(std::move(shaderDir)) {}

ProgramHandle ShaderLibrary::build(const std::string& dir, const std::string& vert, const std::string& frag,
                                   const Defines& defines) {
    ShaderHandle vs = compile(GL_VERTEX_SHADER, dir, vert, defines);
    ShaderHandle fs = compile(GL_FRAGMENT_SHADER, dir, frag, defines);
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
    auto it = cache_.find(key);
    if (it != cache_.end()) return it->second.program.id();
    Entry e{build(dir_, vert, frag, defines), vert, frag, defines};
    GLuint id = e.program.id();
    cache_.emplace(key, std::move(e));
    return id;
}

std::vector<ShaderLibrary::Variant> ShaderLibrary::variants() const {
    std::vector<Variant> out;
    for (const auto& [key, e] : cache_)
        out.push_back({e.vert, e.frag, e.defines});
    return out;
}

void ShaderLibrary::reload() {
    std::map<std::string, Entry> fresh;
    for (auto& [key, e] : cache_)
        fresh.emplace(key, Entry{build(dir_, e.vert, e.frag, e.defines), e.vert, e.frag, e.defines});
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
