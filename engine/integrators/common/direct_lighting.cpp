#include "integrators/common/direct_lighting.h"

namespace photon {

Color sampleDirectLight(const Scene& scene, const ShadingPoint& sp, Vec3 wo, Rng& rng, unsigned lobes,
                        BsdfContinuation next) {
    LightSampler::Pick pick = scene.lights().pick(rng.uniform());
    Vec2 u{rng.uniform(), rng.uniform()};
    if (!pick.light) return Color(0.0f);
    std::optional<LightSample> ls = pick.light->sampleIncident(sp.hit.p, sp.hit.ns, u);
    if (!ls) return Color(0.0f);
    const Vec3 woLocal = sp.frame.toLocal(wo), wiLocal = sp.frame.toLocal(ls->wi);
    Color f = sp.material->eval(woLocal, wiLocal, sp.tint, TransportMode::Radiance, lobes);
    if (isBlack(f)) return Color(0.0f);
    Ray shadow = std::isinf(ls->distance) ? spawnRay(sp.hit.p, sp.hit.ng, ls->wi)
                                          : spawnRayTo(sp.hit.p, sp.hit.ng, sp.hit.p + ls->wi * ls->distance);
    if (scene.occluded(shadow)) return Color(0.0f);
    const unsigned shared = lobes & next.lobes;
    if (pick.light == scene.environmentLight() && shared && ls->pdf > 0) {
        // The continuation could draw wi too: its lobes' share is weighted against it.
        const float pBsdf = next.probability * sp.material->pdf(woLocal, wiLocal, sp.tint, next.lobes);
        const float w = powerHeuristic(pick.probability * ls->pdf, pBsdf);
        const Color fShared =
            shared == lobes ? f : sp.material->eval(woLocal, wiLocal, sp.tint, TransportMode::Radiance, shared);
        f = (f - fShared) + fShared * w;
    }
    return f * ls->weight * (std::abs(wiLocal.z) / pick.probability);
}

}  // namespace photon
