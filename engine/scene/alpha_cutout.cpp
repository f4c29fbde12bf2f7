#include "scene/alpha_cutout.h"
#include <bit>
#include "math/rng.h"

namespace photon {
namespace {

// A uniform number in [0, 1) from the ray and the primitive: the same ray meets the same
// threshold whichever query casts it.
float threshold(const RTCRayN* ray, unsigned n, unsigned i, unsigned primitive) {
    uint64_t h = primitive;
    for (float f : {RTCRayN_org_x(const_cast<RTCRayN*>(ray), n, i), RTCRayN_org_y(const_cast<RTCRayN*>(ray), n, i),
                    RTCRayN_org_z(const_cast<RTCRayN*>(ray), n, i), RTCRayN_dir_x(const_cast<RTCRayN*>(ray), n, i),
                    RTCRayN_dir_y(const_cast<RTCRayN*>(ray), n, i), RTCRayN_dir_z(const_cast<RTCRayN*>(ray), n, i)})
        h = mix64<uint64_t>(h ^ std::bit_cast<uint32_t>(f));
    return static_cast<float>(h >> 40) * 0x1p-24f;
}

// Where candidate hit i meets the shape, for a textured alpha: uv, the point and Embree's
// geometric normal (made unit), all in the object's frame.
TexturePoint candidatePoint(const ShapeDescription& shape, const RTCFilterFunctionNArguments* args, unsigned i) {
    const unsigned n = args->N;
    const Vec3 ng = normalize(
        Vec3(RTCHitN_Ng_x(args->hit, n, i), RTCHitN_Ng_y(args->hit, n, i), RTCHitN_Ng_z(args->hit, n, i)));
    Vec2 uv;
    if (shape.kind == ShapeDescription::Kind::Sphere) {
        // Embree's sphere normal points outward whatever flip_normals says: the uv the
        // scene gives the hit (Scene::fillSphereHit).
        uv = sphereUv(ng);
    } else {
        uv = shape.mesh.uvAt(RTCHitN_primID(args->hit, n, i), RTCHitN_u(args->hit, n, i), RTCHitN_v(args->hit, n, i));
    }
    // Embree has set the ray's tfar to the candidate hit's distance.
    const float t = RTCRayN_tfar(args->ray, n, i);
    const Vec3 p{RTCRayN_org_x(args->ray, n, i) + t * RTCRayN_dir_x(args->ray, n, i),
                 RTCRayN_org_y(args->ray, n, i) + t * RTCRayN_dir_y(args->ray, n, i),
                 RTCRayN_org_z(args->ray, n, i) + t * RTCRayN_dir_z(args->ray, n, i)};
    return {uv, p, ng};
}

void cutoutFilter(const RTCFilterFunctionNArguments* args) {
    const auto& shape = *static_cast<const ShapeDescription*>(args->geometryUserPtr);
    const unsigned n = args->N;
    for (unsigned i = 0; i < n; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned primitive = RTCHitN_primID(args->hit, n, i);
        // A constant alpha reads nothing of the hit.
        const float a = shape.alpha.textured() ? shape.alpha.eval(candidatePoint(shape, args, i)) : shape.alpha.value;
        if (shape.alphaCutoff > 0) {  // a mask: no randomness
            if (a < shape.alphaCutoff) args->valid[i] = 0;
            continue;
        }
        if (a >= 1) continue;
        if (a <= 0 || threshold(args->ray, n, i, primitive) >= a) args->valid[i] = 0;
    }
}

}  // namespace

bool hasCutout(const ShapeDescription& shape) {
    return shape.alpha.textured() || shape.alpha.value < (shape.alphaCutoff > 0 ? shape.alphaCutoff : 1.0f);
}

void attachAlphaCutout(RTCGeometry geometry, const ShapeDescription& shape) {
    rtcSetGeometryUserData(geometry, const_cast<ShapeDescription*>(&shape));
    rtcSetGeometryIntersectFilterFunction(geometry, cutoutFilter);
    rtcSetGeometryOccludedFilterFunction(geometry, cutoutFilter);
}

}  // namespace photon
