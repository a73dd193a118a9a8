#include "commands/probe/probe_command.h"

#include "cli/headless_runner.h"
#include "gl/resources.h"
#include "gl/shader_library.h"
#include "settings/params.h"
#include "techniques/technique.h"
#include "techniques/user/user_folder.h"
#include "techniques/user/user_technique.h"
#include "util/error.h"
#include "util/files.h"
#include "util/paths.h"
#include "util/process.h"

#include <cstdio>
#include <filesystem>

namespace ssao {

namespace {
constexpr size_t kMaxShaderBytes = size_t(4) << 20; // an assembled user shader: the file's 256 KiB and the includes

// The bytes the parent wrote: a regular file in its private folder, opened without following a link.
std::string readSource(const std::string& source, const std::string& what, size_t maxBytes) {
    const std::filesystem::path p(source);
    return readFileInside(p.has_parent_path() ? p.parent_path().string() : ".", p.filename().string(), what, maxBytes);
}
} // namespace

int runProbeTechnique(const std::string& file, const std::string& source, int width, int height, unsigned maxMib) {
    if (maxMib) limitAddressSpace(maxMib);
    std::shared_ptr<const UserTechnique> t;
    if (source.empty()) {
        t = readUserTechnique(file);
    } else {
        std::string text;
        try {
            text = readSource(source, "user technique", kMaxUserFileBytes);
        } catch (const FileTooLarge&) {
            throw Error(file + ":1: the file is larger than " + std::to_string(kMaxUserFileBytes >> 10) + " KiB");
        }
        t = std::make_shared<const UserTechnique>(loadUserTechnique(text, file, builtinTechniqueIds()));
    }
    setUserTechniques({t});
    Settings s = defaultSettings();
    s.ao.technique = userTechniqueId(t->name);
    HeadlessRunner run;
    const Scene scene = loadNamedScene("builtin:showcase");
    auto r = run.makeRenderer(width, height);
    r->setScene(scene);
    r->setCamera(defaultCamera(scene));
    r->setSettings(s);
    r->render();
    run.readFinite(*r, "ao.raw", t->path);
    r->inspect(0, {width / 2, height / 2}); // the inspector's variant compiles and runs too
    run.checkGl(t->path);
    std::printf("ok %s\n", t->hash.c_str());
    return 0;
}

int runCompileGlsl(const std::string& name, const std::string& source, const std::string& shaderDir,
                   const std::string& vert, const std::vector<std::string>& defines, unsigned maxMib) {
    if (maxMib) limitAddressSpace(maxMib);
    const std::string text = readSource(source, "shader source", kMaxShaderBytes);
    gl::Defines defs;
    for (const std::string& d : defines) {
        const size_t eq = d.find('=');
        if (eq == std::string::npos || eq == 0) throw Error("--define " + d + ": not NAME=VALUE");
        defs.emplace_back(d.substr(0, eq), d.substr(eq + 1));
    }
    HeadlessRunner run;
    gl::ShaderLibrary lib(shaderDir.empty() ? shaderRoot() : shaderDir);
    lib.setSource(name, text);
    const GLuint program = lib.program(vert, name, defs);
    // One pixel drawn: llvmpipe generates a shader's machine code at its first draw, which must
    // happen here too, not first in the parent.
    gl::RenderTarget target;
    target.ensure(1, 1, GL_R32F, "compile-glsl.target");
    target.bind();
    glViewport(0, 0, 1, 1);
    glUseProgram(program);
    gl::FullscreenTriangle().draw();
    glFinish();
    run.checkGl(name);
    std::printf("ok %s\n", userTechniqueHash(text).c_str());
    return 0;
}

} // namespace ssao
