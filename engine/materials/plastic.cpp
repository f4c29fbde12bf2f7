// Plastic: a Lambertian base under a dielectric coating of index `ior`. The coating is
// a GGX microfacet reflector (or an ideal mirror when smooth); the base only receives
// what the coating transmits on the way in and on the way out. The simpler of the two
// coated models: coated_diffuse.cpp adds the internal reflections and the 1/ior^2 of
// refraction, and keeps the full energy under a rough coat.
#include "materials/coat_over_diffuse.h"

namespace photon {
namespace {

class Plastic final : public CoatOverDiffuse {
public:
    using CoatOverDiffuse::CoatOverDiffuse;

private:
    // f_d = (1 - F(cos_o)) (1 - F(cos_i)) albedo / pi. The base only gets what the coat
    // transmits on the way in and out, so its albedo is below 1 - F(cos_o) while the
    // coat's is about F (the idea behind the coupled diffuse term of Ashikhmin & Shirley
    // 2000, "An Anisotropic Phong BRDF Model", here with the exact dielectric Fresnel and
    // no renormalisation). Re-reflections inside the coat are ignored, which loses a
    // little energy; tests/test_bsdf.cpp checks the albedo never exceeds one.
    Color diffuse(Vec3 wo, Vec3 wi, Color albedo) const override {
        return albedo * ((1.0f - fresnel(wo.z)) * (1.0f - fresnel(wi.z)) * kInvPi);
    }
    float coatAlbedo(float cosThetaO) const override { return fresnel(cosThetaO); }
};

}  // namespace

MaterialPtr makePlastic(ColorParam albedo, float ior, float roughness) {
    return std::make_shared<Plastic>(std::move(albedo), ior, roughness);
}

}  // namespace photon
