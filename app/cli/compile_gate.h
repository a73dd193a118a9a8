// The process's gate for untrusted shader text (gl/shader_library.h setSourceGate): each program of
// a user's GLSL - its text, stages and defines - is compiled first by `ssaolab compile-glsl` in a
// child process (cli/untrusted_child.h); only a program that compiled there is compiled here. Each
// variant is tried once per process. The commands that run in such a child set no gate.
#pragma once
#include <string>

namespace ssao {

// `program`: the ssaolab binary the children run.
void installCompileGate(const std::string& program);

} // namespace ssao
