// skip.occluded: the G-buffer leaves out draws the scene hides (scene/gpu/occlusion_culler.h) and sees
// the same surfaces - on the shared scenes while the camera orbits (the visible set of one frame
// used by the next), for a part that comes out from behind a wall, and with the eye inside a box.
#include "gl_fixture.h"
#include "scene/load/load_scene.h"

#include "scene/gpu/occlusion_culler.h"
#include "scene/scene.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <map>

using namespace ssao;
using namespace ssaotest;

namespace {

class Occlusion : public GlTest {};

// Geometry pixels whose position or normal differ between two renders of the same view.
size_t differingPixels(const Rendered& a, const Rendered& b) {
    size_t n = 0;
    for (int y = 0; y < a.position.height; ++y)
        for (int x = 0; x < a.position.width; ++x) {
            bool diff = false;
            for (int k = 0; k < 4; ++k) diff = diff || a.position.at(x, y, k) != b.position.at(x, y, k);
            for (int k = 0; k < 3; ++k) diff = diff || a.normal.at(x, y, k) != b.normal.at(x, y, k);
            n += diff;
        }
    return n;
}

// `c` turned by `degrees` about the vertical through its target.
Camera orbited(Camera c, float degrees) {
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(degrees), c.up);
    c.eye = c.target + glm::vec3(turn * glm::vec4(c.eye - c.target, 0.0f));
    return c;
}

// One closed box (12 triangles, counter-clockwise from outside) as a draw of its own.
void addBox(Scene& s, glm::vec3 lo, glm::vec3 hi) {
    Draw d;
    d.firstIndex = uint32_t(s.indices.size());
    const uint32_t base = uint32_t(s.vertices.size());
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 p(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
        s.vertices.push_back({p, glm::normalize(p - (lo + hi) * 0.5f)});
    }
    for (int k = 0; k < 36; ++k) s.indices.push_back(base + uint32_t(OcclusionCuller::kBoxCorners[k]));
    d.indexCount = 36;
    s.draws.push_back(d);
}

} // namespace

TEST_F(Occlusion, GrownBoxesHoldTheirBoundsWithAMargin) {
    Bounds b;
    b.add(glm::vec3(-1, 2, 3)), b.add(glm::vec3(4, 5, 6));
    const Bounds g = OcclusionCuller::grown(b);
    for (int k = 0; k < 3; ++k) {
        EXPECT_LT(g.min[k], b.min[k]);
        EXPECT_GT(g.max[k], b.max[k]);
        EXPECT_LT(b.min[k] - g.min[k], 1e-2f); // a margin over rounding, not a larger box
    }
    // The box's triangles face outward: (b - a) x (c - a) points away from the centre.
    for (int t = 0; t < 12; ++t) {
        const glm::vec3 a = b.corner(OcclusionCuller::kBoxCorners[3 * t]), p = b.corner(OcclusionCuller::kBoxCorners[3 * t + 1]),
                        q = b.corner(OcclusionCuller::kBoxCorners[3 * t + 2]);
        EXPECT_GT(glm::dot(glm::cross(p - a, q - a), (a + p + q) / 3.0f - b.center()), 0.0f) << "triangle " << t;
    }
}

TEST_F(Occlusion, SharedScenesSeeTheSameSurfacesWhileTheCameraOrbits) {
    const char* scenes[] = {"CornellBox/cornellBox.gltf",      "FlightHelmet/FlightHelmet.gltf",
                            "Lantern/Lantern.gltf",            "ShaderBall/shader_ball.gltf",
                            "2CylinderEngine/2CylinderEngine.gltf", "SciFiHelmet/SciFiHelmet.gltf",
                            "AntiqueCamera/AntiqueCamera.gltf", "ReciprocatingSaw/ReciprocatingSaw.gltf"};
    std::map<std::string, double> occludedShare;
    for (const char* name : scenes) {
        const Scene scene = loadScene(std::string(SSAOLAB_SCENES_DIR) + "/" + name);
        Settings on = defaultSettings(), off = on;
        off.skip.occluded = false;
        const Camera start = sceneCamera(scene);
        auto a = makeRenderer(scene, on, 320, 180, start), b = makeRenderer(scene, off, 320, 180, start);
        double triangles = 0, occluded = 0;
        // Frame 0 draws everything (nothing known yet); each later frame starts from the one before
        // it, 20 degrees round: parts come into view and go out of it.
        for (int frame = 0; frame < 6; ++frame) {
            const Camera cam = orbited(start, 20.0f * float(frame));
            a->setCamera(cam), b->setCamera(cam);
            a->render(), b->render();
            const Rendered ra = readAll(*a), rb = readAll(*b);
            auto ca = gbufferCounters(*a), cb = gbufferCounters(*b);
            EXPECT_EQ(differingPixels(ra, rb), 0u) << name << " frame " << frame;
            EXPECT_TRUE(finiteInRange(ra.ao, 0.0f, 1.0f)) << name;
            EXPECT_EQ(cb["draws_occluded"], 0.0) << name;
            EXPECT_EQ(cb["boxes_tested"], 0.0) << name;
            // Every draw in view is either drawn or occluded.
            EXPECT_EQ(ca["draws"] + ca["draws_occluded"], cb["draws"]) << name << " frame " << frame;
            if (frame == 0) { EXPECT_EQ(ca["boxes_tested"], 0.0) << name; }
            if (frame > 0) triangles += cb["triangles"], occluded += ca["triangles_occluded"];
        }
        occludedShare[name] = occluded / std::max(triangles, 1.0);
        std::printf("%-40s %4.1f %% of the triangles in view occluded over frames 1-5\n", name,
                    100.0 * occludedShare[name]);
    }
    // The CAD assemblies: most of their parts are inside others (measured at 320x180: the engine
    // ~50 %, the saw ~40 %).
    EXPECT_GT(occludedShare["2CylinderEngine/2CylinderEngine.gltf"], 0.3);
    EXPECT_GT(occludedShare["ReciprocatingSaw/ReciprocatingSaw.gltf"], 0.2);
}

TEST_F(Occlusion, TheSameSurfacesInEveryLensAndWhileMoving) {
    // The CAD assemblies, whose parts hide each other, through standard depth, an orthographic
    // lens in both depth mappings, and the moving frames' clustered copies (skip.motion_lod, as the
    // app draws while the camera turns): every frame after the first leaves draws out and still
    // shows every pixel as without the culling.
    struct Lens {
        Projection projection;
        DepthMode depth;
        bool moving;
    };
    const Lens lenses[] = {{Projection::Perspective, DepthMode::Standard, false},
                           {Projection::Orthographic, DepthMode::Reversed, false},
                           {Projection::Orthographic, DepthMode::Standard, false},
                           {Projection::Perspective, DepthMode::Reversed, true}};
    for (const char* name : {"2CylinderEngine/2CylinderEngine.gltf", "ReciprocatingSaw/ReciprocatingSaw.gltf"}) {
        const Scene scene = loadScene(std::string(SSAOLAB_SCENES_DIR) + "/" + name);
        for (const Lens& lens : lenses) {
            Settings on = defaultSettings(), off = on;
            off.skip.occluded = false;
            Camera start = sceneCamera(scene);
            start.projectionKind = lens.projection, start.depth = lens.depth;
            std::unique_ptr<Renderer> r[2];
            for (int k = 0; k < 2; ++k) {
                r[k] = std::make_unique<Renderer>(SSAOLAB_SHADER_DIR);
                r[k]->setSize(240, 135);
                if (lens.moving) r[k]->enableMotionLods();
                r[k]->setScene(scene);
                r[k]->setSettings(k == 0 ? on : off);
                r[k]->setMoving(lens.moving);
            }
            const std::string label = std::string(name) + " " + projectionName(lens.projection) + " " +
                                      depthModeName(lens.depth) + (lens.moving ? " moving" : "");
            double occluded = 0;
            for (int frame = 0; frame < 4; ++frame) {
                const Camera cam = orbited(start, 15.0f * float(frame));
                r[0]->setCamera(cam), r[1]->setCamera(cam);
                r[0]->render(), r[1]->render();
                if (lens.moving) {
                    EXPECT_GE(r[0]->drewLod(), 0) << label;
                }
                EXPECT_EQ(differingPixels(readAll(*r[0]), readAll(*r[1])), 0u) << label << " frame " << frame;
                if (frame > 0) occluded += gbufferCounters(*r[0])["draws_occluded"];
            }
            EXPECT_GT(occluded, 0.0) << label;
        }
    }
}

TEST_F(Occlusion, APartComingOutFromBehindAWallIsDrawnInThatFrame) {
    // A wall (a thin box) at z = 0 and a small box behind it: seen from the front the box is
    // hidden and left out; a camera moved to the side sees it at once, though the frame before
    // counted it hidden.
    Scene s;
    s.name = "wall";
    addBox(s, glm::vec3(-2, -2, -0.1f), glm::vec3(2, 2, 0.1f));
    addBox(s, glm::vec3(-0.5f, -0.5f, -2.0f), glm::vec3(0.5f, 0.5f, -1.0f));
    s.computeBounds();
    Camera front;
    front.eye = glm::vec3(0, 0, 6), front.target = glm::vec3(0, 0, -1);
    Settings on = defaultSettings(), off = on;
    off.skip.occluded = false;
    auto a = makeRenderer(s, on, 160, 90, front), b = makeRenderer(s, off, 160, 90, front);
    a->render(), a->invalidate(), a->render(); // the second frame knows the box was hidden
    EXPECT_EQ(gbufferCounters(*a)["draws_occluded"], 1.0);
    EXPECT_EQ(gbufferCounters(*a)["triangles_occluded"], 12.0);
    Camera side = front;
    side.eye = glm::vec3(7, 0, -1.5f);
    a->setCamera(side), b->setCamera(side);
    a->render(), b->render();
    const Rendered ra = readAll(*a), rb = readAll(*b);
    EXPECT_EQ(gbufferCounters(*a)["draws_occluded"], 0.0);
    EXPECT_EQ(gbufferCounters(*a)["boxes_tested"], 1.0); // it was tested, and shown
    EXPECT_EQ(differingPixels(ra, rb), 0u);
    // The box is on screen: positions with z in [-2, -1] in world space, i.e. seen beside the wall.
    size_t boxPixels = 0;
    const glm::mat4 toWorld = glm::inverse(side.view());
    for (int y = 0; y < ra.position.height; ++y)
        for (int x = 0; x < ra.position.width; ++x)
            if (ra.position.at(x, y, 3) > 0) {
                const glm::vec4 p = toWorld * glm::vec4(ra.position.at(x, y, 0), ra.position.at(x, y, 1),
                                                        ra.position.at(x, y, 2), 1.0f);
                boxPixels += p.z < -0.9f;
            }
    EXPECT_GT(boxPixels, 50u);
}

TEST_F(Occlusion, ABoxAroundTheEyeIsDrawnUntested) {
    // A closed room (a box draw) with a crate in it, and a wall outside it (drawn first): from
    // beyond the wall the room and the crate are hidden and left out; then the eye moves into the room. The
    // room's box now holds the eye (its test would see only back faces): it is drawn without
    // one, and the crate's box is tested and shown.
    Scene s;
    s.name = "room";
    addBox(s, glm::vec3(-10, -5, 6), glm::vec3(10, 10, 6.5f));
    addBox(s, glm::vec3(-4, 0, -4), glm::vec3(4, 3, 4));
    addBox(s, glm::vec3(-0.5f, 0, -0.5f), glm::vec3(0.5f, 1, 0.5f));
    s.computeBounds();
    Camera outside;
    outside.eye = glm::vec3(0, 1.5f, 20), outside.target = glm::vec3(0, 1.5f, 0);
    Settings on = defaultSettings(), off = on;
    off.skip.occluded = false;
    auto a = makeRenderer(s, on, 160, 90, outside), b = makeRenderer(s, off, 160, 90, outside);
    a->render(), a->invalidate(), a->render();
    EXPECT_EQ(gbufferCounters(*a)["draws_occluded"], 2.0);
    Camera inside = outside;
    inside.eye = glm::vec3(0, 1.5f, 3), inside.target = glm::vec3(0, 0.5f, 0);
    a->setCamera(inside), b->setCamera(inside);
    a->render(), b->render();
    EXPECT_EQ(differingPixels(readAll(*a), readAll(*b)), 0u);
    EXPECT_EQ(gbufferCounters(*a)["draws_occluded"], 0.0);
    EXPECT_EQ(gbufferCounters(*a)["boxes_tested"], 1.0); // the crate's; the room's holds the eye
}
