#include "integrators/radiosity/radiosity.h"
#include "integrators/common/pixel_mean.h"
#include "integrators/common/shading.h"

namespace photon {

namespace {

class RadiosityIntegrator final : public PixelMeanIntegrator {
public:
    explicit RadiosityIntegrator(std::shared_ptr<const Scene> scene) : PixelMeanIntegrator(std::move(scene)) {}

private:
    // The first pass meshes, computes form factors and direct light and solves; a render
    // resumed from a checkpoint does the same again, which gives the same solution.
    bool preparePass(const CancelToken& cancel) override {
        if (solution_) return true;
        solution_ = RadiositySolution::compute(*scene_, cancel);
        if (!solution_) return false;
        stats_.patches = static_cast<int64_t>(solution_->mesh().patches().size());
        stats_.formFactorRays = solution_->formFactors().rays;
        stats_.solverIterations = solution_->iterations();
        stats_.solverResidual = solution_->residual();
        stats_.solveMs = solution_->milliseconds();
        return true;
    }

    Color radiance(const Ray& ray, PathSampler& sampler) const override {
        return radiosityRadiance(*scene_, *solution_, ray, sampler, scene_->settings().maxDepth);
    }

    std::unique_ptr<RadiositySolution> solution_;
};

}  // namespace

Color radiosityRadiance(const Scene& scene, const RadiositySolution& solution, Ray ray, PathSampler& sampler,
                        int maxDepth) {
    Color L(0.0f), beta(1.0f);
    int32_t medium = -1;  // scenes with media are refused (scene-format.md#media)
    for (int depth = 0; depth < maxDepth; ++depth) {
        SurfaceHit hit;
        if (!traceCameraRay(scene, ray, beta, medium, true, hit, L)) break;
        Vec3 wo = -ray.d;
        ShadingPoint sp = makeShadingPoint(scene, hit, wo);
        const Material& m = *sp.material;
        Vec3 woLocal = sp.frame.toLocal(wo);
        const unsigned others = m.lobes() & ~kDiffuseLobe;
        float uLobe = sampler.get1D();
        const Vec2 u = sampler.get2D();
        float pDiffuse = 0;
        if (m.hasDiffuse()) {
            // Like SPPM's camera pass: stop on the diffuse lobe with its share of the
            // albedo, otherwise follow the other lobes (plastic's coat).
            pDiffuse = others ? m.diffuseShare(woLocal, sp.inputs) : 1.0f;
            if (uLobe < pDiffuse) {
                if (std::optional<Color> I = solution.irradianceAt(hit, wo))
                    L += beta * solution.mesh().diffuseReflectance(scene.materialIndex(hit), sp.inputs.tint) * *I *
                         (kInvPi / pDiffuse);
                break;
            }
            uLobe = sampler.get1D();
        }
        std::optional<BSDFSample> s = m.sample(woLocal, uLobe, u, sp.inputs, TransportMode::Radiance, others);
        if (!s) break;
        beta *= s->weight / (1.0f - pDiffuse);
        ray = spawnRay(hit.p, hit.ng, sp.frame.toWorld(s->wi));
    }
    return L;
}

std::unique_ptr<Integrator> makeRadiosityIntegrator(std::shared_ptr<const Scene> scene) {
    return std::make_unique<RadiosityIntegrator>(std::move(scene));
}

}  // namespace photon
