#include "materials/material_mixture.h"
#include <algorithm>
#include <cmath>
#include <limits>

namespace photon {

Color MaterialMixture::eval(Vec3 wo, Vec3 wi, TransportMode mode, unsigned lobes) const {
    Color f(0.0f);
    if (t_ < 1) f += a_.eval(wo, wi, inA_, mode, lobes) * (1.0f - t_);
    if (t_ > 0) f += b_.eval(wo, wi, inB_, mode, lobes) * t_;
    return f;
}

float MaterialMixture::probabilityOfA(unsigned lobes) const {
    const float wa = (a_.lobes() & lobes) ? 1.0f - t_ : 0.0f;
    const float wb = (b_.lobes() & lobes) ? t_ : 0.0f;
    const float sum = wa + wb;
    return sum > 0 ? wa / sum : std::numeric_limits<float>::quiet_NaN();
}

float MaterialMixture::pdf(Vec3 wo, Vec3 wi, unsigned lobes) const {
    const float pa = probabilityOfA(lobes);
    float p = 0;
    if (pa > 0) p += pa * a_.pdf(wo, wi, inA_, lobes);
    if (pa < 1) p += (1.0f - pa) * b_.pdf(wo, wi, inB_, lobes);
    return p;
}

std::optional<BSDFSample> MaterialMixture::sample(Vec3 wo, float uLobe, Vec2 u, TransportMode mode,
                                                  unsigned lobes) const {
    const float pa = probabilityOfA(lobes);
    if (!(pa > 0) && !(pa < 1)) return std::nullopt;
    const bool pickA = uLobe < pa;
    const Material& part = pickA ? a_ : b_;
    const float pick = pickA ? pa : 1.0f - pa;
    const float share = pickA ? 1.0f - t_ : t_;  // the part's factor in f
    const float uPart = pickA ? uLobe / pa : (uLobe - pa) / (1.0f - pa);
    std::optional<BSDFSample> s = part.sample(wo, std::min(uPart, 0x1.fffffep-1f), u, pickA ? inA_ : inB_, mode, lobes);
    if (!s) return std::nullopt;
    if (s->delta) {  // a Dirac lobe belongs to one part alone
        s->weight *= share / pick;
        s->pdf *= pick;
        s->lobeProbability *= pick;
        return s;
    }
    const float p = pdf(wo, s->wi, lobes);
    if (!(p > 0)) return std::nullopt;
    s->weight = eval(wo, s->wi, mode, lobes) * (std::abs(s->wi.z) / p);
    s->pdf = p;
    return s;
}

float MaterialMixture::diffuseShare(Vec3 wo) const {
    float share = 0;
    if (a_.hasDiffuse()) share += (1.0f - t_) * a_.diffuseShare(wo, inA_);
    if (b_.hasDiffuse()) share += t_ * b_.diffuseShare(wo, inB_);
    return share;
}

}  // namespace photon
