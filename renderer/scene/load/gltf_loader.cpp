// glTF 2.0 → Scene: meshes under the default scene's node hierarchy, flattened to world space.
#include "scene/load/gltf_loader.h"

#include "scene/load/gltf_accessors.h"
#include "scene/load/gltf_files.h"
#include "scene/load/gltf_guard.h"
#include "scene/load/gltf_instancing.h"
#include "scene/load/gltf_materials.h"
#include "scene/view_fit.h"
#include "util/error.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>

namespace ssao {

namespace {

// A file that requires an extension a loader does not support must be refused (glTF 2.0 §3.12).
// ssaolab honours instancing, texture transforms and transmission (as BLEND); the rest of this list
// changes neither geometry nor coverage (shading, lights, texture formats: images are decoded only
// for MASK cut-outs, which name a texture they cannot read). Anything else - compressed or quantised
// geometry, an extension this list does not know - is refused by name.
bool supportedRequirement(const std::string& ext) {
    static const char* exact[] = {"EXT_mesh_gpu_instancing", "KHR_texture_transform", "KHR_lights_punctual",
                                  "KHR_texture_basisu", "EXT_texture_webp", "KHR_xmp_json_ld"};
    for (const char* e : exact)
        if (ext == e) return true;
    // Material models (transmission, volume, ior, specular, clearcoat, sheen, unlit, ...) shade; they
    // do not move a surface. KHR_materials_variants only switches among materials.
    return ext.rfind("KHR_materials_", 0) == 0;
}

// Converts strips and fans to lists; returns an empty list for points/lines (no surface, no AO).
std::vector<uint32_t> toTriangleList(const std::vector<uint32_t>& in, int mode) {
    if (mode == TINYGLTF_MODE_TRIANGLES) return in;
    std::vector<uint32_t> out;
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (size_t i = 2; i < in.size(); ++i) {
            if (i % 2 == 0)
                out.insert(out.end(), {in[i - 2], in[i - 1], in[i]});
            else
                out.insert(out.end(), {in[i - 1], in[i - 2], in[i]});
        }
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        for (size_t i = 2; i < in.size(); ++i)
            out.insert(out.end(), {in[0], in[i - 1], in[i]});
    }
    return out;
}

// In double: a node 1e6 units from the origin keeps its mesh's sub-millimetre detail until the
// positions are made relative to the scene's origin (Scene::setWorldPositions).
glm::dmat4 localMatrix(const tinygltf::Node& n) {
    if (n.matrix.size() == 16) {
        glm::dmat4 m;
        for (int i = 0; i < 16; ++i)
            glm::value_ptr(m)[i] = n.matrix[i];
        return m;
    }
    glm::dmat4 m(1.0);
    if (n.translation.size() == 3)
        m = glm::translate(m, glm::dvec3(n.translation[0], n.translation[1], n.translation[2]));
    if (n.rotation.size() == 4)
        m *= glm::mat4_cast(glm::dquat(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]));
    if (n.scale.size() == 3) m = glm::scale(m, glm::dvec3(n.scale[0], n.scale[1], n.scale[2]));
    return m;
}

bool finite3(const glm::dvec3& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Counts the primitive's triangles by material class; false when the class is skipped: BLEND and
// transmissive surfaces by default, as engines draw them after the AO (scene.h Transparent).
bool countMaterial(MaterialClass cls, size_t tris, Scene& s) {
    if (cls == MaterialClass::Blend) {
        s.materials.blend += tris;
        if (transparentMode() == Transparent::Skip) {
            s.materials.blendSkipped = true;
            return false;
        }
    } else if (cls == MaterialClass::Mask) {
        s.materials.mask += tris;
    } else {
        s.materials.opaque += tris;
    }
    return true;
}

void pushUv(Scene& s, const std::vector<glm::vec2>& uv, uint32_t i) {
    if (!s.uvs.empty()) s.uvs.push_back(uv.empty() ? glm::vec2(0.0f) : uv[i]);
}

// The primitive's own normals: one vertex per glTF vertex, the triangles indexing them.
void appendSmooth(const Vec3Reader& pos, const Vec3Reader& nrm, const std::vector<uint32_t>& idx,
                  const glm::dmat4& world, const std::vector<glm::vec2>& uv, Scene& s,
                  std::vector<glm::dvec3>& worldPos, const std::string& what) {
    const glm::mat3 normalMat = glm::mat3(glm::transpose(glm::inverse(glm::dmat3(world))));
    const bool mirrored = glm::determinant(glm::dmat3(world)) < 0.0;
    const uint32_t base = uint32_t(s.vertices.size());
    for (size_t i = 0; i < pos.count; ++i) {
        const glm::dvec3 wp = glm::dvec3(world * glm::dvec4(glm::dvec3(pos[i]), 1.0));
        if (!finite3(wp) || !finite3(glm::dvec3(glm::vec3(wp))))
            throw Error(what + ": POSITION " + std::to_string(i) + " is not finite");
        glm::vec3 n = normalMat * nrm[i];
        float len = glm::length(n);
        n = (len > 1e-20f && std::isfinite(len)) ? n / len : glm::vec3(0, 1, 0);
        s.vertices.push_back({glm::vec3(0.0f), n});
        worldPos.push_back(wp);
        pushUv(s, uv, uint32_t(i));
    }
    for (size_t t = 0; t + 2 < idx.size(); t += 3) {
        uint32_t a = idx[t], b = idx[t + 1], c = idx[t + 2];
        if (mirrored) std::swap(b, c); // keep counter-clockwise front faces
        s.indices.insert(s.indices.end(), {base + a, base + b, base + c});
    }
}

// No normals: flat normals per face (glTF spec: "client implementations MUST calculate flat
// normals"), three vertices per triangle.
void appendFlat(const Vec3Reader& pos, const std::vector<uint32_t>& idx, const glm::dmat4& world,
                const std::vector<glm::vec2>& uv, Scene& s, std::vector<glm::dvec3>& worldPos,
                const std::string& what) {
    const bool mirrored = glm::determinant(glm::dmat3(world)) < 0.0;
    for (size_t t = 0; t + 2 < idx.size(); t += 3) {
        auto at = [&](uint32_t i) { return glm::dvec3(world * glm::dvec4(glm::dvec3(pos[i]), 1.0)); };
        glm::dvec3 p0 = at(idx[t]), p1 = at(idx[t + 1]), p2 = at(idx[t + 2]);
        for (const glm::dvec3& q : {p0, p1, p2})
            if (!finite3(q) || !finite3(glm::dvec3(glm::vec3(q))))
                throw Error(what + ": a POSITION is not finite");
        uint32_t corner[3] = {idx[t], idx[t + 1], idx[t + 2]};
        if (mirrored) std::swap(p1, p2), std::swap(corner[1], corner[2]);
        glm::dvec3 nd = glm::cross(p1 - p0, p2 - p0);
        const double len = glm::length(nd);
        const glm::vec3 n = len > 1e-30 && std::isfinite(len) ? glm::vec3(nd / len) : glm::vec3(0, 1, 0);
        uint32_t v0 = uint32_t(s.vertices.size());
        for (const glm::dvec3& q : {p0, p1, p2}) {
            s.vertices.push_back({glm::vec3(0.0f), n});
            worldPos.push_back(q);
        }
        for (uint32_t k : corner)
            pushUv(s, uv, k);
        s.indices.insert(s.indices.end(), {v0, v0 + 1, v0 + 2});
    }
}

// Appends the primitive's triangles; positions go to `world` (file coordinates, double), one per
// vertex, to be made relative to the scene's origin once every mesh is in.
void appendPrimitive(const tinygltf::Model& m, const tinygltf::Primitive& p, const glm::dmat4& world, Scene& s,
                     std::vector<glm::dvec3>& worldPos, const std::string& what, MaskTextures& masks) {
    auto posIt = p.attributes.find("POSITION");
    if (posIt == p.attributes.end()) throw Error(what + ": primitive has no POSITION");
    Vec3Reader pos = vec3Accessor(m, posIt->second, what + " POSITION");
    std::vector<uint32_t> idx = toTriangleList(readIndices(m, p, pos.count, what), p.mode);
    if (idx.empty()) return;
    // The budget, checked before anything is appended (flat normals give every corner a vertex).
    const size_t budget = sceneBudget().triangles;
    const size_t newVertices = p.attributes.count("NORMAL") ? pos.count : idx.size();
    if (s.indices.size() / 3 + idx.size() / 3 > budget || s.vertices.size() + newVertices > 3 * budget)
        throw Error(what + ": the scene expands past the budget of " + std::to_string(budget) +
                    " triangles (raise it with ssaolab --max-triangles N)");

    const size_t tris = idx.size() / 3;
    const tinygltf::Material* mat =
        p.material >= 0 && p.material < int(m.materials.size()) ? &m.materials[size_t(p.material)] : nullptr;
    const MaterialClass cls = materialClass(mat);
    if (!countMaterial(cls, tris, s)) return;
    Draw d;
    d.firstIndex = uint32_t(s.indices.size());
    if (mat) {
        const auto& f = mat->pbrMetallicRoughness.baseColorFactor;
        if (f.size() == 4) d.baseColor = glm::vec4(f[0], f[1], f[2], f[3]);
    }
    // MASK: the alpha test, and the UVs it reads (kept per vertex once any draw needs them).
    std::vector<glm::vec2> uv;
    if (cls == MaterialClass::Mask) {
        uv = maskAlphaTest(m, p, *mat, pos.count, d, masks, s, what);
        if (d.alphaTexture < 0 && d.baseColor.w < d.alphaCutoff) return; // cut out everywhere
        if (d.alphaTexture < 0) d.mask = false;                          // solid everywhere
    }
    if (!uv.empty() || !s.uvs.empty()) s.uvs.resize(s.vertices.size());
    auto nrmIt = p.attributes.find("NORMAL");
    if (nrmIt != p.attributes.end()) {
        Vec3Reader nrm = vec3Accessor(m, nrmIt->second, what + " NORMAL");
        if (nrm.count != pos.count) throw Error(what + ": NORMAL count differs from POSITION count");
        appendSmooth(pos, nrm, idx, world, uv, s, worldPos, what);
    } else {
        appendFlat(pos, idx, world, uv, s, worldPos, what);
    }
    d.indexCount = uint32_t(s.indices.size()) - d.firstIndex;
    if (d.indexCount) s.draws.push_back(d);
}

// The camera in file coordinates (made relative to the scene's origin by the caller).
std::optional<Camera> cameraFromNode(const tinygltf::Model& m, const tinygltf::Node& n,
                                     const glm::dmat4& world, glm::dvec3& eyeOut) {
    const auto& c = m.cameras[n.camera];
    if (c.type != "perspective") {
        std::fprintf(stderr, "note: glTF camera '%s' is %s; framing the scene instead\n", c.name.c_str(),
                     c.type.c_str());
        return std::nullopt;
    }
    Camera cam;
    eyeOut = glm::dvec3(world * glm::dvec4(0, 0, 0, 1));
    cam.eye = glm::vec3(0.0f);
    cam.target = glm::vec3(glm::normalize(glm::dvec3(world * glm::dvec4(0, 0, -1, 0)))); // a direction
    cam.up = glm::vec3(glm::normalize(glm::dvec3(world * glm::dvec4(0, 1, 0, 0))));
    cam.fovYDeg = float(glm::degrees(c.perspective.yfov));
    cam.nearZ = float(c.perspective.znear);
    cam.farZ = c.perspective.zfar > 0.0 ? float(c.perspective.zfar) : 0.0f; // 0 = infinite, fixed up later
    return cam;
}

} // namespace

// The file as tinygltf reads it: regular files only, buffers inside the scene's folder, images
// never decoded; glTF 1.0 and geometry-changing extensions refused by name.
tinygltf::Model readModel(const GuardedGltf& g, const std::string& path, SceneFolder& folder) {
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({fileExistsInFolder, keepPath, readFileInFolder, refuseWrite, &folder});
    loader.SetImageLoader(skipImage, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    const std::string base = g.file.parent_path().string();
    bool ok = false;
    try { // tinygltf throws on some malformed input (e.g. nlohmann::json type errors)
        ok = g.binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, g.glb.data(), unsigned(g.glb.size()), base)
                      : loader.LoadASCIIFromString(&model, &err, &warn, g.json.data(), unsigned(g.json.size()), base);
    } catch (const std::exception& e) {
        throw Error("cannot load glTF " + path + ": " + e.what());
    }
    if (!ok || !err.empty()) {
        std::string msg = err.empty() ? warn : err;
        while (!msg.empty() && (msg.back() == '\n' || msg.back() == ' '))
            msg.pop_back();
        for (auto& ch : msg)
            if (ch == '\n') ch = ';';
        throw Error("cannot load glTF " + path + ": " + (msg.empty() ? "unknown error" : msg));
    }
    if (!model.asset.version.empty() && model.asset.version[0] == '1')
        throw Error("glTF " + path + " is glTF " + model.asset.version +
                    "; only glTF 2.0 is supported (convert it, e.g. with gltf-pipeline)");
    for (const auto& ext : model.extensionsRequired)
        if (!supportedRequirement(ext))
            throw Error("glTF " + path + " requires unsupported extension " + ext +
                        " (ssaolab reads uncompressed float geometry; it honours EXT_mesh_gpu_instancing and KHR_texture_transform)");
    return model;
}

namespace {

// The nodes to draw: the default scene's roots, or, in a file without scenes, every node without a
// parent. glTF 2.0 §3.5.3: a node has at most one parent and the hierarchy is a set of disjoint
// trees. Enforced: a node listed twice (by two parents, or twice by one) would be drawn once per
// path, and 22 levels of that is 4 million copies from a 1.5 KB file. Meshes may still be shared.
std::vector<int> sceneRoots(const tinygltf::Model& model, const std::string& path) {
    std::vector<int> parentOf(model.nodes.size(), -1);
    for (size_t pi = 0; pi < model.nodes.size(); ++pi)
        for (int c : model.nodes[pi].children) {
            if (c < 0 || c >= int(model.nodes.size()))
                throw Error("glTF " + path + ": node " + std::to_string(pi) + " has a child " + std::to_string(c) +
                            " that does not exist");
            if (parentOf[size_t(c)] >= 0)
                throw Error("glTF " + path + ": node " + std::to_string(c) + " has two parents (" +
                            std::to_string(parentOf[size_t(c)]) + " and " + std::to_string(pi) +
                            "); glTF allows one parent per node");
            parentOf[size_t(c)] = int(pi);
        }
    std::vector<int> roots;
    const int sceneIdx = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (sceneIdx < int(model.scenes.size())) {
        roots = model.scenes[size_t(sceneIdx)].nodes;
    } else { // no scenes: the trees' roots, each drawn once
        for (int i = 0; i < int(model.nodes.size()); ++i)
            if (parentOf[size_t(i)] < 0) roots.push_back(i);
    }
    std::vector<char> isRoot(model.nodes.size(), 0);
    for (int r : roots) {
        if (r < 0 || r >= int(model.nodes.size()))
            throw Error("glTF " + path + ": scene root node " + std::to_string(r) + " does not exist");
        if (parentOf[size_t(r)] >= 0 || isRoot[size_t(r)])
            throw Error("glTF " + path + ": node " + std::to_string(r) +
                        " is a scene root and also listed elsewhere; glTF allows one parent per node");
        isRoot[size_t(r)] = 1;
    }
    return roots;
}

// "glTF mesh 'name'" for messages, the name cut at 60 characters: building the label for every
// primitive from an 8 MB name would make loading time grow with name length x primitives.
std::string meshLabel(const tinygltf::Mesh& mesh, int index) {
    const std::string name = mesh.name.size() > 60 ? mesh.name.substr(0, 57) + "..." : mesh.name;
    return "glTF mesh " + std::to_string(index) + (name.empty() ? "" : " '" + name + "'");
}

// What the scene will hold once flattened, from the accessors' counts alone: the budget is checked
// before anything is allocated (900 primitives sharing one accessor would expand to 5.4 GiB).
struct Expansion {
    double triangles = 0, vertices = 0;
    void add(const tinygltf::Model& m, const tinygltf::Primitive& p, double copies) {
        auto pos = p.attributes.find("POSITION");
        if (pos == p.attributes.end() || pos->second < 0 || pos->second >= int(m.accessors.size())) return;
        const double pc = double(m.accessors[size_t(pos->second)].count);
        const double ic = p.indices >= 0 && p.indices < int(m.accessors.size()) ? double(m.accessors[size_t(p.indices)].count) : pc;
        const double tris = p.mode == TINYGLTF_MODE_TRIANGLES ? std::floor(ic / 3)
                            : (p.mode == TINYGLTF_MODE_TRIANGLE_STRIP || p.mode == TINYGLTF_MODE_TRIANGLE_FAN) ? std::max(ic - 2, 0.0)
                                                                                                              : 0.0;
        triangles += copies * tris;
        vertices += copies * (p.attributes.count("NORMAL") ? pc : 3 * tris); // flat normals: a vertex per corner
    }
    void add(const Expansion& e, double times) {
        triangles += times * e.triangles, vertices += times * e.vertices;
    }
    // Primitives appended (instances x primitives over every node visited): each is at least a
    // triangle's work even when it draws none, so the triangle budget bounds them too.
    double copies = 0;
    // Vertices (scene frame), their file positions (double) and three indices a triangle.
    double bytes() const { return vertices * double(sizeof(Vertex) + sizeof(glm::dvec3)) + triangles * 12; }
};

// The draws from `first` on, one primitive's instances: consecutive in the index buffer and alike
// but for their ranges, they become one draw (one call a frame, not one per instance).
void mergeDraws(Scene& s, size_t first) {
    size_t keep = first;
    for (size_t k = first + 1; k < s.draws.size(); ++k) {
        Draw& d = s.draws[keep];
        const Draw& e = s.draws[k];
        if (e.firstIndex == d.firstIndex + d.indexCount && e.baseColor == d.baseColor && e.mask == d.mask &&
            e.alphaCutoff == d.alphaCutoff && e.alphaTexture == d.alphaTexture)
            d.indexCount += e.indexCount;
        else
            s.draws[++keep] = e;
    }
    if (first < s.draws.size()) s.draws.resize(keep + 1);
}

// Walks the node trees, flattening meshes into the scene and collecting the cameras. Cycles (a
// node its own ancestor) are caught on the walk; the visit bound stays as a guard.
class NodeWalker {
  public:
    // masks = nullptr: counts only (adds up `expansion` and allocates nothing).
    NodeWalker(const tinygltf::Model& m, const std::string& path, Scene& s, MaskTextures* masks)
        : m_(m), path_(path), s_(s), onPath_(m.nodes.size(), 0), countOnly_(!masks), masks_(masks) {}

    void visit(int ni, const glm::dmat4& parent, int depth) {
        if (ni < 0 || ni >= int(m_.nodes.size()))
            throw Error("glTF " + path_ + ": node index " + std::to_string(ni) + " does not exist");
        if (onPath_[size_t(ni)]) throw Error("glTF " + path_ + ": node " + std::to_string(ni) + " is its own ancestor");
        if (depth > 1000) throw Error("glTF " + path_ + ": node hierarchy deeper than 1000 levels");
        if (++visits_ > kMaxVisits)
            throw Error("glTF " + path_ + ": more than 1 million node instances (shared nodes multiply)");
        onPath_[size_t(ni)] = 1;
        const auto& n = m_.nodes[size_t(ni)];
        const glm::dmat4 world = parent * localMatrix(n);
        if (n.mesh >= 0) {
            if (n.mesh >= int(m_.meshes.size())) throw Error("glTF " + path_ + ": node refers to missing mesh");
            const auto& mesh = m_.meshes[size_t(n.mesh)];
            const std::string what = "glTF " + path_ + ": node " + std::to_string(ni);
            // EXT_mesh_gpu_instancing: the mesh once per instance (1 without it), counted before any
            // instance is read so the budget sees the whole expansion.
            const size_t instances = instanceCount(m_, n, what);
            if (countOnly_) {
                expansion.add(meshCost(n.mesh), double(instances));
                expansion.copies += double(instances) * double(mesh.primitives.size());
            } else {
                const InstanceTransforms transforms(m_, n, what);
                const std::string label = meshLabel(mesh, n.mesh);
                for (const auto& p : mesh.primitives) {
                    const size_t first = s_.draws.size();
                    for (size_t i = 0; i < transforms.count(); ++i)
                        appendPrimitive(m_, p, world * transforms[i], s_, worldPos, label, *masks_);
                    mergeDraws(s_, first);
                }
            }
        }
        if (!countOnly_ && n.camera >= 0 && n.camera < int(m_.cameras.size())) {
            glm::dvec3 eye;
            if (auto cam = cameraFromNode(m_, n, world, eye)) {
                const std::string name = !n.name.empty() ? n.name : m_.cameras[size_t(n.camera)].name;
                s_.cameras.emplace_back(name.empty() ? "camera " + std::to_string(s_.cameras.size()) : name, *cam);
                cameraEyes.push_back(eye);
            }
        }
        for (int c : n.children)
            visit(c, world, depth + 1);
        onPath_[size_t(ni)] = 0;
    }

    std::vector<glm::dvec3> worldPos;   // per vertex, file coordinates
    std::vector<glm::dvec3> cameraEyes; // per entry of s.cameras, file coordinates
    Expansion expansion;                // countOnly

  private:
    static constexpr size_t kMaxVisits = 1000000;
    // What one copy of mesh i expands to, summed over its primitives once: a visit costs O(1)
    // however many primitives the mesh holds.
    const Expansion& meshCost(int i) {
        if (meshCost_.empty()) meshCost_.resize(m_.meshes.size());
        auto& [done, cost] = meshCost_[size_t(i)];
        if (!done)
            for (const auto& p : m_.meshes[size_t(i)].primitives)
                cost.add(m_, p, 1.0);
        done = true;
        return cost;
    }
    std::vector<std::pair<bool, Expansion>> meshCost_;
    const tinygltf::Model& m_;
    const std::string& path_;
    Scene& s_;
    std::vector<char> onPath_;
    size_t visits_ = 0;
    bool countOnly_ = false;
    MaskTextures* masks_ = nullptr;
};

// Positions into the scene frame, cameras with it, the extent checked, far planes for infinite
// projections and orbit targets placed.
void finishScene(Scene& s, const NodeWalker& w, const std::string& path) {
    if (!s.uvs.empty()) s.uvs.resize(s.vertices.size());
    if (s.indices.empty())
        throw Error("glTF " + path + " has no triangles to render" +
                    (s.materials.blendSkipped ? std::string(" (its transparent surfaces are skipped: ssaolab --transparent opaque draws them)")
                                              : std::string()));
    s.setWorldPositions(w.worldPos);
    for (size_t i = 0; i < s.cameras.size(); ++i) { // eye and target in the scene frame
        Camera& c = s.cameras[i].second;
        const glm::vec3 dir = c.target;
        c.eye = s.toScene(w.cameraEyes[i]);
        c.target = c.eye + dir;
    }
    if (!s.cameras.empty()) s.camera = s.cameras.front().second;
    if (!s.bounds.valid() || !std::isfinite(s.bounds.radius())) throw Error("glTF " + path + " has non-finite positions");
    if (!(s.bounds.radius() > 0.0f)) throw Error("glTF " + path + " has no extent: every vertex is at one point");
    // Infinite projections (no zfar): put the far plane safely behind the whole scene.
    auto fixFar = [&](Camera& c) {
        if (c.farZ > c.nearZ) return;
        float d = glm::length(c.eye - s.bounds.center()) + s.bounds.radius();
        c.farZ = std::max(d * 1.5f, c.nearZ * 10.0f);
    };
    // The file's planes are kept (clip "fixed" selects them); by default they are fitted per view.
    if (s.camera) fixFar(*s.camera), placeOrbitTarget(*s.camera, s);
    for (auto& [name, c] : s.cameras)
        fixFar(c), placeOrbitTarget(c, s);
}

} // namespace

Scene loadGltf(const std::string& path) {
    const GuardedGltf guarded = guardGltf(path, sceneBudget()); // checks tinygltf does not make
    SceneFolder folder{guarded.file.parent_path(), sceneBudget().bytes, 0};
    const tinygltf::Model model = readModel(guarded, path, folder);
    Scene s;
    s.name = path;
    const std::vector<int> roots = sceneRoots(model, path);
    NodeWalker count(model, path, s, nullptr);
    for (int r : roots)
        count.visit(r, glm::dmat4(1.0), 0);
    const SceneBudget budget = sceneBudget();
    if (count.expansion.triangles > double(budget.triangles))
        throw Error("glTF " + path + " expands to " + std::to_string((long long)count.expansion.triangles) +
                    " triangles, past the budget of " + std::to_string(budget.triangles) +
                    " triangles (raise it with ssaolab --max-triangles N)");
    if (count.expansion.bytes() > double(budget.bytes))
        throw Error("glTF " + path + " expands to " + std::to_string((long long)(count.expansion.bytes() / (1 << 20))) +
                    " MiB of vertices and indices, past the budget of " + std::to_string(budget.bytes >> 20) +
                    " MiB (raise it with ssaolab --max-scene-mib N)");
    if (count.expansion.copies > double(budget.triangles))
        throw Error("glTF " + path + " draws " + std::to_string((long long)std::min(count.expansion.copies, 1e18)) +
                    " instances, past the budget of " + std::to_string(budget.triangles) +
                    " triangles (an instance of a primitive counts as at least one, with or without triangles; raise it "
                    "with ssaolab --max-triangles N)");
    MaskTextures masks(imageSources(guarded, model, folder), budget.maskPixels, "glTF " + path);
    NodeWalker walker(model, path, s, &masks);
    for (int r : roots)
        walker.visit(r, glm::dmat4(1.0), 0);
    finishScene(s, walker, path);
    return s;
}

} // namespace ssao
