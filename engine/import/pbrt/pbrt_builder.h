// The pbrt-v4 importer's state while it reads a file's directives in order: pbrt's graphics
// state (transform, material, area light, orientation, attribute stack), its named things
// (materials, textures, coordinate systems, objects), and the photon JSON scene it writes.
#pragma once
#include "description/lens_interface.h"
#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>
#include <photon/errors.h>
#include "description/imported_scene.h"
#include "import/pbrt/pbrt_params.h"
#include "import/pbrt/pbrt_parser.h"
#include "math/transform.h"

namespace photon {
class ImageTexture;
}

namespace photon::pbrt {

using Json = nlohmann::ordered_json;

// A colour or vector as the scene JSON's three-number array.
inline Json rgb(Color c) { return Json::array({c.x, c.y, c.z}); }
inline Json vec(Vec3 v) { return Json::array({v.x, v.y, v.z}); }

// A constant colour clamped to [0, 1] (pbrt allows reflectances above 1; photon's loader
// does not), with a warning; textures are left as they are (pbrt_materials.cpp).
Json clampedReflectance(Json value, const Location& where, std::vector<std::string>& warnings);

// pbrt's CTM is a 4x4 matrix, photon's transforms affine: the CTM's first three rows, and
// its last, (0 0 0 1) unless a Transform or ConcatTransform gave it another. pbrt-v4 turns
// directions by the upper 3x3 alone, so a projective CTM still orients infinite and distant
// lights (pbrt-v4-scenes' sssdragon turns its sky by one); points under it are refused
// (SceneBuilder::pointCtm).
using CtmLastRow = std::array<float, 4>;
constexpr CtmLastRow kAffineLastRow{0, 0, 0, 1};
struct Ctm {
    Transform affine;
    CtmLastRow lastRow = kAffineLastRow;
};

struct GraphicsState {
    Transform ctm;  // object (or camera) to world, as pbrt's current transformation matrix
    CtmLastRow ctmLastRow = kAffineLastRow;  // its last row
    bool reverseOrientation = false;
    std::string material;            // the photon material's name; empty: pbrt's default
    std::optional<Json> areaLight;   // emission fields for the shapes that follow
    std::string insideMedium, outsideMedium;  // MediumInterface's names; empty: none
    // Attribute "shape" | "light" | "material" | "medium" | "texture": parameters the
    // directives of that kind take where they do not give their own (pbrt-v4 GraphicsState).
    std::map<std::string, std::vector<Param>> attributes;
};

class SceneBuilder {
public:
    SceneBuilder(std::filesystem::path baseDir, ImportedScene& out, bool lenient = false)
        : baseDir_(std::move(baseDir)), out_(out), lenient_(lenient) {}
    void handle(Directive&& d);
    // Writes camera, render settings and the rest into the document once every directive is read.
    void finish();

private:
    // pbrt_transforms.cpp
    void transformDirective(const Directive& d);
    // pbrt_camera.cpp: Camera, Film, Sampler, Integrator, PixelFilter and the options.
    void camera(const Directive& d);
    void realisticCamera(const Directive& d);
    void pixelFilter(const Directive& d);
    void film(const Directive& d);
    void sampler(const Directive& d);
    void integrator(const Directive& d);
    void writeCameraAndRender();
    void writeViewOfLens(Json& cam) const;
    // pbrt_materials.cpp
    void makeNamedMaterial(const Directive& d);
    void material(const Directive& d);
    void texture(const Directive& d);
    // The photon material for pbrt material parameters (type given by `type`), or nullopt
    // for pbrt's "interface" (no surface: its shapes are left out).
    std::optional<Json> materialJson(const std::string& type, const Params& p);
    std::string currentMaterial();
    Json hairJson(const Params& p);
    // pbrt_subsurface.cpp: a dielectric boundary whose shapes hold a scattering medium
    // (the material's kSubsurfaceMedium member names it until finish() moves it onto them).
    Json subsurfaceJson(const Params& p);
    void placeSubsurfaceMedia();
    // Warns where a layered material's "thickness" darkens it in pbrt-v4 by more than 5%.
    void warnOfLayerThickness(const Params& p, const std::string& type);
    // A colour or float parameter: a constant, or a named texture's photon texture object.
    std::optional<Json> colorValue(const Params& p, std::string_view name, int spectrumKind);
    std::optional<Json> floatValue(const Params& p, std::string_view name);
    // `prefix`: "interface." or "conductor." for a coatedconductor's layers; `texturable`:
    // the material takes a roughness map (coated_diffuse), else a map's mean is not known.
    Json roughnessFields(const Params& p, bool anisotropic, const std::string& prefix = "", bool texturable = false);
    // pbrt_shapes.cpp
    void shape(const Directive& d);
    void addMeshShape(TriangleMesh mesh, const std::string& name, const Params& p, const Directive& d);
    void addSphere(const Params& p, const Directive& d);
    void addShapeJson(Json shape);  // to the world, or to the object being defined
    Json commonShapeFields(const Params& p);
    std::string meshFromPly(const Params& p, const Directive& d);
    // pbrt_curves.cpp: a "curve" joins the pending strands of its material, profile and
    // object; they become one "curves" shape when the object (or the file) ends.
    void addCurve(const Params& p, const Directive& d);
    void flushCurves(const std::optional<std::string>& object);
    // pbrt_lights.cpp
    void lightSource(const Directive& d);
    void areaLightSource(const Directive& d);
    // pbrt_media.cpp: MakeNamedMedium, MediumInterface, and a shape's "medium" field.
    void makeNamedMedium(const Directive& d);
    void mediumInterface(const Directive& d);
    std::optional<Json> shapeMedium();
    // `name` if it is a medium photon renders, else empty.
    std::string renderedMedium(const std::string& name) const;
    // pbrt_objects.cpp (in pbrt_shapes.cpp)
    void objectBegin(const Directive& d);
    void objectInstance(const Directive& d);

    // Attribute, and the parameters it gives a directive that leaves them out.
    void attribute(const Directive& d);
    void addAttributes(Directive& d) const;

    void warn(const Location& where, const std::string& message);
    // What photon cannot render: refused (SceneError) unless the import is lenient, when it
    // is warned with what is done `instead` and the directive's parameters count as read.
    void unsupported(const Directive& d, const std::string& message, const std::string& instead = "left out");
    Json matrixJson(const Transform& t) const;
    // A "uniformgrid" medium's grid of the array `key` (pbrt_media.cpp), `what` naming the
    // medium; and of given values over its box.
    Json sampledGrid(const Directive& d, const Params& p, const std::string& what, const char* key);
    Json boxGrid(const Directive& d, const Params& p, const std::string& what, std::array<int, 3> n, Json values);
    // A "nanovdb" medium's: its file's grid `name`.
    Json nanoVdbGrid(const Directive& d, const Params& p, const std::string& what, const char* name);
    Json cloudGrid(const Directive& d, const Params& p, const std::string& what);
    // The medium's "emission", if it emits.
    std::optional<Json> mediumEmission(const Directive& d, const Params& p, const std::string& type,
                                       const std::string& what);
    Json goniometricLight(const Directive& d, const Params& p, Color intensity);
    Json projectionLight(const Directive& d, const Params& p, float scale);
    std::pair<std::string, std::shared_ptr<const ImageTexture>> lightImage(const Directive& d, const Params& p,
                                                                          const std::string& what, bool load);

    std::filesystem::path baseDir_;
    ImportedScene& out_;
    bool lenient_ = false;
    Json materials_ = Json::object(), shapes_ = Json::array(), objects_ = Json::object(), lights_ = Json::array();
    Json render_ = Json::object();
    bool photonsPerPixel_ = false;  // Integrator "sppm" without photonsperiteration: one a pixel

    GraphicsState state_;
    std::vector<GraphicsState> stack_;          // AttributeBegin/End
    std::vector<Ctm> transformStack_;     // TransformBegin/End
    std::map<std::string, Ctm> coordinateSystems_;
    Ctm ctm() const { return {state_.ctm, state_.ctmLastRow}; }
    void setCtm(const Ctm& c) { state_.ctm = c.affine, state_.ctmLastRow = c.lastRow; }
    // The CTM for points (shapes, cameras, point and spot lights): refused where it is
    // projective.
    const Transform& pointCtm(const Directive& d) const;
    std::map<std::string, Json> floatTextures_, spectrumTextures_;
    std::map<std::string, std::string> namedMaterials_;  // pbrt name -> photon name
    // Named materials used (NamedMaterial, a mix's "materials") before MakeNamedMaterial made
    // them, and where first: pbrt-v4 looks names up once the whole file is read, so scenes
    // name a material before the Include that makes it (pbrt-v4's contemporary-bathroom).
    // They keep their pbrt name, which MakeNamedMaterial then gives the material.
    std::map<std::string, Location> materialsNamedAhead_;
    // The name for a named material: its photon name, or the name itself, remembered as
    // named ahead of its MakeNamedMaterial.
    std::string namedMaterial(const std::string& name, const Location& where);
    // Checks, at the end, that every material named ahead was made.
    void checkMaterialsNamedAhead();
    // pbrt medium name -> whether photon renders it (an absorbing medium under "media"), or
    // false for one left out (lenient import).
    std::map<std::string, bool> media_;
    Json mediaJson_ = Json::object();
    std::optional<std::string> currentObject_;  // inside ObjectBegin
    std::map<std::string, std::string> plyMeshes_;  // (file, reversed) key -> mesh name
    int meshCount_ = 0, materialCount_ = 0, curveCount_ = 0, subsurfaceCount_ = 0;
    struct PendingCurves {
        CurveSet curves;
        Json shape;
        std::optional<std::string> object;
    };
    std::map<std::string, PendingCurves> pendingCurves_;  // by material, profile and object

    // The camera and film, written at the end (the film may follow the camera).
    struct CameraState {
        bool seen = false;
        Transform cameraToWorld;
        double fov = 90, lensRadius = 0, focalDistance = 1e6;
        // A realistic camera's lens system (its rows, mm) and aperture diameter (mm).
        std::vector<LensInterface> lens;
        double lensApertureMm = 1;
        bool orthographic = false;
        std::optional<std::string> sphericalMapping;  // a spherical camera's "equal_area" or "equirectangular"
        std::optional<std::vector<double>> screenWindow;
        std::optional<double> frameAspectRatio;
        // pbrt-v4's camera medium: MediumInterface's outside where the Camera is declared.
        std::string medium;
        Location where;
        // photon's "filter": pbrt-v4's default Gaussian (radius 1.5, sigma 0.5; written by
        // SceneBuilder::pixelFilter) unless the file has a PixelFilter.
        Json filter;
    } camera_;
    int width_ = 1280, height_ = 720;
    // pbrt-v4's film sensor scales the image by its imaging ratio, exposure time x ISO / 100
    // (PixelSensor; the exposure time is the camera's shutterclose - shutteropen): ISO 400
    // makes the image four times as bright. The image being linear in the lights, photon
    // scales every light by it instead (1 with pbrt-v4's defaults, ISO 100 and a shutter of 1).
    double iso_ = 100, exposureTime_ = 1;
    double filmDiagonalMm_ = 35;  // pbrt-v4's Film "diagonal", for a realistic camera's view
    // A realistic camera's rays weigh the exposure time once more (pbrt-v4's RealisticCamera::GenerateRay).
    double imagingRatio() const { return exposureTime_ * iso_ / 100 * (camera_.lens.empty() ? 1 : exposureTime_); }
    bool worldBegun_ = false;
};

}  // namespace photon::pbrt
