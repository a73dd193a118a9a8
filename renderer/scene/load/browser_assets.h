// What a browser loading a glTF with three.js's GLTFLoader would fetch (the web engines' harness,
// tools/peers/scene_server.mjs), checked here before the browser starts: every buffer and image is
// embedded (a bufferView, a data: URI) or a relative file path whose components, each
// percent-decoded, are none of '' and '..' ('.' is dropped) and hold no separator, with no '?', '#',
// '+' or control character - the only files the harness serves - and no network or absolute URI; every image (not only MASK textures) is read through the
// scene's folder and byte budget and its header's pixels counted against the budget of decoded
// pixels (--max-mask-mpix, every image of the file in total), the browser decoding them all.
#pragma once
#include <string>

namespace ssao {

// Throws one ssao::Error naming the file, the buffer or image and why.
void checkBrowserAssets(const std::string& sceneFile);

// A URI as the harness serves it: the relative path of its percent-decoded components joined by
// '/' ('.' components dropped), or throws naming the rule it breaks ("a network or absolute URI",
// "leaves the folder", a '?', '#', '+' or control character that readers resolve differently).
std::string servedRelativePath(const std::string& uri);

} // namespace ssao
