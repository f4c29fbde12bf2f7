// Renders for a fixed time and the figures equal-time comparisons read off them: what
// photon-bench's comparisons (--compare, --compare-schedules, --compare-reference) share.
#pragma once
#include <optional>
#include <string>
#include <vector>
#include <photon/scene_file.h>
#include <photon/image.h>
#include "description/scene_description.h"

namespace photon::bench {

struct TimedRender {
    Image image;
    int passes = 0;
    double seconds = 0;
    std::optional<double> estimatedError;  // the render's own relative error estimate at its end
};

// The scene file in any format photon reads, with `overrides` (KEY=VALUE settings, as
// photon-render's -D), as a description to adjust.
SceneDescription describeScene(const std::string& sceneFile, const std::vector<SettingOverride>& overrides = {});
// Renders `d` until `seconds` have passed (the pass that crosses it is finished), without
// the denoiser: the estimators themselves are compared.
TimedRender renderFor(SceneDescription d, double seconds);
// Renders `d` for exactly `passes` passes, without the denoiser.
TimedRender renderPasses(SceneDescription d, int passes);
// Two renders of `d` with seeds 1 and 2: the first for `seconds`, the second for as many
// passes as the first rendered, so that their difference is noise alone (SPPM's radius
// depends on the pass count: renders that stopped at different passes would differ in blur
// too).
struct RenderPair {
    TimedRender a, b;
};
RenderPair renderPairFor(SceneDescription d, double seconds);
double meanOf(const Image& image);
// One render's relative noise from two renders with different seeds: RMS of their
// difference / sqrt 2 / their mean.
double relativeNoise(const Image& a, const Image& b);
// The same in luminance, over the pixels the engine's error estimate is taken over
// (film/pixel_errors.h): the true value of what RenderProgress::relativeError estimates.
double relativeNoiseOfLuminance(const Image& a, const Image& b);

}  // namespace photon::bench
