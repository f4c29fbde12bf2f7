#include "reference_comparison.h"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
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

// The reference box-averaged down to w x h when its size is a whole multiple of that (a
// converged render at 1024 x 1024 against a quick one at 64 x 64: each pixel's footprint
// averaged); otherwise nullopt.
std::optional<Image> boxReduced(const Image& image, int w, int h) {
    if (image.width % w || image.height % h || image.width / w != image.height / h) return std::nullopt;
    const int k = image.width / w;
    Image out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            Color sum(0.0f);
            for (int j = 0; j < k; ++j)
                for (int i = 0; i < k; ++i) sum += image.at(x * k + i, y * k + j);
            out.set(x, y, sum / float(k * k));
        }
    return out;
}

// The reference at w x h: itself, or box-averaged down when its size is a whole multiple;
// nullopt when it is neither. Pixels where it is brighter than 25 times its mean are left out.
struct ScoringReference {
    Image image;
    bool reduced = false;
    std::vector<bool> keep;
    size_t left = 0;
};

std::optional<ScoringReference> scoringReference(const Image& full, int w, int h) {
    ScoringReference r;
    if (full.width == w && full.height == h) {
        r.image = full;
    } else {
        std::optional<Image> reduced = boxReduced(full, w, h);
        if (!reduced) return std::nullopt;
        r.image = std::move(*reduced), r.reduced = true;
    }
    const double fullMean = meanOf(r.image);
    r.keep.assign(size_t(w) * h, true);
    for (size_t p = 0; p < r.keep.size(); ++p) {
        const float* c = &r.image.rgb[3 * p];
        if ((c[0] + c[1] + c[2]) / 3 > 25 * fullMean) r.keep[p] = false, ++r.left;
    }
    return r;
}

// The figures of two renders that differ by their seed alone, against the reference.
nlohmann::json scoreAgainst(const Image& a, const Image& b, const ScoringReference& reference) {
    const Masked masked{reference.keep};
    const double referenceMean = masked.mean(reference.image);
    const double mean = 0.5 * (masked.mean(a) + masked.mean(b));
    return {{"relative_noise", masked.rmse(a, b) / std::sqrt(2.0) / mean},
            // The same figure in luminance, over the pixels the error estimate takes.
            {"true_relative_error", relativeNoiseOfLuminance(a, b)},
            {"bias_of_mean", mean / referenceMean - 1},
            {"relative_rmse",
             0.5 * (masked.rmse(a, reference.image) + masked.rmse(b, reference.image)) / referenceMean}};
}

}  // namespace

nlohmann::json compareWithReference(const std::string& sceneFile, const std::string& referenceFile,
                                    const std::vector<double>& seconds,
                                    const std::vector<SettingOverride>& overrides) {
    // At the scene's own size when the reference reduces to it, else at the reference's.
    const Image full = readImage(referenceFile);
    const CameraDescription camera = describeScene(sceneFile, overrides).camera;
    std::optional<ScoringReference> reference = scoringReference(full, camera.width, camera.height);
    if (!reference) reference = scoringReference(full, full.width, full.height);
    const int w = reference->image.width, h = reference->image.height;
    nlohmann::json out = {{"scene", sceneFile},
                          {"reference", referenceFile},
                          {"resolution", {w, h}},
                          {"pixels_left_out", reference->left}};
    for (double s : seconds) {
        SceneDescription d = describeScene(sceneFile, overrides);
        d.camera.width = w, d.camera.height = h;
        // A reference reduced by box averages is a box filter of the render's pixel; the
        // scene's own filter, in the render's pixels, would blur k times wider than the
        // reference's did.
        if (reference->reduced) d.camera.filter = PixelFilterDescription{};
        const auto [a, b] = renderPairFor(std::move(d), s);
        nlohmann::json run = {{"seconds", s},
                              {"passes", a.passes},
                              // The renders' own estimate (the mean of the two).
                              {"estimated_relative_error",
                               a.estimatedError && b.estimatedError
                                   ? nlohmann::json(0.5 * (*a.estimatedError + *b.estimatedError))
                                   : nlohmann::json()}};
        run.update(scoreAgainst(a.image, b.image, *reference));
        out["runs"].push_back(std::move(run));
    }
    return out;
}

nlohmann::json scoreRenderPair(const std::string& firstFile, const std::string& secondFile,
                               const std::string& referenceFile) {
    const Image a = readImage(firstFile), b = readImage(secondFile);
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument(firstFile + " and " + secondFile + " differ in size");
    const std::optional<ScoringReference> reference = scoringReference(readImage(referenceFile), a.width, a.height);
    if (!reference)
        throw std::invalid_argument(referenceFile + " is neither the renders' size nor a whole multiple of it");
    nlohmann::json out = {{"renders", {firstFile, secondFile}},
                          {"reference", referenceFile},
                          {"resolution", {a.width, a.height}},
                          {"pixels_left_out", reference->left}};
    out.update(scoreAgainst(a, b, *reference));
    return out;
}

namespace {
SettingOverride parseSetting(const std::string& keyValue) {
    const size_t eq = keyValue.find('=');
    if (eq == std::string::npos || eq == 0) throw std::invalid_argument(keyValue + ": expected KEY=VALUE");
    return {keyValue.substr(0, eq), keyValue.substr(eq + 1)};
}
}  // namespace

std::vector<SceneVariant> parseVariants(const std::vector<std::string>& common, const std::vector<std::string>& variants) {
    std::vector<SettingOverride> shared;
    for (const std::string& kv : common) shared.push_back(parseSetting(kv));
    std::vector<SceneVariant> out;
    for (const std::string& v : variants) {
        const size_t colon = v.find(':');
        if (colon == std::string::npos || colon == 0)
            throw std::invalid_argument("--variant " + v + ": expected NAME:KEY=VALUE");
        const std::string name = v.substr(0, colon);
        auto it = std::find_if(out.begin(), out.end(), [&](const SceneVariant& s) { return s.name == name; });
        if (it == out.end()) it = out.insert(out.end(), SceneVariant{name, shared});
        it->overrides.push_back(parseSetting(v.substr(colon + 1)));
    }
    if (out.empty()) out.push_back({"scene", shared});
    return out;
}

nlohmann::json compareVariantsWithReference(const std::string& sceneFile, const std::string& referenceFile,
                                            const std::vector<double>& seconds,
                                            const std::vector<SceneVariant>& variants) {
    nlohmann::json out = {{"scene", sceneFile}, {"reference", referenceFile}, {"variants", nlohmann::json::array()}};
    for (const SceneVariant& v : variants) {
        nlohmann::json r = compareWithReference(sceneFile, referenceFile, seconds, v.overrides);
        r.erase("scene"), r.erase("reference");
        r["name"] = v.name;
        for (const SettingOverride& o : v.overrides) r["settings"].push_back(o.key + "=" + o.value);
        out["variants"].push_back(std::move(r));
    }
    return out;
}

std::string markdownTable(const nlohmann::json& result) {
    std::string table =
        "| variant | seconds | passes | relative noise | the same in luminance, lights' edges left out | bias of mean | RMSE / mean |\n"
        "|---|---|---|---|---|---|---|\n";
    char row[256];
    for (const nlohmann::json& v : result.at("variants"))
        for (const nlohmann::json& r : v.at("runs")) {
            std::snprintf(row, sizeof row, "| %s | %g | %d | %.4f | %.4f | %+.2f%% | %.4f |\n",
                          v.at("name").get<std::string>().c_str(), r.at("seconds").get<double>(), r.at("passes").get<int>(),
                          r.at("relative_noise").get<double>(), r.at("true_relative_error").get<double>(),
                          100 * r.at("bias_of_mean").get<double>(), r.at("relative_rmse").get<double>());
            table += row;
        }
    return table;
}

}  // namespace photon::bench
