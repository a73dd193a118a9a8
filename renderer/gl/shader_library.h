// Shader files loaded at run time from shaders/: `#include "file"` is inlined (once per file),
// `#define`s are injected after #version, and `#line L F` keeps every line attributable, so a
// compile error is reported as "shaders/passes/denoise.frag:42: ...". Programs are cached by
// (stages, define set); a variant is compiled only the first time it is asked for.
#pragma once
#include "gl/handle.h"

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace ssao::gl {

using Defines = std::vector<std::pair<std::string, std::string>>;

// Pure text processing, testable without GL. Returns GLSL text; `files` receives the file
// table used by the #line directives (index = source-string number).
std::string preprocessShader(const std::string& shaderDir, const std::string& file, const Defines& defines,
                             std::vector<std::string>& files);

// Rewrites driver log lines "0:12(3): error" (Mesa) and "0(12) : error" (NVIDIA) to "file:12: error".
std::string mapLogToFiles(const std::string& log, const std::vector<std::string>& files);

class ShaderLibrary {
  public:
    explicit ShaderLibrary(std::string shaderDir);
    // Vertex + fragment program. Throws ssao::Error naming file and line on failure.
    GLuint program(const std::string& vert, const std::string& frag, const Defines& defines = {});
    const std::string& dir() const { return dir_; }
    void clear() { cache_.clear(); }
    // Every program built so far, as (vertex file, fragment file, defines): what a test hands to an
    // offline compiler (glslangValidator) to catch GLSL that only one driver accepts.
    struct Variant {
        std::string vert, frag;
        Defines defines;
    };
    std::vector<Variant> variants() const;

    // Hot reload: recompiles every cached program from disk, all or nothing. On a compile error
    // the previous programs stay in use and the error (with file:line) is thrown.
    void reload();
    // Newest modification time of any file under the shader folder (cheap: a few files).
    std::filesystem::file_time_type newestSourceTime() const;

  private:
    struct Entry {
        ProgramHandle program;
        std::string vert, frag;
        Defines defines;
    };
    static ProgramHandle build(const std::string& dir, const std::string& vert, const std::string& frag,
                               const Defines& defines);
    std::string dir_;
    std::map<std::string, Entry> cache_;
};

} // namespace ssao::gl
