// The "shapes" section: quads, spheres and triangle meshes (inline or from files).
#include <cmath>
#include "scene/json_scene_parts.h"
#include "description/shape_transform.h"
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
    if (const TriangleMesh* imported = ctx.importedMesh(file.string())) return *imported;
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

void checkFinite(const JsonObject& obj, const ShapeDescription& shape) {
    bool ok = std::isfinite(shape.radius) && isFinite(shape.center);
    for (Vec3 p : shape.mesh.positions) ok = ok && isFinite(p);
    for (const CurvePoint& p : shape.curves.points) ok = ok && isFinite(p.p) && std::isfinite(p.radius);
    if (!ok) obj.fail("coordinates are too large (not finite after the transform)");
}

// "emission" (a colour or a texture of W/(m^2 sr)), times "emission_scale", on one side or
// with "two_sided" on both.
void readEmission(JsonObject& obj, LoadContext& ctx, ShapeDescription& shape) {
    if (auto e = obj.optional("emission")) {
        ColorParam p = readColorParam(*e, ctx, Range::nonNegative());
        shape.emission = p.textured() ? Color(1.0f) : p.value;
        shape.emissionTexture = p.texture;
    }
    shape.emission *= obj.number("emission_scale", 1.0f, Range::nonNegative());
    shape.twoSidedEmission = obj.boolean("two_sided", false);
    if (auto invisible = obj.optional("invisible")) {
        shape.invisible = invisible->boolean();
        if (shape.invisible && isBlack(shape.emission)) invisible->fail("only a shape that emits can be invisible");
    }
}

// "emission_power": P scales the emission so the light sends out P watts of luminance,
// P = Y(mean emission) pi A sides (Y: Rec. 709 luminance), whatever its size: resizing a
// lamp keeps the light it gives.
void normaliseEmission(const JsonValue& value, ShapeDescription& shape) {
    const float target = value.number(Range::nonNegative());
    const float sides = shape.twoSidedEmission ? 2.0f : 1.0f;
    const float current = luminance(shape.meanEmission()) * kPi * shape.surfaceArea() * sides;
    if (!(current > 0)) value.fail("needs an emission that is not black on a shape with area");
    shape.emission *= target / current;
}

}  // namespace

ShapeDescription readShape(const JsonValue& value, LoadContext& ctx) {
    JsonObject obj = value.object();
    ShapeDescription shape;
    shape.name = value.path();
    enum Type { Quad, Sphere, Mesh, Curves, Instance };
    JsonValue typeValue = obj.required("type");
    auto type = Type(typeValue.choice({"quad", "sphere", "mesh", "curves", "instance"}, "type"));
    // readShapes takes the world's instances before they come here.
    if (type == Instance) typeValue.fail("an object's shapes cannot be instances (one level of instancing)");
    shape.kind = type == Sphere   ? ShapeDescription::Kind::Sphere
                 : type == Curves ? ShapeDescription::Kind::Curves
                                  : ShapeDescription::Kind::Mesh;
    // A fibre has no surface to emit from, cut out or close a medium with.
    if (type == Curves)
        for (const char* field : {"emission", "emission_power", "invisible", "alpha", "medium", "flip_normals"})
            if (auto v = obj.optional(field)) v->fail("curves cannot have \"" + std::string(field) + "\"");
    // The cheap fields first: a misspelt name should not wait for a mesh file to load.
    shape.material = readMaterialRef(obj.required("material"), ctx);
    readEmission(obj, ctx, shape);
    shape.flipNormals = obj.boolean("flip_normals", false);
    if (auto medium = obj.optional("medium")) {
        readShapeMedia(*medium, ctx, shape);
        if (shape.invisible && shape.boundsMedium()) medium->fail("an invisible emitter cannot bound a medium (no ray crosses it)");
    }
    if (auto alpha = obj.optional("alpha")) {
        shape.alpha = readFloatParam(*alpha, ctx, Range::closed(0, 1), ImageChannels::Alpha);
        // A light's power and its samples assume all of its surface emits.
        if (!isBlack(shape.emission) && (shape.alpha.textured() || shape.alpha.value < 1))
            alpha->fail("an emissive shape cannot have an alpha below 1");
    }
    // "alpha_cutoff": the alpha is a mask, opaque where it reaches the cutoff (glTF MASK).
    if (auto cutoff = obj.optional("alpha_cutoff")) {
        if (!obj.has("alpha")) cutoff->fail("needs \"alpha\"");
        shape.alphaCutoff = cutoff->number(Range::openClosed(0, 1));
    }
    auto transformValue = obj.optional("transform");
    std::optional<Transform> transform;
    if (transformValue) transform = readTransform(*transformValue);

    if (type == Quad) shape.mesh = readQuad(obj);
    if (type == Mesh) shape.mesh = readMesh(obj, ctx);
    if (type == Curves) shape.curves = readCurves(obj, ctx);
    if (type == Sphere) {
        shape.center = obj.required("center").vec3();
        shape.radius = obj.required("radius").number(Range::positive());
    }
    // A sphere stays a sphere only under rotation, translation and uniform scale.
    if (transform && !transformShape(*transform, shape))
        transformValue->fail("a sphere can only be scaled uniformly (one scale factor for all axes)");
    checkFinite(obj, shape);
    if (auto power = obj.optional("emission_power")) normaliseEmission(*power, shape);
    obj.finish();
    return shape;
}

namespace {

// {"type": "instance", "object": name, "transform": ...}: the object placed once more.
InstanceDescription readInstance(const JsonValue& value, const LoadContext& ctx, const SceneDescription& scene) {
    JsonObject obj = value.object();
    InstanceDescription instance;
    instance.name = value.path();
    obj.required("type");  // "instance", as readShapes saw
    const JsonValue objectName = obj.required("object");
    auto it = ctx.objectIndex.find(objectName.string());
    if (it == ctx.objectIndex.end()) objectName.fail("unknown object \"" + objectName.string() + "\"");
    instance.object = it->second;
    if (auto transform = obj.optional("transform")) {
        instance.toWorld = readTransform(*transform);
        // An emitter becomes a light per instance, in the world: a sphere must stay one.
        for (const ShapeDescription& shape : scene.objects[instance.object].shapes)
            if (shape.kind == ShapeDescription::Kind::Sphere && !isBlack(shape.emission) && !uniformScale(instance.toWorld))
                transform->fail("the object has an emissive sphere (" + shape.name + "), which can only be scaled uniformly");
    }
    obj.finish();
    return instance;
}

}  // namespace

void readShapes(const JsonValue& value, LoadContext& ctx, SceneDescription& scene) {
    auto shapes = value.elements();
    if (shapes.empty()) value.fail("must contain at least one shape");
    for (const JsonValue& shape : shapes) {
        const bool instance = shape.json().is_object() && shape.json().value("type", Json()) == "instance";
        if (instance)
            scene.instances.push_back(readInstance(shape, ctx, scene));
        else
            scene.shapes.push_back(readShape(shape, ctx));
    }
}

}  // namespace photon::scene_json
