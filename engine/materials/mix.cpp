// A blend of two materials, f = (1 - t) f_a + t f_b with t a constant or a texture (moss on
// stone, worn paint). Sampling picks one of the two by its share and weights the sample by
// the whole mixture's eval and pdf (one-sample MIS with the balance heuristic, Veach 1997
// sec. 9.2.4), so the estimate has no more variance than the better of the two allows.
#include "materials/material.h"

namespace photon {
namespace {

class MixMaterial final : public Material {
public:
    // The mixture's own tint is white: each part applies its own colour, and what reads
    // "tint x a factor" (radiosity's diffuse reflectance, the denoiser's albedo) sees the
    // parts' colours through eval alone.
    MixMaterial(MaterialPtr a, MaterialPtr b, FloatParam amount)
        : Material(Color(1.0f)), a_(std::move(a)), b_(std::move(b)), amount_(std::move(amount)) {}

    unsigned lobes() const override { return a_->lobes() | b_->lobes(); }
    bool twoSided() const override { return a_->twoSided(); }  // both agree (makeMix checks)
    bool textured() const override { return amount_.textured() || a_->textured() || b_->textured(); }
    bool transmits() const override { return a_->transmits() || b_->transmits(); }

    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode mode, unsigned lobes) const override {
        float t = amount_.eval(in.uv);
        Color f(0.0f);
        if (t < 1) f += a_->eval(wo, wi, a_->inputsAt(in.uv), mode, lobes) * (1.0f - t);
        if (t > 0) f += b_->eval(wo, wi, b_->inputsAt(in.uv), mode, lobes) * t;
        return f;
    }

    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs& in, unsigned lobes) const override {
        Choice c = choice(in.uv, lobes);
        float p = 0;
        if (c.a > 0) p += c.a * a_->pdf(wo, wi, a_->inputsAt(in.uv), lobes);
        if (c.a < 1) p += (1.0f - c.a) * b_->pdf(wo, wi, b_->inputsAt(in.uv), lobes);
        return p;
    }

    std::optional<BSDFSample> sample(Vec3 wo, float uLobe, Vec2 u, const MaterialInputs& in, TransportMode mode,
                                     unsigned lobes) const override {
        Choice c = choice(in.uv, lobes);
        if (!(c.a > 0) && !(c.a < 1)) return std::nullopt;
        const bool pickA = uLobe < c.a;
        const Material& part = pickA ? *a_ : *b_;
        const float pick = pickA ? c.a : 1.0f - c.a;
        const float share = pickA ? 1.0f - c.t : c.t;  // the part's factor in f
        const float uPart = pickA ? uLobe / c.a : (uLobe - c.a) / (1.0f - c.a);
        std::optional<BSDFSample> s = part.sample(wo, std::min(uPart, 0x1.fffffep-1f), u, part.inputsAt(in.uv), mode, lobes);
        if (!s) return std::nullopt;
        if (s->delta) {  // a Dirac lobe belongs to one part alone
            s->weight *= share / pick;
            s->pdf *= pick;
            return s;
        }
        float p = pdf(wo, s->wi, in, lobes);
        if (!(p > 0)) return std::nullopt;
        s->weight = eval(wo, s->wi, in, mode, lobes) * (std::abs(s->wi.z) / p);
        s->pdf = p;
        return s;
    }

    // The diffuse lobes' share, each part's own share weighted by its factor.
    float diffuseShare(Vec3 wo, const MaterialInputs& in) const override {
        float t = amount_.eval(in.uv), share = 0;
        if (a_->hasDiffuse()) share += (1.0f - t) * a_->diffuseShare(wo, a_->inputsAt(in.uv));
        if (b_->hasDiffuse()) share += t * b_->diffuseShare(wo, b_->inputsAt(in.uv));
        return share;
    }

private:
    struct Choice {
        float t;  // the mix amount at the point
        float a;  // probability of sampling part a among the parts that have `lobes`
    };
    Choice choice(Vec2 uv, unsigned lobes) const {
        float t = amount_.eval(uv);
        float wa = (a_->lobes() & lobes) ? 1.0f - t : 0.0f;
        float wb = (b_->lobes() & lobes) ? t : 0.0f;
        float sum = wa + wb;
        // No part has the lobes: a = NaN makes both "c.a > 0" and "c.a < 1" false.
        return {t, sum > 0 ? wa / sum : std::numeric_limits<float>::quiet_NaN()};
    }

    MaterialPtr a_, b_;
    FloatParam amount_;
};

}  // namespace

MaterialPtr makeMix(MaterialPtr a, MaterialPtr b, FloatParam amount) {
    if (a->twoSided() != b->twoSided())
        throw std::invalid_argument("a mix cannot join a one-sided material (a dielectric) with a two-sided one");
    return std::make_shared<MixMaterial>(std::move(a), std::move(b), std::move(amount));
}

}  // namespace photon
