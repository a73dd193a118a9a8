// G-buffer in view space (seeds 000/003/004): position, normal, albedo, linear depth, and the
// hardware depth buffer — the inputs every AO technique reads.
#pragma once
#include "gl/resources.h"
#include "gl/shader_library.h"
#include "graph/pass.h"
#include "scene/gpu/gpu_scene.h"
#include "scene/gpu/occlusion_culler.h"
#include "settings/settings.h"

namespace ssao {

SSAO_CONFIG_BEGIN
struct GBufferConfig {
    gpu::FrameConstants frame; // view, projection, depth mapping (without the temporal frame index)
    int32_t normalUnorm;       // normals stored as (n+1)/2 (the rgba8 format's shader variant)
    int32_t cull;              // skip.cull: draws outside the view are not issued
    int32_t skipUnused;        // skip.unused_targets: targets nothing reads are not written
    int32_t hiddenFaces;       // skip.hidden_faces: closed shells' hidden sides are culled
    uint32_t sceneVersion;     // what it draws
    int32_t lod;               // skip.motion_lod while the camera moves: the clustered level drawn, -1 none (FrameInfo::lod)
    int32_t occluded;          // skip.occluded: draws the scene hides are not drawn (scene/gpu/occlusion_culler.h)
    int32_t secondLayer;       // gbuffer.second_layer_build = previous: this pass keeps the second layer too
    float separation;          // its minimum separation, scene units
};
SSAO_CONFIG_END

class GBufferPass final : public ConfiguredPass<GBufferConfig> {
  public:
    GBufferPass() : ConfiguredPass("gbuffer", Chain::a()) {}
    void setup(PassBuilder& b, const Settings& s) const override;
    GBufferConfig config(const Settings& s, const FrameInfo& f) const override;
    // draws, draws_culled, triangles, triangles_culled, targets_written, targets_skipped
    std::vector<std::pair<std::string, double>> counters() const override;
    const std::vector<std::string>& written() const { return written_; }
    // gbuffer.second_layer_build = previous: this pass writes gbuffer.second_layer too.
    static bool keepsSecondLayer(const Settings& s);

  private:
    void run(PassContext& ctx, const GBufferConfig& c) override;
    DrawStats stats_;
    std::vector<std::string> written_; // colour targets the last run wrote
    OcclusionCuller occlusion_;        // skip.occluded: what the last run saw, carried to the next
    // second_layer_build = previous: the last run's gbuffer.position and the camera it was seen from.
    struct Previous {
        gl::Texture2D position;
        glm::mat4 view{1.0f}, proj{1.0f};
        uint32_t sceneVersion = 0;
    } previous_;
    // Binds the cleared layer and the previous frame; whether there was one to reproject.
    bool beginSecondLayer(PassContext& ctx, const GBufferConfig& c, const ScenePrograms& programs);
    void keepPrevious(PassContext& ctx, const GBufferConfig& c); // this frame's position, for the next
};

GLenum glFormat(TargetFormat f);

// The programs a scene pass draws with: `vert` + `frag` with `defines`, and, when the scene has
// MASK draws, the same with ALPHA_MASK (include/alpha_mask.glsl).
ScenePrograms scenePrograms(PassContext& ctx, const std::string& vert, const std::string& frag, gl::Defines defines,
                            GLint colorLocation);

// The state every pass that draws the scene needs, for its scope: the bound framebuffer's first
// `colourTargets` colour attachments cleared to 0 (w = 0: sky), its depth cleared to the far end of
// the mapping, the depth test of the mapping (reversed-Z: GREATER, clip control [0, 1], 1 at near;
// scene/camera.h) and no face culling (glTF doubleSided and CAD winding: shade what is visible;
// GpuScene::draw culls only the faces closed shells hide, and only when asked).
// The other passes draw with the default state again once it goes.
class SceneDrawState {
  public:
    SceneDrawState(bool reversed, int colourTargets);
    ~SceneDrawState();
    SceneDrawState(const SceneDrawState&) = delete;
    SceneDrawState& operator=(const SceneDrawState&) = delete;

  private:
    bool reversed_;
};

} // namespace ssao
