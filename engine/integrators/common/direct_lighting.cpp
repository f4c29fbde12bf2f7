#include "integrators/common/direct_lighting.h"

namespace photon {

Color sampleDirectLight(const Scene& scene, const ShadingPoint& sp, Vec3 wo, Rng& rng, unsigned lobes) {
    LightSampler::Pick pick = scene.lights().pick(rng.uniform());
    Vec2 u{rng.uniform(), rng.uniform()};
    if (!pick.light) return Color(0.0f);
    std::optional<LightSample> ls = pick.light->sampleIncident(sp.hit.p, sp.hit.ns, u);
    if (!ls) return Color(0.0f);
    Vec3 wiLocal = sp.frame.toLocal(ls->wi);
    Color f = sp.material->eval(sp.frame.toLocal(wo), wiLocal, sp.inputs, TransportMode::Radiance, lobes);
    if (isBlack(f)) return Color(0.0f);
    Ray shadow = std::isinf(ls->distance) ? spawnRay(sp.hit.p, sp.hit.ng, ls->wi)
                                          : spawnRayTo(sp.hit.p, sp.hit.ng, sp.hit.p + ls->wi * ls->distance);
    if (scene.occluded(shadow)) return Color(0.0f);
    return f * ls->weight * (std::abs(wiLocal.z) / pick.probability);
}

}  // namespace photon
