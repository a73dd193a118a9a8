// What a file's first bytes say it is, so an error can name what was given instead of quoting a
// parser ("scene x.jpg is a JPEG image, not a glTF scene (.gltf or .glb)" rather than "not valid
// JSON", or a nesting error from the '[' bytes of random data).
#pragma once
#include <string>

namespace ssao {

// "a PNG image", "a JPEG image", "a GLB (binary glTF) scene", "an OpenEXR image", ... or "binary
// data" for other bytes that are not text; "" for text (which may still be JSON or not).
std::string binaryFileKind(const std::string& bytes);

} // namespace ssao
