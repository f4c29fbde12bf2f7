#include "integrators/common/direct_lighting.h"

namespace photon {

Color sampleDirectLight(const Scene& scene, const ShadingPoint& sp, Vec3 wo, PathSampler& sampler, unsigned lobes,
                        BsdfContinuation next, int32_t medium, bool fitted) {
    const float uLight = sampler.get1D();
    const Vec2 u = sampler.get2D();
    // Light is kept only from above n: a surface that only reflects sees none from below its
    // shading normal (its BSDF is zero there), and one that transmits picks a side with
    // probability 1/2 and keeps only light from that side, which is unbiased either way (the
    // two sides' restricted estimates sum to the whole). The light is picked for that side
    // (render.light_sampler), and lights may sample only directions above it (the
    // environment does).
    Vec3 n = sp.hit.ns;
    const float sideProbability = lightSampleSideProbability(*sp.material);
    if (sideProbability < 1.0f && sampler.get1D() < 0.5f) n = -n;
    LightSampler::Pick pick = scene.directLights().pick(uLight, sp.hit.p, n);
    if (!pick.light) return Color(0.0f);
    std::optional<LightSample> ls = pick.light->sampleIncident(sp.hit.p, ReceiverSide(n, true, fitted), u);
    if (!ls || !(dot(ls->wi, n) > 0)) return Color(0.0f);
    const Vec3 woLocal = sp.frame.toLocal(wo), wiLocal = sp.frame.toLocal(ls->wi);
    Color f = sp.material->eval(woLocal, wiLocal, sp.inputs, TransportMode::Radiance, lobes);
    if (isBlack(f)) return Color(0.0f);
    Ray shadow = std::isinf(ls->distance) ? spawnRay(sp.hit.p, sp.hit.ng, ls->wi)
                                          : spawnRayTo(sp.hit.p, sp.hit.ng, sp.hit.p + ls->wi * ls->distance);
    // sp.hit's normal is turned toward the viewer only on two-sided (opaque) materials, which
    // the path meets from the side of the medium it is in: mediumToward reads the right side.
    const Color transmittance = scene.shadowTransmittance(shadow, scene.mediumToward(sp.hit, ls->wi, medium));
    if (isBlack(transmittance)) return Color(0.0f);
    const float pickProbability = pick.probability * sideProbability;
    const unsigned shared = lobes & next.lobes;
    if (shared && ls->pdf > 0) {
        // The continuation could draw wi too: its lobes' share is weighted against it.
        const float pBsdf = next.probability * sp.material->pdf(woLocal, wiLocal, sp.inputs, next.lobes);
        const float w = powerHeuristic(pickProbability * ls->pdf, pBsdf);
        const Color fShared =
            shared == lobes ? f : sp.material->eval(woLocal, wiLocal, sp.inputs, TransportMode::Radiance, shared);
        f = (f - fShared) + fShared * w;
    }
    return f * ls->weight * transmittance * (std::abs(wiLocal.z) / pickProbability);
}

Color sampleDirectLightInMedium(const Scene& scene, Vec3 p, Vec3 wo, int32_t medium, PathSampler& sampler,
                                bool continues, const FlightSegment* along) {
    const float uLight = sampler.get1D();
    const Vec3 n = sampler.get1D() < 0.5f ? wo : -wo;
    const Vec2 u = sampler.get2D();
    LightSampler::Pick pick = scene.directLights().pick(uLight, p, n);
    if (!pick.light) return Color(0.0f);
    std::optional<LightSample> ls = pick.light->sampleIncident(p, ReceiverSide(n, false, false), u);
    if (!ls || !(dot(ls->wi, n) > 0)) return Color(0.0f);
    const float phase = henyeyGreenstein(dot(wo, ls->wi), scene.medium(medium).g);
    const Ray shadow = std::isinf(ls->distance) ? Ray{p, ls->wi} : Ray{p, ls->wi, ls->distance * (1.0f - 1e-4f)};
    const Color transmittance = scene.shadowTransmittance(shadow, medium);
    if (isBlack(transmittance)) return Color(0.0f);
    const float pickProbability = 0.5f * pick.probability;
    // The phase-function sample draws wi with density `phase` (scatterInMedium).
    float w = ls->pdf > 0 && continues ? powerHeuristic(pickProbability * ls->pdf, phase) : 1.0f;
    if (along) w *= weightAgainstLightAlongRay(scene, *along, medium, pick.index, *ls);
    return ls->weight * transmittance * (phase * w / pickProbability);
}

}  // namespace photon
