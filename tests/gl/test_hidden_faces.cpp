// skip.hidden_faces: the G-buffer culls the hidden side of closed shells (scene/closed_shells.h)
// and sees the same surfaces - on the shared scenes, with the camera inside a closed room, and
// with the near plane cutting a closed box open (where nothing may be culled).
#include "gl_fixture.h"
#include "scene/load/load_scene.h"
#include "gl/readback.h"

#include "scene/scene.h"

#include <cmath>
#include <cstdio>
#include <map>

using namespace ssao;
using namespace ssaotest;

namespace {

class HiddenFaces : public GlTest {};

struct Compared {
    Rendered on, off;
    std::map<std::string, double> countersOn, countersOff;
    size_t differing = 0, geometry = 0; // pixels whose position or normal differs; geometry pixels
    double maxPositionDiff = 0;
};

Compared compare(const Scene& scene, std::optional<Camera> cam, int w, int h) {
    Compared c;
    Settings s = defaultSettings();
    s.skip.occluded = false; // the draws counted alike: this skip alone (test_occlusion.cpp has the other)
    auto r = makeRenderer(scene, s, w, h, cam);
    r->render();
    c.on = readAll(*r), c.countersOn = gbufferCounters(*r);
    s.skip.hiddenFaces = false;
    r->setSettings(s);
    r->render();
    c.off = readAll(*r), c.countersOff = gbufferCounters(*r);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const bool geo = c.on.position.at(x, y, 3) > 0 || c.off.position.at(x, y, 3) > 0;
            c.geometry += geo;
            bool diff = false;
            for (int k = 0; k < 4; ++k) {
                const double dp = std::fabs(c.on.position.at(x, y, k) - c.off.position.at(x, y, k));
                c.maxPositionDiff = std::max(c.maxPositionDiff, dp);
                diff = diff || dp != 0.0;
            }
            for (int k = 0; k < 3; ++k) diff = diff || c.on.normal.at(x, y, k) != c.off.normal.at(x, y, k);
            c.differing += diff;
        }
    return c;
}

// Vertices and a draw of a box's 12 triangles (counter-clockwise from outside, or inside-out).
void addBox(Scene& s, glm::vec3 lo, glm::vec3 hi, bool inward) {
    Draw d;
    d.firstIndex = uint32_t(s.indices.size());
    auto corner = [&](int i) { return glm::vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z); };
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    const glm::vec3 normals[6] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}};
    for (int f = 0; f < 6; ++f) {
        const uint32_t base = uint32_t(s.vertices.size());
        for (int k = 0; k < 4; ++k)
            s.vertices.push_back({corner(faces[f][k]), inward ? -normals[f] : normals[f]});
        const uint32_t tri[6] = {0, 1, 2, 0, 2, 3}, rev[6] = {0, 2, 1, 0, 3, 2};
        for (int k = 0; k < 6; ++k) s.indices.push_back(base + (inward ? rev[k] : tri[k]));
    }
    d.indexCount = 36;
    s.draws.push_back(d);
}

// A room (a closed box, inside-out as rooms are modelled, or outward) around a closed crate.
Scene roomScene(bool roomInward) {
    Scene s;
    s.name = "room";
    addBox(s, glm::vec3(-4, 0, -4), glm::vec3(4, 3, 4), roomInward);
    addBox(s, glm::vec3(-0.5f, 0, -0.5f), glm::vec3(0.5f, 1, 0.5f), false);
    s.computeBounds();
    return s;
}

} // namespace

TEST_F(HiddenFaces, SharedScenesSeeTheSameSurfacesWithLessWork) {
    // Culled closed shells change no surface but the rare pixel at a grazing silhouette, where
    // the front and the back face meet at the same depth and rounding picked the back one.
    const char* scenes[] = {"CornellBox/cornellBox.gltf",      "FlightHelmet/FlightHelmet.gltf",
                            "Lantern/Lantern.gltf",            "ShaderBall/shader_ball.gltf",
                            "2CylinderEngine/2CylinderEngine.gltf", "SciFiHelmet/SciFiHelmet.gltf",
                            "AntiqueCamera/AntiqueCamera.gltf", "ReciprocatingSaw/ReciprocatingSaw.gltf"};
    double culledShare = 0;
    for (const char* name : scenes) {
        const Scene scene = loadScene(std::string(SSAOLAB_SCENES_DIR) + "/" + name);
        Compared c = compare(scene, std::nullopt, 320, 180);
        const double tris = c.countersOn["triangles"];
        std::printf("%-40s %6.0f of %6.0f triangles face-culled; %zu of %zu geometry pixels differ (max position "
                    "diff %.3g, scene radius %.3g)\n",
                    name, c.countersOn["triangles_face_culled"], tris, c.differing, c.geometry, c.maxPositionDiff,
                    scene.bounds.radius());
        EXPECT_EQ(c.countersOff["triangles_face_culled"], 0.0) << name;
        EXPECT_EQ(c.countersOn["triangles"], c.countersOff["triangles"]) << name;
        EXPECT_EQ(c.countersOn["draws"], c.countersOff["draws"]) << name;
        // Seen at 320x180: AntiqueCamera 2 of 2872 pixels, 2.8 mm apart (a pixel spans ~26 mm
        // there), the others none. Where one differs, both surfaces pass through it.
        EXPECT_LE(double(c.differing), 1e-3 * double(c.geometry)) << name;
        EXPECT_LE(c.maxPositionDiff, 1e-3 * scene.bounds.radius()) << name;
        EXPECT_TRUE(finiteInRange(c.on.ao, 0.0f, 1.0f)) << name;
        culledShare += c.countersOn["triangles_face_culled"] / tris;
    }
    // The saw, the lantern and the helmets are mostly closed solids: there is work to skip.
    EXPECT_GT(culledShare / 8.0, 0.3);
}

TEST_F(HiddenFaces, NothingIsCulledAroundTheEyeOrWhereTheNearPlaneCuts) {
    for (const bool inward : {true, false}) {
        const Scene scene = roomScene(inward);
        // Inside the room, looking at the crate: the room's shell holds the eye (not culled),
        // the crate is outside it (culled). An outward room seen from inside shows its back faces:
        // exactly those a wrong cull would remove.
        Camera inside;
        inside.eye = {0, 1.5f, 3.5f}, inside.target = {0, 0.5f, 0};
        Compared a = compare(scene, inside, 160, 90);
        EXPECT_EQ(a.countersOn["triangles_face_culled"], 12.0) << inside.eye.z;
        EXPECT_EQ(a.differing, 0u);
        EXPECT_EQ(a.geometry, size_t(160 * 90)); // walls everywhere: none was culled away
        // The near plane slicing the crate: its inside shows, so it must not be culled either.
        Camera cut = inside;
        cut.clip = ClipMode::Fixed, cut.nearZ = 0.2f, cut.farZ = 50.0f;
        cut.eye = {0, 0.5f, 0.6f}, cut.target = {0, 0.5f, -1};
        Compared b = compare(scene, cut, 160, 90);
        EXPECT_EQ(b.countersOn["triangles_face_culled"], 0.0);
        EXPECT_EQ(b.differing, 0u);
        EXPECT_EQ(maxAbsDiff(b.on.ao, b.off.ao), 0.0);
    }
    // From outside the (outward) room, everything is culled and the image is the same.
    Camera outside;
    outside.eye = {9, 6, 12}, outside.target = {0, 1, 0};
    Compared c = compare(roomScene(false), outside, 160, 90);
    EXPECT_EQ(c.countersOn["triangles_face_culled"], 24.0);
    EXPECT_EQ(c.differing, 0u);
}
