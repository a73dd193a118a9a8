// A user technique's file made into a fragment shader: its header parsed (user_header.h), its body
// checked for what the interface forbids, and the GLSL assembled around it - #version, the
// includes the built-ins use, the shared AO block, the input interface (shaders/include/
// user_interface.glsl, which holds main()), the generated SsaoUserParams block and the file's own
// text after a #line reset, so the compiler's line numbers are the file's.
#pragma once
#include "gl/shader_library.h"
#include "techniques/user/user_header.h"

#include <string>
#include <vector>

namespace ssao {

struct UserTechnique {
    std::string path;   // as errors name it; also the shader library's name for its source
    std::string name;   // NAME of NAME.ao.glsl
    std::string text;   // the whole file
    UserHeader header;
    std::string hash;   // userTechniqueHash(text)
};

// Parses and checks a NAME.ao.glsl file's text (read through util/files.h by the caller). Beyond
// the header's rules: no parameter may be named as a global of the interface (frame, ssao) nor be
// an enum whose #defines would start as the interface's macros do (ao, inspect), and the body may
// not #include. Every error is one ssao::Error "PATH:LINE: message".
UserTechnique loadUserTechnique(const std::string& text, const std::string& path,
                                const std::vector<std::string>& builtinIds);

// The body's limits, checked on its tokens before any compiler sees it (user_body.cpp): no
// #include, #line, #version, #extension or ## token pasting; macros measured as they would expand
// (each #define's brackets balanced); at most kMaxUserExpandedTokens tokens and steps of macro
// expansion, kMaxUserStatementTokens tokens in one statement (the compiler's recursion on one
// expression), kMaxUserNesting levels of brackets and kMaxUserArrayElements elements in an array
// of a constant size. What these checks cannot see (a size the driver folds from a function) meets
// the compile gate's child process (gl/shader_library.h setSourceGate). Throws "PATH:LINE: ...".
constexpr int kMaxUserExpandedTokens = 1 << 17;
constexpr int kMaxUserStatementTokens = 8192;
constexpr int kMaxUserNesting = 64;
constexpr int kMaxUserArrayElements = 4096;
void checkUserBody(const std::string& text, const std::string& path);

// The fragment shader's source (the shader loader inlines its includes from shaders/).
std::string userShaderSource(const UserTechnique& t);

// Registers the technique's source with `lib` and returns the program for `defines` (the AO
// pass's feature defines: techniques/ao_pass.h aoFeatureDefines). A compile error is one
// ssao::Error "PATH:LINE: error: ..." naming the user's line.
GLuint userProgram(gl::ShaderLibrary& lib, const UserTechnique& t, const gl::Defines& defines);

} // namespace ssao
