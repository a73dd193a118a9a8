#include "cli/compile_gate.h"

#include "cli/untrusted_child.h"
#include "gl/shader_library.h"
#include "util/error.h"

#include <mutex>
#include <set>

namespace ssao {

void installCompileGate(const std::string& program) {
    gl::setSourceGate([program](const std::string& dir, const std::string& vert, const std::string& frag,
                                const std::string& text, const gl::Defines& defines) {
        static std::mutex mutex;
        static std::set<std::string> passed; // variants that compiled in a child
        std::vector<std::string> args{"compile-glsl", frag, "--shaders", dir, "--vert", vert};
        std::string key = dir + "|" + vert + "|" + frag;
        for (const auto& [k, v] : defines) {
            args.insert(args.end(), {"--define", k + "=" + v});
            key += "|" + k + "=" + v;
        }
        key += std::string(1, '\0') + text; // the text itself: a hash could be made to collide
        std::lock_guard<std::mutex> lock(mutex);
        if (passed.count(key)) return;
        const ChildVerdict v = runUntrustedChild(program, args, text, frag);
        if (!v.ok) throw Error(v.message);
        passed.insert(key);
    });
}

} // namespace ssao
