// Unidirectional path tracer with next-event estimation: the independent reference the
// photon mappers are tested against. One sample per pixel per pass.
#include "integrators/common/direct_lighting.h"
#include "integrators/path/path.h"
#include "integrators/common/pixel_mean.h"

namespace photon {

namespace {

class PathIntegrator final : public PixelMeanIntegrator {
public:
    explicit PathIntegrator(std::shared_ptr<const Scene> scene) : PixelMeanIntegrator(std::move(scene)) {}

private:
    Color radiance(const Ray& ray, PathSampler& sampler) const override {
        return traceRadiance(*scene_, ray, sampler, scene_->settings().maxDepth);
    }
};

}  // namespace

Color traceRadiance(const Scene& scene, Ray ray, PathSampler& sampler, int maxDepth) {
    Color L(0.0f), beta(1.0f);
    // Area light found by shadow rays is not counted again; the environment is shared
    // between shadow rays and BSDF samples by multiple importance sampling.
    BounceSampling bounce;
    const BsdfContinuation next{kAllLobes, 1.0f};
    int32_t medium = scene.description().camera.medium;
    // Paths scatter in media that scatter and estimate the light of media that emit (one
    // number a segment in them); elsewhere they draw what they always did.
    PathInMedia inMedia{sampler, {}};
    PathInMedia* media = scene.hasScatteringMedia() || scene.hasEmittingMedia() ? &inMedia : nullptr;
    int walkEvents = 0;  // scattering events under surfaces (walksUnderSurface)
    for (int depth = 0;; ++depth) {
        SurfaceHit hit;
        // A point the ray scatters at takes a light sample below the depth limit.
        inMedia.lightAlong = depth < maxDepth ? &L : nullptr;
        const RayEnd end = traceCameraRay(scene, ray, beta, medium, bounce, hit, L, media);
        if (end == RayEnd::Left) break;
        // The ray after the last vertex is traced only for the light its BSDF sample shares
        // with that vertex's light sample (as pbrt-v4's PathIntegrator does): without it a
        // glossy surface at the last vertex loses most of its highlight.
        if (depth == maxDepth) break;
        Vec3 wo = -ray.d;
        if (end == RayEnd::Scattered) {
            // A vertex in the medium: its light sample, then the phase function's direction.
            // Under a surface the walk takes no light samples (walksUnderSurface).
            const bool underSurface = walksUnderSurface(scene, medium, walkEvents);
            if (!underSurface) L += beta * sampleDirectLightInMedium(scene, hit.p, wo, medium, sampler, true, &inMedia.segment);
            ray = underSurface ? stepUnderSurface(scene, hit.p, wo, medium, inMedia, bounce)
                               : scatterInMedium(scene, hit.p, wo, medium, sampler.get2D(), bounce);
            if (underSurface) --depth;  // the walk is no vertex: the next event has this depth too
            if ((depth >= 3 || walkEvents >= 3) && !survivesRoulette(beta, sampler.get1D())) break;
            continue;
        }
        ShadingPoint sp = makeShadingPoint(scene, hit, wo);
        // Light samples are fitted to the point at the first vertex only: deeper, the light
        // sample is a small part of the pixel's estimate, and fitting it cost more time than
        // it took noise (Bitterli's coffee maker at equal time: 24 samples against 30, 10%
        // more noise; docs/path.md).
        const bool fitted = depth == 0;
        if (!sp.material->isDeltaOnly())
            L += beta * sampleDirectLight(scene, sp, wo, sampler, kAllLobes, next, medium, fitted);
        const float uLobe = sampler.get1D();
        const Vec2 u = sampler.get2D();
        std::optional<BSDFSample> s = sp.material->sample(sp.frame.toLocal(wo), uLobe, u, sp.inputs,
                                                          TransportMode::Radiance);
        if (!s) break;
        beta *= s->weight;
        bounce = bounceFrom(sp, *s);
        bounce.fitted = fitted;
        // Russian roulette after a few bounces, on the throughput's largest channel.
        if (depth >= 3 && !survivesRoulette(beta, sampler.get1D())) break;
        ray = spawnRay(hit.p, hit.ng, sp.frame.toWorld(s->wi));
        const int32_t before = medium;
        medium = scene.mediumToward(hit, ray.d, medium);
        if (reflectsUnderSurface(scene, hit, before, medium, walkEvents)) --depth;
        entersUnderSurface(scene, hit, before, medium, inMedia);
    }
    return L;
}

std::unique_ptr<Integrator> makePathIntegrator(std::shared_ptr<const Scene> scene) {
    return std::make_unique<PathIntegrator>(std::move(scene));
}

}  // namespace photon
