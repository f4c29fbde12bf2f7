// The format-neutral description of a scene: what a loader (JSON today, other formats
// later) produces and what Scene::build turns into an Embree scene, lights and camera.
// Plain data, world space, SI-style units as documented in docs/scene-format.md.
#pragma once
#include <algorithm>
#include <array>
#include <optional>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>
#include <memory>
#include "description/camera_projection.h"
#include "description/curve_set.h"
#include "description/lens_interface.h"
#include "description/pixel_filter_description.h"
#include "materials/material.h"
#include "math/density_grid.h"
#include "description/medium_emission.h"
#include "description/medium_reflectance.h"
#include "math/transform.h"
#include "texture/image_texture.h"
#include <photon/vec.h>
#include <photon/render_settings.h>

namespace photon {

struct CameraDescription {
    Vec3 position{0, 1, 6.8f}, lookAt{0, 1, 0}, up{0, 1, 0};
    float fovDegrees = 19.5f;  // vertical field of view
    // Orthographic: the image viewHeight scene units high (fovDegrees unused); spherical:
    // every direction around the position, laid out by `mapping` (fovDegrees unused).
    CameraProjection projection = CameraProjection::Perspective;
    CameraSphericalMapping mapping = CameraSphericalMapping::EqualArea;
    float viewHeight = 2;
    int width = 512, height = 512;
    float apertureRadius = 0;  // 0: pinhole
    float focusDistance = 1;   // distance to the plane in focus when apertureRadius > 0, or of a lens system
    // CameraProjection::LensSystem: its interfaces (mm, front first), the stop's diameter
    // (mm; 0: its own) and the film's diagonal (mm); the image's side is the film's.
    std::vector<LensInterface> lens;
    float lensApertureDiameter = 0;
    float filmDiagonal = 35;
    // The image's right is up x forward (pbrt's left-handed camera space) rather than
    // forward x up: the image mirrored left to right.
    bool leftHanded = false;
    PixelFilterDescription filter;  // how each pixel weighs the image around it
    int32_t medium = -1;  // the absorbing medium the camera is in (SceneDescription::media), -1: none
};

// Triangles in world space; normals and uvs per vertex, either empty or one per position.
struct TriangleMesh {
    std::vector<Vec3> positions;
    std::vector<uint32_t> indices;  // three per triangle
    std::vector<Vec3> normals;
    std::vector<Vec2> uvs;
    size_t triangleCount() const { return indices.size() / 3; }

    struct Corners {
        Vec3 a, b, c;
    };
    Corners corners(size_t t) const {
        return {positions[indices[3 * t]], positions[indices[3 * t + 1]], positions[indices[3 * t + 2]]};
    }
    // The side triangle t's winding faces: normalize((b - a) x (c - a)).
    Vec3 faceNormal(size_t t) const {
        Corners k = corners(t);
        return normalize(cross(k.b - k.a, k.c - k.a));
    }
    float area(size_t t) const {
        Corners k = corners(t);
        return 0.5f * length(cross(k.b - k.a, k.c - k.a));
    }
    // Texture coordinates on triangle t at Embree's barycentrics (u, v): the vertex uvs
    // interpolated, or (u, v) itself for a mesh without uvs.
    Vec2 uvAt(size_t t, float u, float v) const {
        if (uvs.empty()) return {u, v};
        Vec2 a = uvs[indices[3 * t]], b = uvs[indices[3 * t + 1]], c = uvs[indices[3 * t + 2]];
        float w = 1.0f - u - v;
        return {a.x * w + b.x * u + c.x * v, a.y * w + b.y * u + c.y * v};
    }
};

// Texture coordinates on a sphere from the outward unit normal n: (longitude, latitude)
// scaled to [0, 1], y up.
inline Vec2 sphereUv(Vec3 n) {
    float phi = std::atan2(n.z, n.x);
    return {0.5f + phi / (2.0f * kPi), 0.5f + std::asin(std::clamp(n.y, -1.0f, 1.0f)) / kPi};
}

// A medium (coloured glass, a liquid, fog, smoke, skin): light crossing a distance d of it
// unscattered keeps exp(-(absorption + scattering) d) per channel (Beer-Lambert), and where
// it scatters it turns by the Henyey-Greenstein phase function of asymmetry g. With a
// density grid (smoke, clouds) both coefficients are times the density where the light is,
// and d is the density's integral along the way. Shapes bound it
// (ShapeDescription::insideMedium); docs/scene-format.md#media.
struct MediumDescription {
    std::string name;
    Color absorption{0.0f};  // sigma_a, per unit of scene length, >= 0
    Color scattering{0.0f};  // sigma_s, per unit of scene length, >= 0
    float g = 0;             // the phase function's mean cosine, in (-1, 1): > 0 forward
    std::shared_ptr<const DensityGrid> density;  // none: homogeneous (a density of 1)
    // Light it emits, sigma_a(p) Le(p) per unit length (description/medium_emission.h); none: dark.
    std::shared_ptr<const MediumEmission> emission;
    // Given by its look (description/medium_reflectance.h): absorption and scattering are then
    // those of its reflectance's mean, and where the reflectance is a texture, a path that
    // enters through a shape holding it takes those of the reflectance where it enters.
    std::shared_ptr<const MediumReflectance> reflectance;
    // Light under a surface (skin, wax, marble): a path's walk in it counts as one vertex
    // toward render.max_depth, as pbrt-v4 counts its subsurface material's BSSRDF, however
    // often it scatters there; the walk ends by Russian roulette, by leaving, or after
    // kMaxSubsurfaceEvents scattering events.
    bool subsurface = false;
    static constexpr int kMaxSubsurfaceEvents = 1024;

    Color extinction() const { return absorption + scattering; }
    bool emits() const { return emission && !isBlack(absorption); }
    // The grid whose samples say where it emits: the emission's own, else the density's
    // (MediumEmission::grid); none where homogeneous (the shapes it is inside of then say).
    std::shared_ptr<const DensityGrid> emissionRegion() const {
        if (emission && emission->grid()) return emission->grid();
        return density;
    }
    // What light keeps unscattered where the density integrates to `densityLength`:
    // exp(-extinction densityLength) per channel (Beer-Lambert), 1 in a channel it does not
    // touch, so that an infinite length keeps that channel whole.
    Color transmittanceOver(double densityLength) const {
        const Color sigmaT = extinction();
        Color t;
        for (int c = 0; c < 3; ++c) t[c] = sigmaT[c] > 0 ? static_cast<float>(std::exp(-sigmaT[c] * densityLength)) : 1.0f;
        return t;
    }
    bool scatters() const { return !isBlack(scattering) && (!density || density->maxValue() > 0); }
    // The density at p (1 where homogeneous).
    float densityAt(Vec3 p) const { return density ? density->at(p) : 1.0f; }
    // The density's integral along o + t d, t in [0, length], |d| = 1: the length itself
    // where homogeneous (infinite for a ray that leaves the scene).
    double densityLength(Vec3 o, Vec3 d, float length) const {
        return density ? density->integral(o, d, length) : static_cast<double>(length);
    }
};

struct ShapeDescription {
    enum class Kind { Mesh, Sphere, Curves } kind = Kind::Mesh;
    TriangleMesh mesh;        // Kind::Mesh (quads arrive as two triangles with uvs)
    CurveSet curves;          // Kind::Curves: neither emits nor bounds a medium nor has an alpha
    Vec3 center;              // Kind::Sphere
    float radius = 0;         // Kind::Sphere
    uint32_t material = 0;    // index into SceneDescription::materials
    Color emission{0.0f};     // W/(m^2 sr), emitted on the side the normal faces (times the texture)
    std::shared_ptr<const Texture> emissionTexture;  // if set, multiplies emission at the point's uv
    bool twoSidedEmission = false;  // emit on both sides alike
    // An emitter no ray meets (pbrt-v4's area light of alpha 0): it lights the scene through
    // light samples and its photons, and neither shows nor casts a shadow.
    bool invisible = false;
    bool flipNormals = false; // turn the surface inside out (e.g. a sphere lit from inside)
    // Coverage: where it is below 1 the surface lets that share of every ray through
    // (leaves, fences); 1 everywhere is an ordinary surface.
    FloatParam alpha{1.0f};
    // Above 0, `alpha` is a mask instead (glTF's alphaMode MASK): where it is at least this
    // cutoff the surface is opaque, elsewhere fully transparent.
    float alphaCutoff = 0;
    std::string name;         // for messages: the JSON path it came from
    // The media on either side (indices into SceneDescription::media, -1: none): outside is
    // the side the normal faces (after flip_normals). Where both are the same the shape is
    // no boundary and a path keeps the medium it is in.
    int32_t insideMedium = -1, outsideMedium = -1;
    bool boundsMedium() const { return insideMedium != outsideMedium; }

    // Curves have none that a light could emit from (they cannot emit).
    float surfaceArea() const {
        if (kind == Kind::Sphere) return 4.0f * kPi * radius * radius;
        if (kind == Kind::Curves) return 0;
        double sum = 0;
        for (size_t t = 0; t < mesh.triangleCount(); ++t) sum += mesh.area(t);
        return static_cast<float>(sum);
    }
    // Radiance leaving a point (its texture coordinates and position), on an emitting side.
    Color emissionAt(const TexturePoint& at) const {
        return emissionTexture ? emission * emissionTexture->lookup(at) : emission;
    }
    // The mean emitted radiance over the texture's unit square (its surface mean when the
    // uvs cover the surface evenly): what the light's power and its choice use.
    Color meanEmission() const { return emissionTexture ? emission * emissionTexture->average() : emission; }
};

// Shapes in a frame of their own, placed in the world any number of times by instances:
// their geometry is stored, and built into Embree's hierarchy, once (pbrt's ObjectBegin,
// a glTF mesh used by several nodes).
struct ObjectDescription {
    std::string name;
    std::vector<ShapeDescription> shapes;  // in the object's frame
};

// One placement of an object.
struct InstanceDescription {
    uint32_t object = 0;  // index into SceneDescription::objects
    Transform toWorld;    // invertible
    std::string name;     // for messages: where it came from
};

// How an environment image covers the sphere of directions, in the light's own frame
// (docs/scene-format.md): longitude and latitude (y up), or pbrt-v4's equal-area square.
enum class EnvironmentLayout { LatLong, EqualArea };

struct LightDescription {
    enum class Kind { Point, Spot, Directional, Environment, Projection } kind = Kind::Point;
    Vec3 position, direction{0, -1, 0};
    Color intensity{0.0f};   // W/sr (point, spot)
    Color irradiance{0.0f};  // W/m^2 perpendicular to the direction (directional)
    Color radiance{0.0f};    // W/(m^2 sr) (environment without an image)
    float coneAngleDegrees = 30, falloffAngleDegrees = 25;  // spot: total and full-intensity half-angles
    // Projection: the image's (environment.image's) full angle across its shorter side,
    // along the light frame's +z (environment.toWorld), its top toward +y.
    float projectionFovDegrees = 90;
    // Environment with an image: radiance from a direction is its texel times `scale`.
    struct EnvironmentImage {
        std::shared_ptr<const ImageTexture> image;
        EnvironmentLayout layout = EnvironmentLayout::LatLong;
        float scale = 1;
        Transform toWorld;  // a rotation or a mirror image: the light's frame to the world
        // > 0: the radiance is further scaled so that a surface facing the map's pole (+y
        // of a lat-long map, +z of an equal-area one) receives this irradiance from it
        // (pbrt-v4's "illuminance"; EnvironmentMap::poleIrradiance).
        float illuminance = 0;
    };
    EnvironmentImage environment;  // image null: constant `radiance`
    // Point, spot and projection lights: the absorbing medium the light is in (-1: none),
    // where its photons start.
    int32_t medium = -1;
    // Environment: the light comes in only through this rectangle (world space, corners in
    // order; light arrives from the side of cross(p3 - p0, p1 - p0)), as pbrt-v4's portals.
    std::optional<std::array<Vec3, 4>> portal;
};

struct SceneDescription {
    CameraDescription camera;
    std::vector<MaterialPtr> materials;
    std::vector<std::string> materialNames;
    std::vector<ShapeDescription> shapes;  // in world space
    std::vector<ObjectDescription> objects;
    std::vector<InstanceDescription> instances;
    std::vector<LightDescription> lights;
    std::vector<MediumDescription> media;
    RenderSettings render;
    // Files the scene named (meshes, textures), relative to its folder in normal form, sorted.
    std::vector<std::string> files;
};

}  // namespace photon
