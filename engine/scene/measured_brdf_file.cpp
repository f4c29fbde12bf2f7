#include "scene/measured_brdf_file.h"
#include <cmath>
#include <stdexcept>
#include "math/sampling.h"
#include "math/spectrum_rgb.h"

namespace photon {

namespace {

std::string shapeText(const std::vector<uint64_t>& shape) {
    std::string s = "[";
    for (size_t i = 0; i < shape.size(); ++i) s += (i ? ", " : "") + std::to_string(shape[i]);
    return s + "]";
}

std::vector<float> finiteFloats(const TensorFile& file, const std::string& key, size_t rank) {
    std::vector<float> values = file.floats(key, rank);
    for (float v : values)
        if (!std::isfinite(v)) file.fail("field \"" + key + "\" holds a value that is not finite");
    return values;
}

// A 2D table's field: ny x nx, each at least 2.
BilinearTable<float> table2D(const TensorFile& file, const std::string& key) {
    const auto& shape = file.field(key, TensorFile::Type::Float32, 2).shape;
    if (shape[0] < 2 || shape[1] < 2) file.fail("field \"" + key + "\" must be at least 2 x 2, not " + shapeText(shape));
    return BilinearTable<float>(int(shape[1]), int(shape[0]), finiteFloats(file, key, 2));
}

// A field of one slice per measured direction: phi_i x theta_i x (extra) x n x n.
void checkSlices(const TensorFile& file, const std::string& key, size_t rank, uint64_t phis, uint64_t thetas,
                 uint64_t n) {
    const auto& shape = file.field(key, TensorFile::Type::Float32, rank).shape;
    if (shape[0] != phis || shape[1] != thetas || shape[rank - 1] != n || shape[rank - 2] != n)
        file.fail("field \"" + key + "\" has shape " + shapeText(shape) + ", expected " + std::to_string(phis) + " x " +
                  std::to_string(thetas) + (rank == 5 ? " x k" : "") + " x " + std::to_string(n) + " x " +
                  std::to_string(n) + " (phi_i x theta_i" + (rank == 5 ? " x channels" : "") + " x n x n)");
}

// The reflectance table in linear sRGB: each node's spectrum (or RGB triple) in slices of
// phis * thetas, channels, n * n.
std::vector<Color> reflectanceColors(const TensorFile& file, uint64_t slices, uint64_t n) {
    const bool spectral = file.has("spectra") || !file.has("rgb");
    const std::string key = spectral ? "spectra" : "rgb";
    const std::vector<float> values = finiteFloats(file, key, 5);
    std::vector<Color> weights;
    if (spectral) {
        const std::vector<float> lambda = finiteFloats(file, "wavelengths", 1);
        if (lambda.empty()) file.fail("field \"wavelengths\" is empty");
        for (size_t i = 1; i < lambda.size(); ++i)
            if (!(lambda[i] > lambda[i - 1])) file.fail("field \"wavelengths\" must be ascending");
        weights = spectrumWeights(std::vector<double>(lambda.begin(), lambda.end()));
    } else {
        weights = {Color(1, 0, 0), Color(0, 1, 0), Color(0, 0, 1)};
    }
    const auto& shape = file.field(key, TensorFile::Type::Float32, 5).shape;
    if (shape[2] != weights.size())
        file.fail("field \"" + key + "\" has " + std::to_string(shape[2]) + " channels, expected " +
                  std::to_string(weights.size()));
    const size_t nodes = size_t(n * n);
    std::vector<Color> colors(size_t(slices) * nodes, Color(0.0f));
    for (size_t s = 0; s < slices; ++s)
        for (size_t c = 0; c < weights.size(); ++c) {
            const float* channel = values.data() + (s * weights.size() + c) * nodes;
            for (size_t k = 0; k < nodes; ++k) colors[s * nodes + k] += weights[c] * channel[k];
        }
    return colors;
}

}  // namespace

std::shared_ptr<const MeasuredBrdf> readMeasuredBrdf(const TensorFile& file) {
    auto brdf = std::make_shared<MeasuredBrdf>();
    const std::vector<float> thetas = finiteFloats(file, "theta_i", 1), phis = finiteFloats(file, "phi_i", 1);
    if (thetas.empty() || phis.empty()) file.fail("fields \"theta_i\" and \"phi_i\" must not be empty");
    try {
        brdf->outgoing = SliceAxes({phis, thetas});
    } catch (const std::invalid_argument&) {
        file.fail("fields \"phi_i\" and \"theta_i\" must be ascending");
    }
    // pbrt-v4 and Mitsuba take a table of at most two azimuths as isotropic. An anisotropic
    // one must cover the whole circle: a table of 1/k of it, which their "reduction" k would
    // repeat, is refused by pbrt-v4 as by photon.
    brdf->isotropic = phis.size() <= 2;
    if (!brdf->isotropic && std::rint(2.0f * kPi / (phis.back() - phis.front())) != 1.0f)
        file.fail("an anisotropic table's \"phi_i\" must span the circle (from -pi to pi)");
    brdf->ndf = table2D(file, "ndf");
    brdf->sigma = table2D(file, "sigma");
    const auto& vndfShape = file.field("vndf", TensorFile::Type::Float32, 4).shape;
    const uint64_t n = vndfShape[3];
    if (n < 2 || vndfShape[2] != n) file.fail("field \"vndf\" must hold square slices of at least 2 x 2, not " + shapeText(vndfShape));
    checkSlices(file, "vndf", 4, phis.size(), thetas.size(), n);
    checkSlices(file, "luminance", 4, phis.size(), thetas.size(), n);
    checkSlices(file, file.has("spectra") || !file.has("rgb") ? "spectra" : "rgb", 5, phis.size(), thetas.size(), n);
    try {
        brdf->vndf = BilinearWarp2D(int(n), int(n), finiteFloats(file, "vndf", 4));
        brdf->luminance = BilinearWarp2D(int(n), int(n), finiteFloats(file, "luminance", 4));
    } catch (const std::invalid_argument&) {
        file.fail("fields \"vndf\" and \"luminance\" are densities and must not be negative");
    }
    brdf->reflectance = BilinearTable<Color>(int(n), int(n), reflectanceColors(file, phis.size() * thetas.size(), n));
    return brdf;
}

}  // namespace photon
