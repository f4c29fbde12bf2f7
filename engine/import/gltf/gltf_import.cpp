// glTF 2.0 import: the file read with tinygltf, its default scene's node hierarchy walked,
// and a photon JSON scene made of what the nodes place.
//
// tinygltf rather than Assimp (which the engine links for OBJ and other mesh files): it
// gives the glTF document itself — the KHR extensions' values, positions in the document
// to name in errors as JSON pointers, embedded and .glb images' encoded bytes, and the node
// hierarchy exactly as written (mesh reuse becomes photon's instancing) — where Assimp
// converts everything to its own scene graph and material model.
#include "import/gltf/gltf_import.h"
#include <cmath>
#include <map>
#include <set>
#include <photon/errors.h>
#include "import/gltf/gltf_parts.h"

namespace photon {
namespace gltf {
namespace {

const std::set<std::string> kSupportedExtensions = {"KHR_lights_punctual", "KHR_materials_emissive_strength",
                                                    "KHR_materials_ior", "KHR_materials_transmission",
                                                    "KHR_materials_volume", "KHR_texture_transform"};

// Images are kept encoded (their bytes, for ImportedScene::files): tinygltf's decoder is
// not needed, photon's image reader decodes them.
bool keepEncodedBytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

// Buffers and images a glTF names by uri are read only from inside its folder, as every
// file a photon scene names (docs/scene-format.md, "Files").
bool readInsideFolder(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* folder) {
    std::error_code ec;
    const auto root = std::filesystem::weakly_canonical(*static_cast<std::filesystem::path*>(folder), ec);
    const auto file = std::filesystem::weakly_canonical(path, ec);
    const auto rel = file.lexically_relative(root);
    if (ec || rel.empty() || *rel.begin() == "..") {
        if (err) *err += "\"" + path + "\" is outside the glTF's folder\n";
        return false;
    }
    return tinygltf::ReadWholeFile(out, err, path, nullptr);
}

tinygltf::Model load(const std::filesystem::path& file, const std::string& name) {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keepEncodedBytes, nullptr);
    std::filesystem::path folder = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
    loader.SetFsCallbacks({&tinygltf::FileExists, &tinygltf::ExpandFilePath, &readInsideFolder,
                           &tinygltf::WriteWholeFile, &folder});
    tinygltf::Model model;
    std::string err, warn;
    const bool binary = file.extension() == ".glb" || file.extension() == ".GLB";
    const bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, file.string())
                           : loader.LoadASCIIFromFile(&model, &err, &warn, file.string());
    if (!ok) {
        while (!err.empty() && err.back() == '\n') err.pop_back();
        // tinygltf names the file by its full path; the message names it once, by its name.
        for (size_t at; (at = err.find(file.string())) != std::string::npos;) err.replace(at, file.string().size(), name);
        throw SceneError(name, err.empty() ? "cannot read the glTF" : err);
    }
    return model;
}

struct Placement {
    int node;
    Matrix4 toWorld;
};

// What the scene's nodes place, in node order (depth first, children in order).
struct Placements {
    std::vector<Placement> meshes, cameras, lights;
};

void walk(Context& ctx, int node, const Matrix4& parent, std::set<int>& seen, Placements& out) {
    if (node < 0 || size_t(node) >= ctx.model.nodes.size()) ctx.fail("", "names node " + std::to_string(node) + ", which does not exist");
    // sec. 3.5.1: the nodes form disjoint trees.
    if (!seen.insert(node).second) ctx.fail(pointerTo("nodes", node), "is reached twice: the node hierarchy is not a tree");
    const tinygltf::Node& n = ctx.model.nodes[node];
    const Matrix4 toWorld = parent * Matrix4::ofNode(n);
    if (n.skin >= 0) ctx.warn(pointerTo("nodes", node) + "/skin", "skinning is ignored (the mesh's bind pose is used)");
    if (n.mesh >= 0) out.meshes.push_back({node, toWorld});
    if (n.camera >= 0) out.cameras.push_back({node, toWorld});
    if (auto it = n.extensions.find("KHR_lights_punctual"); it != n.extensions.end()) out.lights.push_back({node, toWorld});
    for (int child : n.children) walk(ctx, child, toWorld, seen, out);
}

Placements walkScene(Context& ctx) {
    if (ctx.model.scenes.empty()) ctx.fail("", "the glTF has no scene (\"scenes\" is empty)");
    const int scene = ctx.model.defaultScene >= 0 ? ctx.model.defaultScene : 0;  // sec. 3.5.1
    if (size_t(scene) >= ctx.model.scenes.size()) ctx.fail("/scene", "names scene " + std::to_string(scene) + ", which does not exist");
    Placements out;
    std::set<int> seen;
    for (int node : ctx.model.scenes[scene].nodes) walk(ctx, node, Matrix4::identity(), seen, out);
    return out;
}

void checkRequiredExtensions(Context& ctx) {
    for (size_t i = 0; i < ctx.model.extensionsRequired.size(); ++i) {
        const std::string& name = ctx.model.extensionsRequired[i];
        if (kSupportedExtensions.count(name)) continue;
        std::string known;
        for (const std::string& k : kSupportedExtensions) known += (known.empty() ? "" : ", ") + k;
        ctx.fail("/extensionsRequired/" + std::to_string(i),
                 "the glTF requires " + name + ", which photon does not support (supported: " + known + ")");
    }
}

Json chooseCamera(Context& ctx, const Placements& placed, const std::string& wanted) {
    if (placed.cameras.empty())
        ctx.fail("", "the glTF has no camera (no node of its scene has a \"camera\"); photon needs one to render from");
    if (wanted.empty()) return cameraJson(ctx, placed.cameras.front().node, placed.cameras.front().toWorld);
    std::string names;
    for (const Placement& p : placed.cameras) {
        const std::string& name = ctx.model.cameras[std::max(ctx.model.nodes[p.node].camera, 0)].name;
        if (name == wanted) return cameraJson(ctx, p.node, p.toWorld);
        names += (names.empty() ? "\"" : ", \"") + name + "\"";
    }
    ctx.fail("", "no camera named \"" + wanted + "\" (the scene's cameras: " + names + ")");
}

// A node's mesh as shapes: one per primitive, its triangles in ImportedScene::meshes.
// Primitives are read once per mesh, however many nodes place it.
class MeshShapes {
public:
    explicit MeshShapes(Context& ctx) : ctx_(ctx) {}

    const std::vector<Json>& of(int mesh) {
        if (mesh >= int(ctx_.model.meshes.size())) ctx_.fail("", "a node names mesh " + std::to_string(mesh) + ", which does not exist");
        auto [it, added] = shapes_.try_emplace(mesh);
        if (!added) return it->second;
        const auto& primitives = ctx_.model.meshes[mesh].primitives;
        for (size_t p = 0; p < primitives.size(); ++p) {
            std::optional<TriangleMesh> triangles = readPrimitive(ctx_, mesh, int(p));
            if (!triangles) continue;
            const std::string file = "meshes/" + std::to_string(mesh) + "-" + std::to_string(p) + ".ply";
            ctx_.out.meshes[file] = std::move(*triangles);
            Json shape = {{"type", "mesh"}, {"file", file}, {"material", material(primitives[p].material)}};
            const MaterialMapping& mapping = materials_[primitives[p].material];
            shape.update(mapping.shapeFields);
            // A material's volume: the medium inside its shapes, named after it.
            if (!mapping.medium.is_null()) shape["medium"] = {{"inside", name(primitives[p].material)}};
            it->second.push_back(std::move(shape));
        }
        return it->second;
    }
    Json materialsJson() const {
        Json all = Json::object();
        for (const auto& [index, mapping] : materials_) all[name(index)] = mapping.material;
        return all;
    }
    Json mediaJson() const {
        Json all = Json::object();
        for (const auto& [index, mapping] : materials_)
            if (!mapping.medium.is_null()) all[name(index)] = mapping.medium;
        return all;
    }
    bool anyEmission() const {
        for (const auto& [index, mapping] : materials_)
            if (mapping.shapeFields.contains("emission")) return true;
        return false;
    }

private:
    std::string name(int index) const {
        if (index < 0) return "default";
        const std::string& given = ctx_.model.materials[index].name;
        return "material-" + std::to_string(index) + (given.empty() ? "" : "-" + given);
    }
    std::string material(int index) {
        if (!materials_.count(index)) materials_.emplace(index, mapMaterial(ctx_, index));
        return name(index);
    }

    Context& ctx_;
    std::map<int, std::vector<Json>> shapes_;
    std::map<int, MaterialMapping> materials_;
};

// A mesh placed by one node: its shapes in the world, each with the node's matrix. A mesh
// placed by several: an object, placed by instances (docs/scene-format.md, "Objects and
// instances"), so that its triangles are held once.
void placeMeshes(Context& ctx, const Placements& placed, MeshShapes& meshes, Json& doc) {
    std::map<int, int> uses;
    for (const Placement& p : placed.meshes) ++uses[ctx.model.nodes[p.node].mesh];
    Json objects = Json::object(), shapes = Json::array();
    for (const Placement& p : placed.meshes) {
        const int mesh = ctx.model.nodes[p.node].mesh;
        const std::vector<Json>& parts = meshes.of(mesh);
        if (parts.empty()) continue;
        const double det = p.toWorld.determinant3();
        if (!(std::abs(det) > 1e-12) || !std::isfinite(det)) {
            ctx.warn(pointerTo("nodes", p.node), "its matrix is singular (a zero scale): its mesh is not placed");
            continue;
        }
        const Json transform = {{"matrix", p.toWorld.rowMajor()}};
        if (uses[mesh] == 1) {
            for (Json shape : parts) {
                shape["transform"] = transform;
                shapes.push_back(std::move(shape));
            }
            continue;
        }
        const std::string object = "mesh-" + std::to_string(mesh);
        if (!objects.contains(object)) objects[object] = {{"shapes", parts}};
        shapes.push_back({{"type", "instance"}, {"object", object}, {"transform", transform}});
    }
    if (shapes.empty()) ctx.fail("", "the glTF's scene has no triangles to render");
    doc["materials"] = meshes.materialsJson();
    if (Json media = meshes.mediaJson(); !media.empty()) doc["media"] = std::move(media);
    if (!objects.empty()) doc["objects"] = std::move(objects);
    doc["shapes"] = std::move(shapes);
}

}  // namespace
}  // namespace gltf

ImportedScene importGltf(const std::filesystem::path& file, const GltfImportOptions& options) {
    using namespace gltf;
    const std::string name = file.filename().string();
    const tinygltf::Model model = load(file, name);
    ImportedScene out;
    Context ctx{model, name, out};
    checkRequiredExtensions(ctx);
    const Placements placed = walkScene(ctx);

    Json& doc = out.document;
    doc["camera"] = chooseCamera(ctx, placed, options.camera);
    MeshShapes meshes(ctx);
    placeMeshes(ctx, placed, meshes, doc);
    Json lights = Json::array();
    for (const Placement& p : placed.lights) {
        const tinygltf::Value& ext = model.nodes[p.node].extensions.at("KHR_lights_punctual");
        const int light = ext.Has("light") && ext.Get("light").IsInt() ? ext.Get("light").GetNumberAsInt() : -1;
        lights.push_back(lightJson(ctx, light, p.node, p.toWorld));
    }
    if (lights.empty() && !meshes.anyEmission())
        ctx.fail("", "the scene has no light: no node places a KHR_lights_punctual light and no material is emissive");
    if (!lights.empty()) doc["lights"] = std::move(lights);
    if (!model.animations.empty()) ctx.warn("/animations", "animations are ignored (the scene as it stands is rendered)");
    return out;
}

}  // namespace photon
