#include "reference_comparison.h"
#include <cmath>
#include <photon/image_io.h>
#include "timed_render.h"

namespace photon::bench {
namespace {

// Means and differences over the channels of the pixels `keep` admits.
struct Masked {
    const std::vector<bool>& keep;
    double mean(const Image& a) const {
        double sum = 0;
        size_t n = 0;
        for (size_t i = 0; i < a.rgb.size(); ++i)
            if (keep[i / 3]) sum += a.rgb[i], ++n;
        return n ? sum / double(n) : 0;
    }
    double rmse(const Image& a, const Image& b) const {
        double sum = 0;
        size_t n = 0;
        for (size_t i = 0; i < a.rgb.size(); ++i)
            if (keep[i / 3]) {
                const double d = double(a.rgb[i]) - double(b.rgb[i]);
                sum += d * d, ++n;
            }
        return n ? std::sqrt(sum / double(n)) : 0;
    }
};

}  // namespace

nlohmann::json compareWithReference(const std::string& sceneFile, const std::string& referenceFile,
                                    const std::vector<double>& seconds) {
    const Image reference = readImage(referenceFile);
    const double fullMean = meanOf(reference);
    std::vector<bool> keep(size_t(reference.width) * reference.height, true);
    size_t left = 0;
    for (size_t p = 0; p < keep.size(); ++p) {
        const float* c = &reference.rgb[3 * p];
        if ((c[0] + c[1] + c[2]) / 3 > 25 * fullMean) keep[p] = false, ++left;
    }
    const Masked masked{keep};
    const double referenceMean = masked.mean(reference);
    nlohmann::json out = {{"scene", sceneFile}, {"reference", referenceFile}, {"pixels_left_out", left}};
    for (double s : seconds) {
        auto render = [&](uint64_t seed) {
            SceneDescription d = describeScene(sceneFile);
            d.render.seed = seed;
            return renderFor(std::move(d), s);
        };
        const TimedRender a = render(1), b = render(2);
        if (a.image.width != reference.width || a.image.height != reference.height)
            throw std::runtime_error("the reference is " + std::to_string(reference.width) + "x" +
                                     std::to_string(reference.height) + ", the render " + std::to_string(a.image.width) +
                                     "x" + std::to_string(a.image.height));
        const double mean = 0.5 * (masked.mean(a.image) + masked.mean(b.image));
        out["runs"].push_back({{"seconds", s},
                               {"passes", (a.passes + b.passes) / 2},
                               {"relative_noise", masked.rmse(a.image, b.image) / std::sqrt(2.0) / mean},
                               {"bias_of_mean", mean / referenceMean - 1},
                               {"relative_rmse", 0.5 * (masked.rmse(a.image, reference) + masked.rmse(b.image, reference)) /
                                                     referenceMean}});
    }
    return out;
}

}  // namespace photon::bench
