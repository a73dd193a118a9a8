// Procedural scenes selectable as builtin:NAME. Units are metres; +y is up.
#include "scene/load/builtin_scenes.h"

#include "util/error.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace ssao {

namespace {

class Builder {
  public:
    explicit Builder(Scene& s) : s_(s) {}

    void begin(glm::vec3 color) {
        flush();
        cur_.firstIndex = uint32_t(s_.indices.size());
        cur_.baseColor = glm::vec4(color, 1.0f);
    }
    void flush() {
        cur_.indexCount = uint32_t(s_.indices.size()) - cur_.firstIndex;
        if (cur_.indexCount) s_.draws.push_back(cur_);
        cur_.firstIndex = uint32_t(s_.indices.size());
    }
    // Quad p0..p3 counter-clockwise seen from the side its normal points to.
    void quad(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3) {
        glm::vec3 n = glm::normalize(glm::cross(p1 - p0, p3 - p0));
        uint32_t b = uint32_t(s_.vertices.size());
        for (auto& p : {p0, p1, p2, p3})
            s_.vertices.push_back({p, n});
        s_.indices.insert(s_.indices.end(), {b, b + 1, b + 2, b, b + 2, b + 3});
    }
    void box(glm::vec3 lo, glm::vec3 hi) {
        glm::vec3 c[8];
        for (int i = 0; i < 8; ++i)
            c[i] = {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
        quad(c[0], c[4], c[6], c[2]); // -x
        quad(c[1], c[3], c[7], c[5]); // +x
        quad(c[0], c[1], c[5], c[4]); // -y
        quad(c[2], c[6], c[7], c[3]); // +y
        quad(c[0], c[2], c[3], c[1]); // -z
        quad(c[4], c[5], c[7], c[6]); // +z
    }
    void sphere(glm::vec3 center, float r, int slices = 48, int stacks = 24) {
        uint32_t b = uint32_t(s_.vertices.size());
        for (int i = 0; i <= stacks; ++i) {
            float th = glm::pi<float>() * float(i) / float(stacks);
            for (int j = 0; j <= slices; ++j) {
                float ph = glm::two_pi<float>() * float(j) / float(slices);
                glm::vec3 n(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
                s_.vertices.push_back({center + r * n, n});
            }
        }
        for (int i = 0; i < stacks; ++i)
            for (int j = 0; j < slices; ++j) {
                uint32_t a = b + uint32_t(i * (slices + 1) + j), c = a + uint32_t(slices + 1);
                s_.indices.insert(s_.indices.end(), {a, a + 1, c, a + 1, c + 1, c});
            }
    }
    void floor(float half, float y = 0.0f) {
        quad({-half, y, -half}, {-half, y, half}, {half, y, half}, {half, y, -half});
    }

  private:
    Scene& s_;
    Draw cur_;
};

const glm::vec3 kFloor(0.75f, 0.72f, 0.68f), kWall(0.8f, 0.8f, 0.82f), kRed(0.8f, 0.25f, 0.2f),
    kBlue(0.25f, 0.4f, 0.8f), kGreen(0.3f, 0.7f, 0.35f);

Scene showcase() {
    Scene s;
    Builder b(s);
    b.begin(kFloor);
    b.floor(6.0f);
    b.begin(kWall);
    b.box({-6.0f, 0.0f, -6.0f}, {6.0f, 3.0f, -5.8f}); // back wall: floor/wall edge
    b.box({-6.0f, 0.0f, -5.8f}, {-5.8f, 3.0f, 2.0f}); // left wall: second edge and a 3-way corner
    b.begin(kBlue);
    for (int i = 0; i < 4; ++i) // stairs rising towards the back wall: concave step corners
        b.box({2.0f, 0.0f, -5.8f}, {4.5f, 0.3f * float(i + 1), -5.8f + 0.6f * float(4 - i)});
    b.begin(kRed);
    b.sphere({-1.5f, 0.8f, -2.0f}, 0.8f); // resting on the floor: contact point
    b.begin(kGreen);
    b.box({-4.8f, 0.0f, -0.5f}, {-3.8f, 1.2f, 0.2f}); // two blocks 6 cm apart: a narrow crevice
    b.box({-4.8f, 0.0f, 0.26f}, {-3.8f, 1.2f, 0.96f});
    b.flush();
    s.camera = Camera{{3.2f, 2.4f, 3.6f}, {-1.6f, 0.5f, -3.2f}, {0, 1, 0}, 60.0f, 0.1f, 60.0f};
    return s;
}

Scene plane() {
    Scene s;
    Builder b(s);
    b.begin(kFloor);
    b.floor(20.0f);
    b.flush();
    // 45° down onto the floor: every pixel of a 16:9 frame sees floor.
    s.camera = Camera{{0.0f, 4.0f, 4.0f}, {0.0f, 0.0f, 0.0f}, {0, 1, 0}, 50.0f, 0.1f, 50.0f};
    return s;
}

Scene corner() {
    Scene s;
    Builder b(s);
    b.begin(kFloor);
    b.floor(10.0f);
    b.begin(kWall);
    b.box({-10.0f, 0.0f, -2.2f}, {10.0f, 6.0f, -2.0f}); // wall face at z = -2
    b.flush();
    s.camera = Camera{{0.0f, 2.5f, 4.0f}, {0.0f, 0.3f, -2.0f}, {0, 1, 0}, 50.0f, 0.1f, 50.0f};
    return s;
}

// The corner with its wall hidden from the designed camera: a 0.1-thick plate near the camera whose
// lower edge lies on the eye's ray through the crease, so the image shows the floor up to the crease
// and the plate above it, never the wall. The plate is over 1.5 units from every floor point within
// 2 units of the wall: at R <= 1.5 it occludes none of them, and their AO is the corner's closed form,
// which only what the depth buffer hides can give (the second layer, gbuffer.second_layer).
Scene hidden() {
    Scene s = corner();
    Builder b(s);
    b.begin(kWall);
    // The eye (0, 2.5, 4) to the crease (x, 0, -2) crosses z = 1 at y = 1.25 for every x.
    b.box({-10.0f, 1.26f, 0.95f}, {10.0f, 6.0f, 1.05f});
    b.flush();
    return s;
}

// Three 0.1-thick slabs that pass through each other as CornellBox's walls do: each ends at the
// mid-plane of the others, so the visible floor/wall crease lies inside the other slab's volume
// to within rounding. Floor y in [-0.05, 0.05] over x, z in [0, 4]; back wall z in [-0.05, 0.05];
// left wall x in [-0.05, 0.05]; the inner corner at (0.05, 0.05, 0.05). The designed camera looks
// at the floor/back-wall crease from its bisecting plane with `up` normal to the plane through the
// eye and the crease, so the crease projects onto the centre row of any odd-height image: those
// pixel centres hit the crease exactly (CornellBox's diagonal creases do the same by symmetry).
// Closed forms (R well under the slabs' 4 units): AO 0.5 on a straight crease and
// 1 - (acos a - a sqrt(1 - a^2)) / pi at distance d from it, a = min(d / R, 1).
Scene slabs() {
    Scene s;
    Builder b(s);
    b.begin(kFloor);
    b.box({0.0f, -0.05f, 0.0f}, {4.0f, 0.05f, 4.0f});
    b.begin(kWall);
    b.box({0.0f, 0.0f, -0.05f}, {4.0f, 4.0f, 0.05f}); // back wall
    b.box({-0.05f, 0.0f, 0.0f}, {0.05f, 4.0f, 4.0f}); // left wall
    b.flush();
    s.camera = Camera{{3.5f, 1.55f, 1.55f}, {2.0f, 0.05f, 0.05f}, {0.0f, 1.0f, -1.0f}, 50.0f, 0.1f, 20.0f};
    return s;
}

} // namespace

std::vector<std::string> builtinSceneNames() {
    return {"showcase", "plane", "corner", "slabs", "hidden"};
}

Scene makeBuiltinScene(const std::string& name) {
    Scene s;
    if (name == "showcase")
        s = showcase();
    else if (name == "plane")
        s = plane();
    else if (name == "corner")
        s = corner();
    else if (name == "slabs")
        s = slabs();
    else if (name == "hidden")
        s = hidden();
    else {
        std::string list;
        for (auto& n : builtinSceneNames())
            list += (list.empty() ? "" : ", ") + n;
        throw Error("unknown built-in scene 'builtin:" + name + "' (available: " + list + ")");
    }
    s.name = "builtin:" + name;
    s.computeBounds();
    // A built-in scene's designed view keeps its designed clip planes (the golden images are made
    // with them); glTF cameras and framed views get planes fitted to the bounds.
    if (s.camera) s.camera->clip = ClipMode::Fixed;
    return s;
}

} // namespace ssao
