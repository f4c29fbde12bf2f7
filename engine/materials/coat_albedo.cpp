#include "materials/coat_albedo.h"
#include <algorithm>
#include <cmath>
#include "materials/fresnel.h"

namespace photon {

CoatAlbedo::CoatAlbedo(float ior, GGX ggx) : ior_(ior), ggx_(ggx) {
    if (!ggx_.smooth())
        for (int k = 0; k < kTableSize; ++k) table_[k] = integrateRough(tableCosine(k));
    // Ebar by the midpoint rule, with E as the lobes use it (interpolated), so that a white
    // base under the coat keeps exactly what the coat does not reflect.
    constexpr int kSteps = 4096;
    double sum = 0;
    for (int i = 0; i < kSteps; ++i) {
        float mu = (float(i) + 0.5f) / kSteps;
        sum += 2.0 * double((*this)(mu)) * mu / kSteps;
    }
    cosineWeighted_ = float(sum);
}

float CoatAlbedo::operator()(float cosTheta) const {
    if (ggx_.smooth()) return fresnelDielectric(cosTheta, ior_);
    // Linear in sqrt(cos): the nodes crowd toward grazing, where E changes fastest.
    float t = std::sqrt(std::clamp(cosTheta, 0.0f, 1.0f)) * (kTableSize - 1);
    int k = std::min(int(t), kTableSize - 2);
    float f = t - float(k);
    return table_[k] * (1.0f - f) + table_[k + 1] * f;
}

float CoatAlbedo::tableCosine(int k) {
    float t = float(k) / (kTableSize - 1);
    return std::max(t * t, 1e-4f);
}

// E(mu) = int F(wo.h) D G2 / (4 mu cos_i) cos_i dwi, by visible-normal sampling on a
// stratified grid: with wi = reflect(wo, h) and h drawn from D_wo, the integrand over the
// density is F(wo.h) G2 / G1(wo) (Heitz 2018, sec. 2), 0 where wi is below.
float CoatAlbedo::integrateRough(float mu) const {
    constexpr int kGrid = 48;
    Vec3 wo(std::sqrt(1.0f - mu * mu), 0.0f, mu);
    double sum = 0;
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j) {
            Vec3 h = ggx_.sampleVisibleNormal(wo, {(float(i) + 0.5f) / kGrid, (float(j) + 0.5f) / kGrid});
            Vec3 wi = reflect(wo, h);
            if (wi.z <= 0) continue;
            sum += fresnelDielectric(dot(wo, h), ior_) * ggx_.G2(wo, wi) / ggx_.G1(wo);
        }
    return float(sum / (kGrid * kGrid));
}

}  // namespace photon
