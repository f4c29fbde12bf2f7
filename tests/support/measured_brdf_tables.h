// Measured-BRDF files (RGL's ".bsdf" tensor files) written from a known BRDF, for tests:
// an isotropic GGX surface of roughness alpha, tabulated as Dupuy & Jakob 2018 lay out a
// measurement: D and the projected area sigma over the angles' unit-square coordinates,
// the visible normals' density for each tabulated outgoing direction, a luminance over
// the warp's input (uneven on purpose: it steers sampling only) and a constant reflectance R.
// The BRDF the file describes is then f = R D(wm) / (4 sigma(wo) cos theta_i).
#pragma once
#include <cmath>
#include <cstring>
#include <string>
#include <vector>
#include "math/sampling.h"
#include "scene/tensor_file.h"

namespace photon::test {

// GGX's distribution of normals at angle theta from the normal (Walter et al. 2007, eq. 33)
// and the area of the microsurface projected toward a direction at angle theta,
// cos theta (1 + Lambda) = (cos theta + sqrt(cos^2 theta + alpha^2 sin^2 theta)) / 2.
inline double ggxD(double alpha, double theta) {
    const double c = std::cos(theta), t2 = std::tan(theta) * std::tan(theta), a2 = alpha * alpha;
    if (c <= 0) return 0;
    return a2 / (kPi * c * c * c * c * (a2 + t2) * (a2 + t2));
}
inline double ggxSigma(double alpha, double theta) {
    const double c = std::cos(theta), s = std::sin(theta);
    return 0.5 * (c + std::sqrt(c * c + alpha * alpha * s * s));
}

inline double uToTheta(double u) { return u * u * 0.5 * kPi; }
inline double vToPhi(double v) { return (2 * v - 1) * kPi; }

inline TensorFieldData floatField(const std::string& name, std::vector<uint64_t> shape, const std::vector<float>& v) {
    std::string bytes(v.size() * sizeof(float), '\0');
    std::memcpy(bytes.data(), v.data(), bytes.size());
    return {name, TensorFile::Type::Float32, std::move(shape), std::move(bytes)};
}

struct GgxTableOptions {
    double alpha = 0.4;
    Color reflectance{0.9f, 0.6f, 0.3f};
    int n = 64;           // samples a side of each 2D table
    int thetas = 12;      // outgoing elevations tabulated
    bool spectral = true; // R as "spectra" on four wavelengths (flat), else as "rgb"
};

inline std::vector<TensorFieldData> ggxTableFields(const GgxTableOptions& o) {
    const int n = o.n, nt = o.thetas;
    std::vector<float> thetaI(nt), phiI = {0.0f};
    // Outgoing elevations spaced as the tables' u, up to 85 degrees.
    for (int k = 0; k < nt; ++k) thetaI[k] = float(uToTheta(double(k) / (nt - 1)) * (85.0 / 90.0));
    auto grid = [&](auto value) {
        std::vector<float> v(size_t(n) * n);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) v[size_t(j) * n + i] = float(value(double(i) / (n - 1), double(j) / (n - 1)));
        return v;
    };
    std::vector<float> ndf = grid([&](double u, double) { return ggxD(o.alpha, uToTheta(u)); });
    std::vector<float> sigma = grid([&](double u, double) { return ggxSigma(o.alpha, uToTheta(u)); });
    std::vector<float> vndf, luminanceTable;
    for (int k = 0; k < nt; ++k) {
        const double to = thetaI[k];
        // Visible normals from wo = (sin to, 0, cos to): max(0, wo.m) D(m) per solid angle,
        // times the (u, v) -> sphere Jacobian 2 pi^2 u sin(theta_m); v is the azimuth
        // relative to wo's.
        auto visible = grid([&](double u, double v) {
            const double tm = uToTheta(u), pm = vToPhi(v);
            const double cosWoM = std::sin(to) * std::sin(tm) * std::cos(pm) + std::cos(to) * std::cos(tm);
            return std::max(0.0, cosWoM) * ggxD(o.alpha, tm) * 2 * kPi * kPi * u * std::sin(tm);
        });
        vndf.insert(vndf.end(), visible.begin(), visible.end());
        auto lum = grid([&](double u, double v) { return 1.0 + 2.0 * u * v; });
        luminanceTable.insert(luminanceTable.end(), lum.begin(), lum.end());
    }
    std::vector<float> wavelengths = {400, 500, 600, 700}, reflectance;
    const int channels = o.spectral ? 4 : 3;
    for (int k = 0; k < nt; ++k)
        for (int c = 0; c < channels; ++c) {
            // A flat spectrum projects to grey; the RGB form carries the colour.
            const float r = o.spectral ? luminance(o.reflectance) : o.reflectance[c];
            reflectance.insert(reflectance.end(), size_t(n) * n, r);
        }
    const uint64_t un = uint64_t(n), unt = uint64_t(nt);
    std::vector<TensorFieldData> fields = {
        floatField("theta_i", {unt}, thetaI),
        floatField("phi_i", {1}, phiI),
        floatField("ndf", {un, un}, ndf),
        floatField("sigma", {un, un}, sigma),
        floatField("vndf", {1, unt, un, un}, vndf),
        floatField("luminance", {1, unt, un, un}, luminanceTable),
        {"description", TensorFile::Type::UInt8, {4}, "ggx "},
        {"jacobian", TensorFile::Type::UInt8, {1}, std::string(1, '\1')},
    };
    if (o.spectral) {
        fields.push_back(floatField("wavelengths", {4}, wavelengths));
        fields.push_back(floatField("spectra", {1, unt, 4, un, un}, reflectance));
    } else {
        fields.push_back(floatField("rgb", {1, unt, 3, un, un}, reflectance));
    }
    return fields;
}

inline std::string ggxTableFile(const GgxTableOptions& o = {}) { return tensorFileBytes(ggxTableFields(o)); }

}  // namespace photon::test
