// Shader files loaded at run time from shaders/: `#include "file"` is inlined (once per file),
// `#define`s are injected after #version, and `#line L F` keeps every line attributable, so a
// compile error is reported as "shaders/passes/denoise.frag:42: ...". Programs are cached by
// (stages, define set); a variant is compiled only the first time it is asked for. A program may
// also be built from a source string registered under a virtual name (setSource: a user technique,
// renderer/techniques/user): its includes come from the folder, its errors name it as given.
#pragma once
#include "gl/handle.h"

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace ssao::gl {

using Defines = std::vector<std::pair<std::string, std::string>>;

// Source strings by virtual name (ShaderLibrary::setSource).
using Sources = std::map<std::string, std::string>;

// Pure text processing, testable without GL. Returns GLSL text; `files` receives the file
// table used by the #line directives (index = source-string number). A name in `sources` is read
// from there instead of the folder.
std::string preprocessShader(const std::string& shaderDir, const std::string& file, const Defines& defines,
                             std::vector<std::string>& files, const Sources* sources = nullptr);

// Rewrites driver log lines "0:12(3): error" (Mesa) and "0(12) : error" (NVIDIA) to "file:12: error".
std::string mapLogToFiles(const std::string& log, const std::vector<std::string>& files);

// Text registered with setSource is untrusted (a user's file): before the driver compiles a program
// of it, the process's gate - when one is set - is asked with the shader folder, the program's
// stages, that text and the defines, and may throw ssao::Error to refuse it. The app sets one gate that compiles the same
// program first in a child process under memory and time limits (app/cli/compile_gate.h), so a
// compiler that crashes or blows up does it there.
using SourceGate = std::function<void(const std::string& shaderDir, const std::string& vert, const std::string& frag,
                                      const std::string& text, const Defines& defines)>;
void setSourceGate(SourceGate gate);

class ShaderLibrary {
  public:
    explicit ShaderLibrary(std::string shaderDir);
    // Vertex + fragment program. Throws ssao::Error naming file and line on failure.
    GLuint program(const std::string& vert, const std::string& frag, const Defines& defines = {});
    const std::string& dir() const { return dir_; }
    void clear() { cache_.clear(); }
    // Registers `text` as the shader `name` (used in place of a file under the folder; its
    // includes still come from the folder). A compile error of a program whose fragment shader is
    // `name` is one line "NAME:LINE: message" (no "shaders/" before it). Programs are cached by
    // the text's hash as well, so new text under the same name compiles afresh.
    void setSource(const std::string& name, const std::string& text);
    // Every program built so far, as (vertex file, fragment file, defines): what a test hands to an
    // offline compiler (glslangValidator) to catch GLSL that only one driver accepts.
    struct Variant {
        std::string vert, frag;
        Defines defines;
    };
    std::vector<Variant> variants() const; // of files under the folder (no setSource ones)

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
    ProgramHandle build(const std::string& vert, const std::string& frag, const Defines& defines) const;
    std::string dir_;
    Sources sources_;
    std::map<std::string, Entry> cache_;
};

} // namespace ssao::gl
