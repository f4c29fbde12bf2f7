// The "shapes" section: quads, spheres and triangle meshes (inline or from files).
#include <cmath>
#include "scene/json_scene_parts.h"
#include "scene/mesh_loader.h"

namespace photon::scene_json {

namespace {

// Two triangles origin, +u, +u+v, +v, wound so cross(p1 - p0, p2 - p0) = u x v: the side
// the quad faces (and emits to) is the one its normal names.
TriangleMesh readQuad(JsonObject& obj) {
    Vec3 o = obj.required("origin").vec3();
    Vec3 u = obj.required("edge_u").vec3();
    Vec3 v = obj.required("edge_v").vec3();
    Vec3 n = cross(u, v);
    float area = length(n);
    // Relative test: parallel edges leave only rounding noise in the cross product.
    if (!(area > 1e-7f * length(u) * length(v)) || !std::isfinite(area))
        obj.fail("quad has zero area (edge_u and edge_v are parallel or zero)");
    n = n / area;
    TriangleMesh mesh;
    mesh.positions = {o, o + u, o + u + v, o + v};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    mesh.normals = {n, n, n, n};
    mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    return mesh;
}

// Each entry of `value` through `read`, which must yield one element per position.
template <typename T, typename Read>
std::vector<T> readPerVertex(const JsonValue& value, size_t count, Read read) {
    auto e = value.elements();
    if (e.size() != count) value.fail("must have one entry per position (" + std::to_string(count) + ")");
    std::vector<T> out;
    out.reserve(count);
    for (const JsonValue& v : e) out.push_back(read(v));
    return out;
}

std::vector<uint32_t> readIndices(const JsonValue& value, size_t vertexCount) {
    auto e = value.elements();
    if (e.empty()) value.fail("must contain at least one triangle (3 indices)");
    if (e.size() % 3 != 0) value.fail("must have a length that is a multiple of 3");
    if (e.size() / 3 > kMaxMeshTriangles)
        value.fail("more than the limit of " + std::to_string(kMaxMeshTriangles) + " triangles");
    std::vector<uint32_t> indices;
    indices.reserve(e.size());
    for (const JsonValue& v : e) indices.push_back(uint32_t(v.integer(0, int64_t(vertexCount) - 1)));
    return indices;
}

TriangleMesh readInlineMesh(JsonObject& obj) {
    TriangleMesh mesh;
    JsonValue positions = obj.required("positions");
    for (const JsonValue& p : positions.elements()) mesh.positions.push_back(p.vec3());
    if (mesh.positions.empty()) positions.fail("must not be empty");
    if (mesh.positions.size() > 3 * kMaxMeshTriangles) positions.fail("too many positions");
    size_t n = mesh.positions.size();
    mesh.indices = readIndices(obj.required("indices"), n);
    if (auto normals = obj.optional("normals"))
        mesh.normals = readPerVertex<Vec3>(*normals, n, [](const JsonValue& v) { return v.direction(); });
    if (auto uvs = obj.optional("uvs"))
        mesh.uvs = readPerVertex<Vec2>(*uvs, n, [](const JsonValue& v) { return v.vec2(); });
    return mesh;
}

TriangleMesh readFileMesh(const JsonValue& file, LoadContext& ctx) {
    std::filesystem::path path = resolveFile(file, ctx);
    try {
        return loadMeshFile(path, ctx.baseDir.empty() ? std::filesystem::path(".") : ctx.baseDir);
    } catch (const std::exception& e) {
        failWithLibraryError(file, e, ctx);
    }
}

TriangleMesh readMesh(JsonObject& obj, LoadContext& ctx) {
    bool hasFile = obj.has("file"), hasPositions = obj.has("positions");
    if (hasFile == hasPositions) obj.fail("a mesh needs exactly one of \"file\" or \"positions\"");
    if (hasFile) return readFileMesh(obj.required("file"), ctx);
    return readInlineMesh(obj);
}

uint32_t readMaterialRef(const JsonValue& value, const LoadContext& ctx) {
    const std::string& name = value.string();
    auto it = ctx.materialIndex.find(name);
    if (it == ctx.materialIndex.end()) value.fail("unknown material \"" + name + "\"");
    return it->second;
}

// A sphere stays a sphere only under rotation, translation and uniform scale.
void transformSphere(const Transform& t, const JsonValue& where, ShapeDescription& shape) {
    auto s = uniformScale(t);
    if (!s) where.fail("a sphere can only be scaled uniformly (one scale factor for all axes)");
    shape.center = t.point(shape.center);
    shape.radius *= *s;
}

void checkFinite(const JsonObject& obj, const ShapeDescription& shape) {
    bool ok = std::isfinite(shape.radius) && isFinite(shape.center);
    for (Vec3 p : shape.mesh.positions) ok = ok && isFinite(p);
    if (!ok) obj.fail("coordinates are too large (not finite after the transform)");
}

ShapeDescription readShape(const JsonValue& value, LoadContext& ctx) {
    JsonObject obj = value.object();
    ShapeDescription shape;
    shape.name = value.path();
    enum Type { Quad, Sphere, Mesh };
    auto type = Type(obj.required("type").choice({"quad", "sphere", "mesh"}, "type"));
    shape.kind = type == Sphere ? ShapeDescription::Kind::Sphere : ShapeDescription::Kind::Mesh;
    // The cheap fields first: a misspelt name should not wait for a mesh file to load.
    shape.material = readMaterialRef(obj.required("material"), ctx);
    shape.emission = obj.vec3("emission", Color(0.0f), Range::nonNegative());
    shape.flipNormals = obj.boolean("flip_normals", false);
    if (auto alpha = obj.optional("alpha")) {
        shape.alpha = readFloatParam(*alpha, ctx, Range::closed(0, 1), ImageChannels::Alpha);
        // A light's power and its samples assume all of its surface emits.
        if (!isBlack(shape.emission) && (shape.alpha.textured() || shape.alpha.value < 1))
            alpha->fail("an emissive shape cannot have an alpha below 1");
    }
    auto transformValue = obj.optional("transform");
    std::optional<Transform> transform;
    if (transformValue) transform = readTransform(*transformValue);

    if (type == Quad) shape.mesh = readQuad(obj);
    if (type == Mesh) shape.mesh = readMesh(obj, ctx);
    if (type == Sphere) {
        shape.center = obj.required("center").vec3();
        shape.radius = obj.required("radius").number(Range::positive());
    }
    if (transform && type == Sphere) transformSphere(*transform, *transformValue, shape);
    if (transform && type != Sphere) applyTransform(*transform, shape.mesh);
    checkFinite(obj, shape);
    obj.finish();
    return shape;
}

}  // namespace

void readShapes(const JsonValue& value, LoadContext& ctx, SceneDescription& scene) {
    auto shapes = value.elements();
    if (shapes.empty()) value.fail("must contain at least one shape");
    for (const JsonValue& shape : shapes) scene.shapes.push_back(readShape(shape, ctx));
}

}  // namespace photon::scene_json
