// Options every command shares: the frame size and the camera's lens and depth mapping.
#pragma once
#include "scene/camera.h"
#include "scene/scene.h"

#include <string>

namespace CLI {
class App;
}

namespace ssao {

// --projection and --depth (render and view): the camera's lens and depth mapping.
void addLensOptions(CLI::App& cmd, std::string& projection, std::string& depth);
// Applies --clip/--projection/--depth given as text (empty: keep the camera's own).
void applyCameraOptions(Camera& c, const std::string& clip, const std::string& projection,
                        const std::string& depth);
// --camera for bench and tune: "eye,target[,up[,fov_deg[,near,far]]]" in the scene file's coordinates,
// as render takes it.
void addStartCameraOption(CLI::App& cmd, std::string& camera);
// Their first viewpoint (the orbits turn about it): --camera when given, else the scene's own camera.
// Throws ssao::Error naming --camera when it does not parse or is degenerate.
Camera startCamera(const std::string& cameraOption, const Scene& scene);
// "WIDTHxHEIGHT" within the render limits; throws ssao::Error naming --size (render, bench, tune).
void parseSizeOption(const std::string& text, int& w, int& h);

} // namespace ssao
