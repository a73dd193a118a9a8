#include "techniques/user/user_source.h"

#include "util/error.h"

#include "../../../shaders/include/bindings.h"


namespace ssao {

namespace {

void checkNames(const UserTechnique& t) {
    for (const UserParam& p : t.header.params) {
        const bool global = p.name == "frame" || p.name == "ssao";
        const bool macros = p.type == UserParam::Type::Enum && (p.name == "ao" || p.name == "inspect");
        if (global || macros)
            throw Error(t.path + ":" + std::to_string(p.line) + ": parameter name '" + p.name + "' is reserved by " +
                        (global ? "the interface's globals" : "the interface's macros (" + p.name + "_...)"));
    }
}

} // namespace

UserTechnique loadUserTechnique(const std::string& text, const std::string& path,
                                const std::vector<std::string>& builtinIds) {
    UserTechnique t;
    t.path = path;
    t.name = userTechniqueName(path, builtinIds);
    t.text = text;
    t.header = parseUserHeader(text, path, builtinIds);
    t.hash = userTechniqueHash(text);
    checkNames(t);
    checkUserBody(t.text, t.path);
    return t;
}

std::string userShaderSource(const UserTechnique& t) {
    // The includes of the built-ins (gtao.frag, kernel.frag) and the interface last: it uses them all.
    std::string s = "#version 450 core\n"
                    "#include \"include/bindings.h\"\n"
                    "#include \"techniques/user/layout.h\"\n"
                    "#include \"include/frame.glsl\"\n"
                    "#include \"include/onb.glsl\"\n"
                    "#include \"include/ao_common.glsl\"\n"
                    "#include \"include/noise.glsl\"\n"
                    "#include \"include/position_taps.glsl\"\n"
                    "#include \"include/slice.glsl\"\n"
                    "#include \"include/inspect.glsl\"\n"
                    "#include \"include/user_interface.glsl\"\n";
    // The generated block numbered from the first parameter's line (its first member there), so an
    // error in it names the header; it ends with #line 1: the file follows as its own lines.
    const int first = t.header.params.empty() ? 1 : t.header.params.front().line;
    s += "#line " + std::to_string(first > 2 ? first - 2 : 1) + "\n";
    s += userParamsGlsl(t.header, SSAO_UBO_USER);
    s += t.text;
    if (!t.text.empty() && t.text.back() != '\n') s += "\n";
    return s;
}

GLuint userProgram(gl::ShaderLibrary& lib, const UserTechnique& t, const gl::Defines& defines) {
    lib.setSource(t.path, userShaderSource(t));
    return lib.program("passes/fullscreen.vert", t.path, defines);
}

} // namespace ssao
