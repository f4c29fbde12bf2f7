#include "schedule_comparison.h"
#include "timed_render.h"

namespace photon::bench {
namespace {

TimedRender renderWith(const std::string& sceneFile, RadiusSchedule schedule, uint64_t seed, double seconds) {
    SceneDescription d = describeScene(sceneFile);
    d.render.radiusSchedule = schedule;
    d.render.seed = seed;
    return renderFor(std::move(d), seconds);
}

}  // namespace

nlohmann::json compareRadiusSchedules(const std::string& sceneFile, double seconds, double referenceSeconds) {
    const TimedRender reference = renderWith(sceneFile, RadiusSchedule::PerPixel, 1000, referenceSeconds);
    const double referenceMean = meanOf(reference.image);
    nlohmann::json out = {{"scene", sceneFile},
                          {"seconds_each", seconds},
                          {"reference", {{"schedule", "pixel"}, {"passes", reference.passes}}}};
    for (auto [name, schedule] : {std::pair{"pixel", RadiusSchedule::PerPixel}, std::pair{"global", RadiusSchedule::Global}}) {
        SceneDescription d = describeScene(sceneFile);
        d.render.radiusSchedule = schedule;
        const auto [a, b] = renderPairFor(std::move(d), seconds);
        const double mean = 0.5 * (meanOf(a.image) + meanOf(b.image));
        out["schedules"][name] = {{"passes", a.passes},
                                  {"relative_noise", relativeNoise(a.image, b.image)},
                                  {"bias_of_mean", mean / referenceMean - 1},
                                  {"relative_rmse", 0.5 * (rmse(a.image, reference.image) + rmse(b.image, reference.image)) / referenceMean}};
    }
    return out;
}

}  // namespace photon::bench
