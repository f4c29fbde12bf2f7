// What integrators need at a surface hit: the material, its local frame and its colour.
#pragma once
#include "math/frame.h"
#include "scene/scene.h"

namespace photon {

struct ShadingPoint {
    SurfaceHit hit;
    const Material* material = nullptr;
    Frame frame;
    MaterialInputs inputs;  // what the material reads here: uv, and its tint there
};

// `wo` points back along the arriving ray. Two-sided materials see their normals turned
// toward it, so a quad or mesh shades alike whichever way its winding faces.
inline void turnTowardViewer(SurfaceHit& hit, Vec3 wo) {
    if (dot(wo, hit.ng) < 0) {
        hit.ng = -hit.ng;
        hit.ns = -hit.ns;
    }
}
inline void turnTowardViewer(const Material& m, SurfaceHit& hit, Vec3 wo) {
    if (m.twoSided()) turnTowardViewer(hit, wo);
}
inline ShadingPoint makeShadingPoint(const Scene& scene, const SurfaceHit& hit, Vec3 wo) {
    const Material& m = scene.material(hit);
    ShadingPoint sp{hit, &m, {}, m.inputsAt(hit.uv)};
    turnTowardViewer(m, sp.hit, wo);
    sp.frame = Frame::fromNormal(sp.hit.ns);
    return sp;
}

// Casts a camera path's ray; returns whether it hit. Light the ray reaches directly (the
// environment when it leaves, emission where it lands) is added to L with weight beta when
// `countEmitted`: integrators that sample lights count it only after delta bounces, where
// no shadow ray could have found it.
inline bool traceCameraRay(const Scene& scene, const Ray& ray, Color beta, bool countEmitted, SurfaceHit& hit,
                           Color& L) {
    if (!scene.intersect(ray, hit)) {
        if (countEmitted) L += beta * scene.environment(ray.d);
        return false;
    }
    if (countEmitted) L += beta * scene.emitted(hit, -ray.d);
    return true;
}

}  // namespace photon
