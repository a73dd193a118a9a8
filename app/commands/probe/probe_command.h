// `ssaolab probe-technique FILE --size WxH` (hidden): the explorer's test of a new version of a user
// technique before it adopts it (app/view/technique_watch.h). In its own process, under the
// per-frame time limit: reads and checks the file, renders two frames of builtin:showcase with it at its
// defaults (the second with the inspector's variant) at `width` x `height` - the explorer's render
// size, so a shader too slow for the explorer's frames is refused by the frame limit here - and
// prints "ok HASH" - the hash of the text it tested - or fails with one `ssaolab: error:` line
// naming FILE:LINE.
#pragma once
#include <string>

namespace ssao {

int runProbeTechnique(const std::string& file, int width, int height);

} // namespace ssao
