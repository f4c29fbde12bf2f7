#include "post/feature_buffers.h"
#include <tbb/parallel_for.h>
#include "integrators/common/shading.h"
#include "math/rng.h"

namespace photon {

namespace {

struct FirstHit {
    Color albedo{0.0f};
    Vec3 normal{0.0f};
};

// One camera ray through the film point (px, py), followed through delta-only materials.
FirstHit traceFirstHit(const Scene& scene, float px, float py, Rng& rng) {
    Ray ray = scene.camera().generateRay(px, py, {rng.uniform(), rng.uniform()});
    Color beta(1.0f);
    for (int depth = 0; depth < scene.settings().maxDepth; ++depth) {
        SurfaceHit hit;
        if (!scene.intersect(ray, hit)) return {};
        Vec3 wo = -ray.d;
        ShadingPoint sp = makeShadingPoint(scene, hit, wo);
        const Material& m = *sp.material;
        if (!m.isDeltaOnly()) return {beta * sp.inputs.tint, sp.frame.n};
        float uLobe = rng.uniform();
        Vec2 u{rng.uniform(), rng.uniform()};
        std::optional<BSDFSample> s = m.sample(sp.frame.toLocal(wo), uLobe, u, sp.inputs, TransportMode::Radiance);
        if (!s) return {};
        beta *= s->weight;
        ray = spawnRay(hit.p, hit.ng, sp.frame.toWorld(s->wi));
    }
    return {};
}

}  // namespace

FeatureBuffers renderFeatureBuffers(const Scene& scene, int samplesPerPixel) {
    const int width = scene.camera().width(), height = scene.camera().height();
    FeatureBuffers f{Image(width, height), Image(width, height)};
    const float weight = 1.0f / static_cast<float>(samplesPerPixel);
    tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y)
            for (int x = 0; x < width; ++x) {
                size_t index = static_cast<size_t>(y) * width + x;
                Rng rng(scene.settings().seed, 0, index, StreamPurpose::Features);
                Color albedo(0.0f);
                Vec3 normal(0.0f);
                for (int s = 0; s < samplesPerPixel; ++s) {
                    // Through the pixel filter as the image's samples, so that the guide's
                    // edges are as soft as the image's (x's number drawn first, then y's).
                    const float ux = rng.uniform();
                    const Camera::FilmSample film = scene.camera().sampleFilm(x, y, {ux, rng.uniform()});
                    FirstHit h = traceFirstHit(scene, film.x, film.y, rng);
                    albedo += h.albedo * film.weight;
                    normal += h.normal * film.weight;
                }
                f.albedo.set(x, y, albedo * weight);
                f.normal.set(x, y, normal * weight);
            }
    });
    return f;
}

}  // namespace photon
