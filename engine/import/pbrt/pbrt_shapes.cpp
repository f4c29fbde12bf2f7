// Shapes and object instancing. Every mesh is held in the object's own frame with pbrt's
// orientation baked into its winding, so photon's geometric normal faces where pbrt's
// does: with vertex normals, the side they point to (pbrt-v4 makes the geometric normal
// follow the shading normal, and ReverseOrientation flips the vertex normals); without,
// the winding's, flipped by ReverseOrientation. The CTM goes into the shape's "transform",
// which mirrors winding and normals alike, as pbrt's handedness test does.
#include <cmath>
#include <utility>
#include "description/shape_transform.h"
#include "import/pbrt/bilinear_patches.h"
#include "import/pbrt/pbrt_builder.h"
#include "import/pbrt/loop_subdivision.h"
#include "import/pbrt/pbrt_quadrics.h"
#include "scene/mesh_loader.h"
#include "scene/scene_paths.h"

namespace photon::pbrt {

namespace {

// A bound on what a loopsubdiv may grow to: 16M triangles, ~1.3 GB as a mesh.
constexpr int64_t kMaxSubdividedTriangles = int64_t(1) << 24;

// Returns how many triangles were turned over.
size_t orient(TriangleMesh& mesh, bool reverse) {
    size_t turned = 0;
    if (!mesh.normals.empty()) {
        if (reverse)
            for (Vec3& n : mesh.normals) n = -n;
        for (size_t t = 0; t < mesh.triangleCount(); ++t) {
            uint32_t* v = &mesh.indices[3 * t];
            const Vec3 shading = mesh.normals[v[0]] + mesh.normals[v[1]] + mesh.normals[v[2]];
            const TriangleMesh::Corners k = mesh.corners(t);
            if (dot(cross(k.b - k.a, k.c - k.a), shading) < 0) {
                std::swap(v[1], v[2]);
                ++turned;
            }
        }
        return turned;
    }
    if (reverse)
        for (size_t t = 0; t < mesh.triangleCount(); ++t) std::swap(mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]);
    return reverse ? mesh.triangleCount() : 0;
}

std::vector<Vec3> points(const std::vector<double>& v) {
    std::vector<Vec3> out;
    for (size_t i = 0; i + 2 < v.size(); i += 3) out.push_back({float(v[i]), float(v[i + 1]), float(v[i + 2])});
    return out;
}

// The common mesh parameters: positions, normals and uvs per vertex, checked.
TriangleMesh meshVertices(const Params& p, const Directive& d) {
    TriangleMesh mesh;
    const std::vector<double> P = p.numbers("P", {"point3", "point"});
    if (P.empty() || P.size() % 3 != 0) fail(d.where, describe(d) + ": \"P\" must hold 3 numbers per vertex");
    mesh.positions = points(P);
    for (Vec3 q : mesh.positions)
        if (!isFinite(q)) fail(d.where, describe(d) + ": \"P\" has a coordinate that is not finite");
    const std::vector<double> N = p.numbers("N", {"normal", "normal3"});
    if (!N.empty()) {
        if (N.size() != P.size()) fail(d.where, describe(d) + ": \"N\" must have one normal per vertex of \"P\"");
        mesh.normals = points(N);
    }
    std::vector<double> uv = p.numbers("uv", {"point2", "float"});
    if (uv.empty()) uv = p.numbers("st", {"point2", "float"});
    if (!uv.empty()) {
        if (uv.size() != 2 * mesh.positions.size())
            fail(d.where, describe(d) + ": \"uv\" must have one (u, v) per vertex of \"P\"");
        for (size_t i = 0; i < uv.size(); i += 2) mesh.uvs.push_back({float(uv[i]), float(uv[i + 1])});
    }
    return mesh;
}

std::vector<uint32_t> meshIndices(const Params& p, const Directive& d, size_t vertices, size_t perFace) {
    std::vector<double> raw = p.numbers("indices", {"integer"});
    if (raw.empty() && vertices == perFace)
        for (size_t i = 0; i < perFace; ++i) raw.push_back(double(i));
    if (raw.empty() || raw.size() % perFace != 0)
        fail(d.where, describe(d) + ": \"indices\" must hold " + std::to_string(perFace) + " indices per face");
    if (raw.size() / perFace > kMaxMeshTriangles) fail(d.where, describe(d) + ": more triangles than photon's limit");
    std::vector<uint32_t> out;
    out.reserve(raw.size());
    for (double i : raw) {
        if (!(i >= 0 && i < double(vertices)))
            fail(d.where, describe(d) + ": index " + std::to_string(int64_t(i)) + " is out of range (" +
                              std::to_string(vertices) + " vertices)");
        out.push_back(uint32_t(i));
    }
    return out;
}

}  // namespace

Json SceneBuilder::commonShapeFields(const Params& p) {
    Json s = Json::object();
    // An area light's alpha makes it invisible at 0 and is refused (lenient: left out)
    // elsewhere below 1 (shape()).
    if (auto alpha = floatValue(p, "alpha"); alpha && !state_.areaLight) {
        if (!(alpha->is_number() && alpha->get<double>() >= 1)) s["alpha"] = *alpha;
    } else if (alpha && alpha->is_number() && alpha->get<double>() <= 0) {
        s["invisible"] = true;
    }
    if (!state_.ctm.identity()) s["transform"] = matrixJson(state_.ctm);
    if (state_.areaLight) s.update(*state_.areaLight);
    if (auto medium = shapeMedium()) s["medium"] = *medium;
    return s;
}

void SceneBuilder::addShapeJson(Json shape) {
    if (currentObject_)
        objects_[*currentObject_]["shapes"].push_back(std::move(shape));
    else
        shapes_.push_back(std::move(shape));
}

void SceneBuilder::addMeshShape(TriangleMesh mesh, const std::string& name, const Params& p, const Directive& d) {
    Json s = {{"type", "mesh"}, {"file", name}, {"material", currentMaterial()}};
    s.update(commonShapeFields(p));
    out_.meshes[name] = std::move(mesh);
    addShapeJson(std::move(s));
}

std::string SceneBuilder::meshFromPly(const Params& p, const Directive& d) {
    const std::string file = p.string("filename", "");
    if (file.empty()) fail(d.where, "plymesh needs a \"filename\"");
    if (auto why = checkRelativePath(file)) fail(d.where, "plymesh \"" + file + "\": " + *why);
    const std::string key = file + (state_.reverseOrientation ? "\n" : "");
    if (auto it = plyMeshes_.find(key); it != plyMeshes_.end()) return it->second;
    const std::filesystem::path full = baseDir_ / file;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(full, ec) || !isInsideFolder(full, baseDir_))
        fail(d.where, "plymesh: file not found: " + file);
    TriangleMesh mesh;
    try {
        mesh = loadMeshFile(full, baseDir_);
    } catch (const std::exception& e) {
        fail(d.where, "plymesh \"" + file + "\": " + e.what());
    }
    const size_t turned = orient(mesh, state_.reverseOrientation);
    // Unchanged, the mesh is the file itself; changed, it gets a name of its own.
    std::string name = file;
    if (turned > 0) name = file.substr(0, file.size() - std::filesystem::path(file).extension().string().size()) +
                           (state_.reverseOrientation ? "-reversed.ply" : "-oriented.ply");
    if (turned == 0) out_.meshesOnDisk.insert(name);
    out_.meshes[name] = std::move(mesh);
    plyMeshes_[key] = name;
    return name;
}

void SceneBuilder::addSphere(const Params& p, const Directive& d) {
    const double r = p.number("radius", 1);
    if (!(r > 0)) fail(d.where, "sphere: radius must be > 0");
    const double zMin = p.number("zmin", -r), zMax = p.number("zmax", r), phiMax = p.number("phimax", 360);
    if (zMin > -r || zMax < r || phiMax < 360) {
        // Part of a sphere: a mesh of it (pbrt_quadrics.h).
        if (!(phiMax > 0) || !(std::max(zMin, zMax) > -r && std::min(zMin, zMax) < r && zMin != zMax))
            fail(d.where, "sphere: zmin, zmax and phimax leave nothing of it");
        TriangleMesh mesh = partialSphereMesh(r, zMin, zMax, phiMax);
        orient(mesh, state_.reverseOrientation);
        return addMeshShape(std::move(mesh), "meshes/" + std::to_string(++meshCount_) + ".ply", p, d);
    }
    Json s = {{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", r}, {"material", currentMaterial()}};
    if (state_.reverseOrientation) s["flip_normals"] = true;
    s.update(commonShapeFields(p));
    if (state_.ctm.identity() || uniformScale(state_.ctm)) return addShapeJson(std::move(s));
    // A sphere under a non-uniform scale is an ellipsoid: an instance of an object holding it.
    if (state_.areaLight) fail(d.where, "sphere: an emissive sphere can only be scaled uniformly");
    if (currentObject_) fail(d.where, "sphere: a sphere scaled unevenly inside ObjectBegin is not supported");
    Json transform = s["transform"];
    s.erase("transform");
    const std::string object = "ellipsoid " + std::to_string(objects_.size() + 1);
    objects_[object] = {{"shapes", Json::array({s})}};
    shapes_.push_back({{"type", "instance"}, {"object", object}, {"transform", transform}});
}

void SceneBuilder::shape(const Directive& d) {
    Params p(d);
    const std::string& type = d.strings.at(0);
    pointCtm(d);
    if (currentMaterial().empty() && !shapeMedium()) {
        // pbrt's "interface" material: a boundary between media, not a surface; with no
        // medium photon renders on either side, nothing.
        for (const Param& param : d.params) param.used = true;
        warn(d.where, describe(d) + " has the interface material (no surface) and is left out");
        return;
    }
    if (state_.areaLight)
        if (std::optional<Json> alpha = floatValue(p, "alpha")) {
            // pbrt-v4 makes an area light of constant alpha 0 an invisible one (its scene.cpp
            // and DiffuseAreaLight): no ray meets it, and it lights in full through light
            // samples (commonShapeFields). Elsewhere it emits only where alpha lets it.
            const bool invisible = alpha->is_number() && alpha->get<double>() <= 0;
            if (!invisible && !(alpha->is_number() && alpha->get<double>() >= 1))
                unsupported(d, describe(d) + ": an area light cut away in part (alpha below 1) is not supported",
                            "rendered whole, without its alpha");
        }
    if (type == "trianglemesh" || type == "bilinearmesh" || type == "loopsubdiv") {
        TriangleMesh mesh = meshVertices(p, d);
        const size_t perFace = type == "bilinearmesh" ? 4 : 3;
        std::vector<uint32_t> indices = meshIndices(p, d, mesh.positions.size(), perFace);
        if (perFace == 4) {
            try {
                mesh = bilinearPatches(std::move(mesh), indices, size_t(kMaxSubdividedTriangles));
            } catch (const std::length_error& e) {
                fail(d.where, "bilinearmesh: " + std::string(e.what()));
            }
        } else {
            mesh.indices = std::move(indices);
        }
        if (type == "loopsubdiv") {
            // pbrt-v4's default is 3 levels; each multiplies the triangles by four.
            const int levels = int(p.number("levels", 3));
            if (levels < 0 || double(mesh.triangleCount()) * std::pow(4.0, levels) > double(kMaxSubdividedTriangles))
                fail(d.where, "loopsubdiv: " + std::to_string(levels) + " levels of " + std::to_string(mesh.triangleCount()) +
                                  " triangles would make more than " + std::to_string(kMaxSubdividedTriangles) + " (or levels < 0)");
            mesh = loopSubdivide(mesh, levels);
        }
        if (p.has("faceIndices")) p.find("faceIndices");  // per-face material ids; one material per shape here
        orient(mesh, state_.reverseOrientation);
        return addMeshShape(std::move(mesh), "meshes/" + std::to_string(++meshCount_) + ".ply", p, d);
    }
    if (type == "plymesh") {
        const std::string name = meshFromPly(p, d);
        if (p.has("displacement")) warn(d.where, "plymesh: displacement is not applied");
        p.find("displacement");
        p.find("edgelength");
        Json s = {{"type", "mesh"}, {"file", name}, {"material", currentMaterial()}};
        s.update(commonShapeFields(p));
        return addShapeJson(std::move(s));
    }
    if (type == "sphere") return addSphere(p, d);
    if (type == "curve") return addCurve(p, d);
    if (type == "disk" || type == "cylinder") {
        const double r = p.number("radius", 1), phiMax = p.number("phimax", 360);
        if (!(phiMax > 0)) fail(d.where, type + ": phimax must be > 0");
        TriangleMesh mesh;
        if (type == "disk") {
            const double ri = p.number("innerradius", 0), h = p.number("height", 0);
            if (!(r > 0) || !(ri >= 0 && ri < r)) fail(d.where, "disk: needs radius > innerradius >= 0");
            mesh = diskMesh(h, r, ri, phiMax);
        } else {
            const double zMin = p.number("zmin", -1), zMax = p.number("zmax", 1);
            if (!(r > 0) || !(zMin != zMax)) fail(d.where, "cylinder: needs radius > 0 and zmin != zmax");
            mesh = cylinderMesh(r, zMin, zMax, phiMax);
        }
        orient(mesh, state_.reverseOrientation);
        return addMeshShape(std::move(mesh), "meshes/" + std::to_string(++meshCount_) + ".ply", p, d);
    }
    unsupported(d, "Shape \"" + type + "\" is not supported (photon imports trianglemesh, plymesh, sphere, disk, "
                                   "cylinder, bilinearmesh, loopsubdiv, curve)");
}

void SceneBuilder::objectBegin(const Directive& d) {
    if (currentObject_) fail(d.where, "ObjectBegin inside ObjectBegin \"" + *currentObject_ + "\"");
    const std::string& name = d.strings.at(0);
    if (objects_.contains(name)) fail(d.where, "ObjectBegin: an object named \"" + name + "\" exists already");
    // pbrt-v4 opens an attribute block with the object.
    stack_.push_back(state_);
    currentObject_ = name;
    objects_[name] = {{"shapes", Json::array()}};
}

void SceneBuilder::objectInstance(const Directive& d) {
    if (currentObject_) fail(d.where, "ObjectInstance inside ObjectBegin is not supported (one level of instancing)");
    const std::string& name = d.strings.at(0);
    if (!objects_.contains(name)) fail(d.where, "ObjectInstance: no object named \"" + name + "\"");
    if (objects_[name]["shapes"].empty()) return;  // nothing photon renders in it
    Json instance = {{"type", "instance"}, {"object", name}};
    if (!pointCtm(d).identity()) instance["transform"] = matrixJson(state_.ctm);
    shapes_.push_back(std::move(instance));
}

}  // namespace photon::pbrt
