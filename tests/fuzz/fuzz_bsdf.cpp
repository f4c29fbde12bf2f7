// Fuzzes the measured-BRDF reader (an RGL .bsdf tensor file, as a scene or an uploaded pbrt
// scene names one): TensorFile on the bytes, then readMeasuredBrdf on its fields.
//
// Contract checked: both throw only std::runtime_error for bad input (a count, offset or
// shape the bytes cannot hold fails before anything is allocated for it); a BRDF they
// accept evaluates, samples and gives densities that are finite and not negative.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include "materials/measured_brdf.h"
#include "scene/measured_brdf_file.h"

namespace {

bool finiteAndNotNegative(photon::Color c) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(c[i]) || c[i] < 0) return false;
    return true;
}

void checkBrdf(const photon::Material& m) {
    const photon::Vec3 dirs[] = {{0, 0, 1}, {0.6f, 0, 0.8f}, {-0.28f, 0.96f, 0.0f}, {0.1f, -0.3f, 0.9486833f}};
    const photon::MaterialInputs in;
    for (const photon::Vec3& wo : dirs) {
        for (const photon::Vec3& wi : dirs) {
            if (!finiteAndNotNegative(m.eval(wo, wi, in, photon::TransportMode::Radiance))) std::abort();
            const float p = m.pdf(wo, wi, in);
            if (!std::isfinite(p) || p < 0) std::abort();
        }
        for (float u : {0.0f, 0.3f, 0.999f}) {
            auto s = m.sample(wo, 0.5f, {u, 1 - u}, in, photon::TransportMode::Radiance);
            if (s && (!finiteAndNotNegative(s->weight) || !(s->pdf > 0) || !std::isfinite(s->pdf))) std::abort();
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        const photon::TensorFile file(std::string(reinterpret_cast<const char*>(data), size), "fuzz.bsdf");
        checkBrdf(*photon::makeMeasured(photon::readMeasuredBrdf(file)));
    } catch (const std::runtime_error&) {
    }
    return 0;
}
