// The hidden commands a parent ssaolab runs in a child process to try untrusted GLSL where it
// cannot hurt: each caps its own address space first (util/process.h limitAddressSpace) and reads
// the bytes its parent checked from `source` (a file in the parent's private folder), never the
// user's file again, so a link swapped in meanwhile is never followed.
//
// `ssaolab probe-technique FILE --size WxH --source BYTES`: the explorer's test of a new version of
// a user technique before it adopts it (app/view/live/technique_watch.h). Under the per-frame time limit
// it renders two frames of builtin:showcase with it at its defaults (the second with the
// inspector's variant) at `width` x `height` - the explorer's render size, so a shader too slow for
// the explorer's frames is refused here - and prints "ok HASH" (the hash of the text it tested) or
// fails with one `ssaolab: error:` line naming FILE:LINE.
//
// `ssaolab compile-glsl NAME --source TEXT --shaders DIR --vert FILE --define K=V ...`: one program of a
// fragment shader registered as NAME (gl/shader_library.h setSourceGate, app/cli/compile_gate.h)
// compiled and linked as the parent would and drawn on one pixel (llvmpipe generates machine code at
// the first draw); prints "ok HASH" or its compile error.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace ssao {

int runProbeTechnique(const std::string& file, const std::string& source, int width, int height, unsigned maxMib);
int runCompileGlsl(const std::string& name, const std::string& source, const std::string& shaderDir,
                   const std::string& vert, const std::vector<std::string>& defines, unsigned maxMib);

} // namespace ssao
