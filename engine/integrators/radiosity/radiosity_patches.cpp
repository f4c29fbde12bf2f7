#include "integrators/radiosity/radiosity_patches.h"
#include "scene/alpha_cutout.h"
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include "math/rng.h"
#include "math/sampling.h"

namespace photon {

namespace {

constexpr uint32_t kMaxDivisions = 4096;
// Corners of neighbouring cells are one vertex when their normals are within this angle
// (cos 30 deg): smooth meshes shade smoothly, a box's edges stay sharp.
constexpr float kCreaseCos = 0.866f;

uint32_t divisions(float length, float size) {
    double n = std::ceil(static_cast<double>(length) / size - 1e-4);
    return static_cast<uint32_t>(std::clamp(n, 1.0, static_cast<double>(kMaxDivisions)));
}

bool meshHasPatches(const Scene& scene, const ShapeDescription& s) {
    return scene.materialAt(s.material).hasDiffuse() || !isBlack(s.emission);
}

// A quad as the loader makes it (origin, +u, +u+v, +v as triangles 0 1 2 and 0 2 3) is cut
// into a grid; any other mesh triangle by triangle.
bool isParallelogram(const TriangleMesh& m) {
    static const uint32_t quadIndices[6] = {0, 1, 2, 0, 2, 3};
    if (m.positions.size() != 4 || m.indices.size() != 6 || !std::equal(m.indices.begin(), m.indices.end(), quadIndices))
        return false;
    const auto& p = m.positions;
    float scale = length(p[1] - p[0]) + length(p[3] - p[0]);
    return length(p[0] + p[2] - p[1] - p[3]) <= 1e-5f * scale;
}

struct SphereGrid {
    uint32_t bands, sectors;  // equal steps in y (equal-area bands, Archimedes) and in phi
};
SphereGrid sphereGrid(float radius, float size) {
    return {std::max(2u, divisions(kPi * radius, size)), std::max(4u, divisions(2 * kPi * radius, size))};
}

uint64_t cellCount(const ShapeDescription& s, float size) {
    if (s.kind == ShapeDescription::Kind::Sphere) {
        SphereGrid g = sphereGrid(s.radius, size);
        return uint64_t(g.bands) * g.sectors;
    }
    const TriangleMesh& m = s.mesh;
    if (isParallelogram(m))
        return uint64_t(divisions(length(m.positions[1] - m.positions[0]), size)) *
               divisions(length(m.positions[3] - m.positions[0]), size);
    uint64_t total = 0;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        TriangleMesh::Corners corners = m.corners(t);
        Vec3 p0 = corners.a, p1 = corners.b, p2 = corners.c;
        uint64_t n = divisions(std::max({length(p1 - p0), length(p2 - p1), length(p0 - p2)}), size);
        total += n * n;
    }
    return total;
}

uint64_t patchCount(const Scene& scene, float size) {
    uint64_t total = 0;
    for (const ShapeDescription& s : scene.description().shapes)
        if (meshHasPatches(scene, s)) total += cellCount(s, size) * (s.kind == ShapeDescription::Kind::Sphere ? 1 : 2);
    return total;
}

// Diffuse reflectance per unit tint: the hemispherical-hemispherical albedo of the diffuse
// lobe, rho_hh = (1/pi) int int f cos cos dwo dwi (Cohen & Wallace 1993, 2.5), by a fixed
// stratified set of cosine-distributed direction pairs. 1 for a Lambertian material.
Color diffuseFactor(const Material& m) {
    if (m.lobes() == kDiffuseLobe) return Color(1.0f);
    if (!m.hasDiffuse()) return Color(0.0f);
    constexpr int n = 16;
    Color sum(0.0f);
    for (int i = 0; i < n * n; ++i) {
        Vec3 wo = sampleCosineHemisphere({(i % n + 0.5f) / n, (i / n + 0.5f) / n});
        for (int j = 0; j < n * n; ++j) {
            Vec3 wi = sampleCosineHemisphere({(j % n + 0.37f) / n, (j / n + 0.61f) / n});
            sum += m.eval(wo, wi, MaterialInputs{{}, Color(1.0f)}, TransportMode::Radiance, kDiffuseLobe) * kPi;
        }
    }
    return sum / float(n * n * n * n);
}

// A patch holds the light leaving one side of a surface; a sheet that transmits would need
// both sides coupled, and a one-sided surface its back black to the light arriving there,
// which the solver does not model. Rather than render either wrong in silence, the render
// fails naming the material.
void rejectTransmission(const Scene& scene) {
    const SceneDescription& d = scene.description();
    for (const ShapeDescription& s : d.shapes) {
        const Material& m = scene.materialAt(s.material);
        const bool transmits = m.transmits(), oneSided = m.hasDiffuse() && !m.twoSided();
        if (!transmits && !oneSided) continue;
        std::string name = s.material < d.materialNames.size() ? d.materialNames[s.material] : std::to_string(s.material);
        throw std::runtime_error("radiosity: material \"" + name +
                                 (transmits ? "\" transmits light (diffuse_transmission)" : "\" is one-sided (two_sided: false)") +
                                 ", which radiosity does not model; render the scene with sppm, path or photonmap");
    }
}

Vec3 spherePoint(float y, float phi) {
    float s = std::sqrt(std::max(0.0f, 1 - y * y));
    return {s * std::cos(phi), y, s * std::sin(phi)};
}

// Lattice cells of a triangle cut n x n: row j (along p2) holds n - j upright cells and
// n - j - 1 inverted ones, interleaved; the rows before j hold 2nj - j^2 cells.
uint32_t latticeCell(uint32_t n, uint32_t i, uint32_t j, bool inverted) { return 2 * n * j - j * j + 2 * i + inverted; }

}  // namespace

// Fills cells and vertices shape by shape.
class PatchMesh::Builder {
public:
    Builder(PatchMesh& mesh, const Scene& scene, float size) : mesh_(mesh), scene_(scene), size_(size) {
        Vec3 extent = scene.boundsMax() - scene.boundsMin();
        quantum_ = std::max(length(extent), 1e-6f) * 1e-5f;
    }

    void addShape(uint32_t index) {
        const ShapeDescription& s = scene_.description().shapes[index];
        ShapeCells& sc = mesh_.shapes_[index];
        vertices_.clear();
        if (!meshHasPatches(scene_, s)) return;
        sc.firstCell = static_cast<uint32_t>(mesh_.cells_.size());
        float sign = s.flipNormals ? -1.0f : 1.0f;
        if (s.kind == ShapeDescription::Kind::Sphere)
            addSphere(s, index, sc, sign);
        else if (isParallelogram(s.mesh))
            addGrid(s, index, sc, sign);
        else
            addTriangles(s, index, sc, sign);
    }

private:
    void addGrid(const ShapeDescription& s, uint32_t index, ShapeCells& sc, float sign) {
        const auto& p = s.mesh.positions;
        Vec3 u = p[1] - p[0], v = p[3] - p[0], n = cross(u, v);
        Vec3 front = normalize(n) * sign;
        sc.kind = ShapeCells::Kind::Grid;
        sc.nu = int(divisions(length(u), size_));
        sc.nv = int(divisions(length(v), size_));
        sc.origin = p[0];
        // Dual basis: dot(du, u) = 1, dot(du, v) = 0, and alike for dv.
        sc.du = cross(v, n) / dot(u, cross(v, n));
        sc.dv = cross(n, u) / dot(v, cross(n, u));
        auto vertex = [&](int i, int j) { return vertexAt(p[0] + u * (float(i) / sc.nu) + v * (float(j) / sc.nv), front); };
        for (int j = 0; j < sc.nv; ++j)
            for (int i = 0; i < sc.nu; ++i) {
                PatchCell c = cell(index, PatchCell::Kind::Parallelogram, 4, 2, front);
                c.a = p[0] + u * (float(i) / sc.nu) + v * (float(j) / sc.nv);
                c.b = u / float(sc.nu);
                c.c = v / float(sc.nv);
                uint32_t corners[4] = {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)};
                std::copy(corners, corners + 4, c.corners);
                float sc0 = (i + 0.5f) / sc.nu, tc0 = (j + 0.5f) / sc.nv;
                // The centre's texture coordinate, through the triangle (0 1 2 or 0 2 3) it lies in.
                Vec2 uv = sc0 >= tc0 ? s.mesh.uvAt(0, sc0 - tc0, tc0) : s.mesh.uvAt(1, sc0, tc0 - sc0);
                addCell(c, s, uv, length(cross(c.b, c.c)), c.a + (c.b + c.c) * 0.5f);
            }
    }

    void addTriangles(const ShapeDescription& s, uint32_t index, ShapeCells& sc, float sign) {
        const TriangleMesh& m = s.mesh;
        sc.kind = ShapeCells::Kind::Triangles;
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            TriangleMesh::Corners corners = m.corners(t);
            Vec3 p0 = corners.a, p1 = corners.b, p2 = corners.c;
            uint32_t n = divisions(std::max({length(p1 - p0), length(p2 - p1), length(p0 - p2)}), size_);
            sc.triangleFirstCell.push_back(static_cast<uint32_t>(mesh_.cells_.size()));
            sc.triangleDivisions.push_back(n);
            Vec3 cr = cross(p1 - p0, p2 - p0);
            Vec3 front = lengthSquared(cr) > 0 ? normalize(cr) * sign : Vec3(0, 0, 1);
            Vec3 e1 = (p1 - p0) / float(n), e2 = (p2 - p0) / float(n);
            auto point = [&](uint32_t i, uint32_t j) { return p0 + e1 * float(i) + e2 * float(j); };
            for (uint32_t j = 0; j < n; ++j)
                for (uint32_t i = 0; i + j < n; ++i)
                    for (int inverted = 0; inverted < 2; ++inverted) {
                        if (inverted && i + j + 2 > n) continue;
                        // Upright: (i,j) (i+1,j) (i,j+1); inverted: (i+1,j) (i+1,j+1) (i,j+1).
                        uint32_t ci[3][2] = {{i, j}, {i + 1, j}, {i, j + 1}};
                        if (inverted) ci[0][1] = j, ci[0][0] = i + 1, ci[1][0] = i + 1, ci[1][1] = j + 1;
                        PatchCell c = cell(index, PatchCell::Kind::Triangle, 3, 2, front);
                        c.a = point(ci[0][0], ci[0][1]);
                        c.b = point(ci[1][0], ci[1][1]);
                        c.c = point(ci[2][0], ci[2][1]);
                        for (int k = 0; k < 3; ++k) c.corners[k] = vertexAt(point(ci[k][0], ci[k][1]), front);
                        float bu = (float(ci[0][0] + ci[1][0] + ci[2][0]) / 3) / n;
                        float bv = (float(ci[0][1] + ci[1][1] + ci[2][1]) / 3) / n;
                        addCell(c, s, m.uvAt(t, bu, bv), 0.5f * length(cross(c.b - c.a, c.c - c.a)),
                                (c.a + c.b + c.c) / 3.0f);
                    }
        }
    }

    void addSphere(const ShapeDescription& s, uint32_t index, ShapeCells& sc, float sign) {
        SphereGrid g = sphereGrid(s.radius, size_);
        sc.kind = ShapeCells::Kind::Sphere;
        sc.nu = int(g.sectors);
        sc.nv = int(g.bands);
        auto y = [&](uint32_t j) { return -1.0f + 2.0f * float(j) / g.bands; };
        auto phi = [&](uint32_t i) { return -kPi + 2.0f * kPi * float(i % g.sectors) / g.sectors; };
        auto vertex = [&](uint32_t i, uint32_t j) {
            Vec3 n = spherePoint(y(j), phi(i));
            return vertexAt(s.center + n * s.radius, n * sign);
        };
        for (uint32_t j = 0; j < g.bands; ++j)
            for (uint32_t i = 0; i < g.sectors; ++i) {
                float phi0 = phi(i), phi1 = phi0 + 2.0f * kPi / g.sectors;
                Vec3 n = spherePoint(0.5f * (y(j) + y(j + 1)), 0.5f * (phi0 + phi1));
                PatchCell c = cell(index, PatchCell::Kind::SphereCell, 4, 1, n * sign);
                c.a = s.center;
                c.b = {y(j), y(j + 1), s.radius};
                c.c = {phi0, phi1, sign};
                uint32_t corners[4] = {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)};
                std::copy(corners, corners + 4, c.corners);
                Vec2 uv = sphereUv(n);  // as the scene gives hits there
                float area = s.radius * s.radius * (c.b.y - c.b.x) * (phi1 - phi0);
                addCell(c, s, uv, area, s.center + n * s.radius);
            }
    }

    PatchCell cell(uint32_t shape, PatchCell::Kind kind, uint8_t corners, uint8_t sides, Vec3 front) const {
        PatchCell c;
        c.kind = kind;
        c.cornerCount = corners;
        c.sides = sides;
        c.shape = shape;
        c.normal = front;
        c.firstPatch = static_cast<uint32_t>(mesh_.patches_.size());
        return c;
    }

    void addCell(const PatchCell& c, const ShapeDescription& s, Vec2 uv, float area, Vec3 center) {
        uint32_t cellIndex = static_cast<uint32_t>(mesh_.cells_.size());
        mesh_.cells_.push_back(c);
        const Material& m = scene_.materialAt(s.material);
        Color albedo = mesh_.diffuseReflectance(s.material, m.tint().eval({uv, center, c.normal}));
        for (int side = 0; side < c.sides; ++side) {
            Patch p;
            p.cell = cellIndex;
            p.back = side == 1;
            p.center = center;
            p.normal = side ? -c.normal : c.normal;
            p.area = area;
            p.albedo = albedo;
            p.exitance = side && !s.twoSidedEmission ? Color(0.0f) : s.emissionAt({uv, center, c.normal}) * kPi;
            mesh_.patches_.push_back(p);
        }
    }

    // One vertex per position within a shape, unless the normals there differ by a crease.
    uint32_t vertexAt(Vec3 p, Vec3 n) {
        auto q = [&](float x) { return static_cast<int64_t>(std::llround(x / quantum_)); };
        int64_t key = mix(mix(q(p.x), q(p.y)), q(p.z));
        auto& list = vertices_[key];
        for (auto& [normal, id] : list)
            if (dot(normal, n) >= kCreaseCos) return id;
        list.push_back({n, static_cast<uint32_t>(mesh_.vertexCount_)});
        return static_cast<uint32_t>(mesh_.vertexCount_++);
    }
    static int64_t mix(int64_t h, int64_t v) { return int64_t(mix64(uint64_t(h) * 0x9e3779b97f4a7c15ull ^ uint64_t(v))); }

    PatchMesh& mesh_;
    const Scene& scene_;
    float size_, quantum_ = 1e-6f;
    std::unordered_map<int64_t, std::vector<std::pair<Vec3, uint32_t>>> vertices_;
};

PatchMesh::PatchMesh(const Scene& scene, const RadiositySettings& settings) {
    float diagonal = std::max(length(scene.boundsMax() - scene.boundsMin()), 1e-6f);
    float size = settings.patchSize > 0 ? settings.patchSize : diagonal / 40;
    uint64_t limit = static_cast<uint64_t>(settings.maxPatches);
    uint64_t fewest = patchCount(scene, std::numeric_limits<float>::infinity());
    if (fewest > limit)
        throw std::runtime_error("radiosity: the scene needs at least " + std::to_string(fewest) +
                                 " patches, more than render.radiosity.max_patches (" + std::to_string(limit) + ")");
    for (uint64_t count = patchCount(scene, size); count > limit; count = patchCount(scene, size))
        size *= std::max(1.05f, std::sqrt(float(count) / float(limit)));
    patchSize_ = size;
    const SceneDescription& d = scene.description();
    for (size_t i = 0; i < d.materials.size(); ++i) {
        // A patch's reflectance is its diffuse factor times the colour at its centre: a
        // texture on anything but the colour (a mix amount, a roughness) would be read at
        // one point for the whole material.
        const Material& m = *d.materials[i];
        if (m.textured() && !m.tint().textured())
            throw std::runtime_error("radiosity: material \"" + (i < d.materialNames.size() ? d.materialNames[i] : "") +
                                     "\" has a texture on a parameter other than its colour; render it with sppm or path");
        diffuseFactors_.push_back(diffuseFactor(m));
    }
    // Patches cover whole surfaces: a cut-away part would still reflect light, an invisible
    // emitter would be seen.
    for (const ShapeDescription& shape : d.shapes) {
        if (hasCutout(shape))
            throw std::runtime_error("radiosity: " + shape.name + " has an alpha cutout; render it with sppm or path");
        if (shape.invisible)
            throw std::runtime_error("radiosity: " + shape.name + " is an invisible emitter; render it with sppm or path");
    }
    // Patches are cut from the world's own meshes; an instanced object's would be repeated
    // per instance, which is what instancing is there to avoid.
    if (!d.instances.empty())
        throw std::runtime_error("radiosity: " + d.instances.front().name +
                                 " places an object (instancing); render the scene with sppm or path");
    rejectTransmission(scene);
    shapes_.resize(scene.description().shapes.size());
    Builder builder(*this, scene, size);
    for (uint32_t i = 0; i < shapes_.size(); ++i) builder.addShape(i);
}

std::optional<CellPoint> PatchMesh::locate(const SurfaceHit& hit) const {
    const ShapeCells& sc = shapes_[hit.shape];
    CellPoint at;
    auto bilinear = [&](float fs, float ft) {
        at.weights[0] = (1 - fs) * (1 - ft);
        at.weights[1] = fs * (1 - ft);
        at.weights[2] = fs * ft;
        at.weights[3] = (1 - fs) * ft;
    };
    auto split = [](float x, int n, int& i) {
        i = std::clamp(static_cast<int>(x * n), 0, n - 1);
        return std::clamp(x * n - i, 0.0f, 1.0f);
    };
    switch (sc.kind) {
        case ShapeCells::Kind::None: return std::nullopt;
        case ShapeCells::Kind::Grid: {
            Vec3 d = hit.p - sc.origin;
            int i, j;
            float fs = split(dot(d, sc.du), sc.nu, i), ft = split(dot(d, sc.dv), sc.nv, j);
            at.cell = sc.firstCell + uint32_t(j * sc.nu + i);
            bilinear(fs, ft);
            return at;
        }
        case ShapeCells::Kind::Sphere: {
            const PatchCell& any = cells_[sc.firstCell];
            Vec3 n = normalize(hit.p - any.a);
            int i, j;
            float fs = split((std::atan2(n.z, n.x) + kPi) / (2 * kPi), sc.nu, i);
            float ft = split((n.y + 1) * 0.5f, sc.nv, j);
            at.cell = sc.firstCell + uint32_t(j * sc.nu + i);
            bilinear(fs, ft);
            return at;
        }
        case ShapeCells::Kind::Triangles: {
            uint32_t n = sc.triangleDivisions[hit.primitive];
            float x = hit.barycentric.x * n, y = hit.barycentric.y * n;
            uint32_t j = std::min(static_cast<uint32_t>(std::max(y, 0.0f)), n - 1);
            uint32_t i = std::min(static_cast<uint32_t>(std::max(x, 0.0f)), n - 1 - j);
            float fx = std::clamp(x - float(i), 0.0f, 1.0f), fy = std::clamp(y - float(j), 0.0f, 1.0f);
            bool inverted = fx + fy > 1 && i + j + 2 <= n;
            at.cell = sc.triangleFirstCell[hit.primitive] + latticeCell(n, i, j, inverted);
            if (inverted) {
                at.weights[0] = 1 - fy;
                at.weights[1] = fx + fy - 1;
                at.weights[2] = 1 - fx;
            } else {
                float s = std::max(fx + fy, 1.0f);  // clamped overshoot at the triangle's far edge
                at.weights[1] = fx / s;
                at.weights[2] = fy / s;
                at.weights[0] = 1 - at.weights[1] - at.weights[2];
            }
            return at;
        }
    }
    return std::nullopt;
}

uint32_t PatchMesh::patchSeenFrom(const CellPoint& at, const SurfaceHit& hit, Vec3 wo) const {
    const PatchCell& c = cells_[at.cell];
    return c.firstPatch + (c.sides == 2 && dot(wo, hit.ng) < 0 ? 1 : 0);
}

PatchMesh::SurfaceSample PatchMesh::sample(const Patch& patch, Vec2 u) const {
    const PatchCell& c = cells_[patch.cell];
    switch (c.kind) {
        case PatchCell::Kind::Parallelogram: return {c.a + c.b * u.x + c.c * u.y, patch.normal};
        case PatchCell::Kind::Triangle: {
            Vec2 b = sampleUniformTriangle(u);
            return {c.a * b.x + c.b * b.y + c.c * (1 - b.x - b.y), patch.normal};
        }
        case PatchCell::Kind::SphereCell: {
            // Uniform in y and phi is uniform in area on the sphere (Archimedes).
            Vec3 n = spherePoint(c.b.x + u.x * (c.b.y - c.b.x), c.c.x + u.y * (c.c.y - c.c.x));
            return {c.a + n * c.b.z, n * c.c.z};
        }
    }
    return {patch.center, patch.normal};
}

}  // namespace photon
