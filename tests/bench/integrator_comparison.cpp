#include "integrator_comparison.h"
#include <chrono>
#include <photon/render.h>
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "timed_render.h"

namespace photon::bench {

nlohmann::json compareIntegrators(const std::string& sceneFile, double seconds, double referenceSeconds) {
    auto renderWith = [&](IntegratorKind kind, double seconds) {
        SceneDescription d = describeScene(sceneFile);
        d.render.integrator = kind;
        return renderFor(std::move(d), seconds);
    };
    TimedRender reference = renderWith(IntegratorKind::Sppm, referenceSeconds);
    const double referenceMean = meanOf(reference.image);
    nlohmann::json out = {{"scene", sceneFile},
                          {"seconds_each", seconds},
                          {"reference", {{"integrator", "sppm"}, {"passes", reference.passes}, {"seconds", reference.seconds}}}};
    for (std::string_view name : kIntegratorNames) {
        TimedRender r = renderWith(*integratorNamed(name), seconds);
        double error = rmse(r.image, reference.image);
        out["integrators"][std::string(name)] = {
            {"passes", r.passes},
            {"seconds", r.seconds},
            {"rmse", error},
            {"relative_rmse", referenceMean > 0 ? error / referenceMean : 0.0},  // over the reference's mean
            {"mean_over_reference_mean", referenceMean > 0 ? meanOf(r.image) / referenceMean : 0.0}};
    }
    return out;
}

}  // namespace photon::bench
