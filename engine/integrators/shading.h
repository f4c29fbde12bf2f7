// What integrators need at a surface hit: the material, its local frame and its colour.
#pragma once
#include "../math/frame.h"
#include "../scene/scene.h"

namespace photon {

struct ShadingPoint {
    SurfaceHit hit;
    const Material* material = nullptr;
    Frame frame;
    Color tint;
};

inline ShadingPoint makeShadingPoint(const Scene& scene, const SurfaceHit& hit) {
    const Material& m = scene.material(hit);
    return {hit, &m, Frame::fromNormal(hit.ns), m.tint().eval(hit.uv)};
}

}  // namespace photon
