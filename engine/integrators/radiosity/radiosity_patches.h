// The surfaces of a scene cut into patches for finite-element radiosity (Cohen & Wallace
// 1993, ch. 6): quads into grids, triangles into n x n barycentric sub-triangles, spheres
// into equal-area bands and sectors. A cell is a piece of surface; each side of it a
// radiosity reaches is a patch, one unknown of the linear system. Corners are shared by
// neighbouring cells of a shape (where position and normal agree), for Gouraud shading.
#pragma once
#include <cstdint>
#include <vector>
#include "scene/scene.h"

namespace photon {

struct PatchCell {
    enum class Kind : uint8_t { Parallelogram, Triangle, SphereCell };
    Kind kind = Kind::Triangle;
    uint8_t cornerCount = 3;
    uint8_t sides = 2;          // 2 for open surfaces (quads, meshes); 1 for spheres
    uint32_t shape = 0;
    uint32_t firstPatch = 0;    // front side; the back side, if any, is firstPatch + 1
    uint32_t corners[4] = {};   // vertex indices, in the order surface weights refer to
    Vec3 normal;                // front normal (the side the shape emits to) of a flat cell
    // Parallelogram: origin, edge u, edge v. Triangle: the three corners.
    // Sphere cell: centre; (y0, y1, radius); (phi0, phi1, +-1 for flip_normals).
    Vec3 a, b, c;
};

struct Patch {
    uint32_t cell = 0;
    bool back = false;  // the side facing away from the cell's front normal
    Vec3 center, normal;  // normal points into the side this patch faces
    float area = 0;
    Color albedo;         // diffuse reflectance rho of the material at the centre
    Color exitance;       // emitted radiosity E = pi Le, W/m^2 (front side of emitters only)
};

// Where on its cell a surface point lies: the corner weights for Gouraud interpolation.
struct CellPoint {
    uint32_t cell = 0;
    float weights[4] = {};
};

class PatchMesh {
public:
    // Cuts every shape whose material has a diffuse lobe, and every emitter, into patches
    // of edge about settings.patchSize (0: the scene's bounding diagonal / 40). If that
    // gives more than settings.maxPatches patches the size grows until it fits; throws
    // std::runtime_error if even one cell per triangle is too many.
    PatchMesh(const Scene& scene, const RadiositySettings& settings);

    const std::vector<Patch>& patches() const { return patches_; }
    const std::vector<PatchCell>& cells() const { return cells_; }
    size_t vertexCount() const { return vertexCount_; }
    float patchSize() const { return patchSize_; }
    // The diffuse reflectance rho of a material whose colour at the point is `tint`.
    Color diffuseReflectance(uint32_t material, Color tint) const { return diffuseFactors_[material] * tint; }

    // The cell a ray hit, or nullopt for shapes that have no patches.
    std::optional<CellPoint> locate(const SurfaceHit& hit) const;
    // The patch on the side of the hit's cell that direction wo (away from the surface) is in.
    uint32_t patchSeenFrom(const CellPoint& at, const SurfaceHit& hit, Vec3 wo) const;

    struct SurfaceSample {
        Vec3 p, n;  // point and the patch side's normal
    };
    // Uniform by area over the patch's cell, for u in [0, 1)^2.
    SurfaceSample sample(const Patch& patch, Vec2 u) const;

private:
    struct ShapeCells {
        enum class Kind : uint8_t { None, Grid, Triangles, Sphere } kind = Kind::None;
        uint32_t firstCell = 0;
        int nu = 0, nv = 0;  // grid: cells along u and v; sphere: bands in y and sectors in phi
        Vec3 origin, du, dv; // grid: (s, t) = (dot(p - origin, du), dot(p - origin, dv)) in [0, 1]^2
        std::vector<uint32_t> triangleFirstCell;  // triangles: per source triangle
        std::vector<uint32_t> triangleDivisions;
    };
    class Builder;

    std::vector<ShapeCells> shapes_;
    std::vector<PatchCell> cells_;
    std::vector<Patch> patches_;
    std::vector<Color> diffuseFactors_;  // per material: rho per unit tint
    size_t vertexCount_ = 0;
    float patchSize_ = 0;
};

}  // namespace photon
