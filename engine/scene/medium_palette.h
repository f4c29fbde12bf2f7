// Media whose reflectance is a texture (MediumReflectance) rendered as palettes of
// homogeneous media. Paths carry the index of the medium they are in, and every estimator
// that crosses a medium (free flights, transmittance, shadow rays, photons in lanes) reads
// one MediumDescription by that index; so a textured medium becomes (kSteps + 1)^3 media,
// one for each reflectance on a grid of kSteps steps per channel, and a path that enters it
// takes the one for the reflectance at the point where it enters, as random-walk subsurface
// scattering takes the albedo at its entry point. The texture's value there is dithered to
// one of the two neighbouring steps in each channel, by a number hashed from the point, with
// the odds that keep its mean: E[step / kSteps] = reflectance, so the image converges to
// that of the reflectance itself up to the dipole's curvature over one step (below 0.1% of
// the reflectance; tests/test_subsurface_reflectance.cpp). 36k media of about 120 bytes each:
// 4.3 MB a textured medium.
#pragma once
#include <cstdint>
#include <vector>
#include "description/scene_description.h"

namespace photon {

class MediumPalettes {
public:
    static constexpr int kSteps = 32;

    MediumPalettes() = default;
    // Appends each textured medium's palette to `media` (whose first media are the scene's).
    explicit MediumPalettes(std::vector<MediumDescription>& media);

    bool any() const { return !first_.empty(); }
    // The scene's medium an index stands for: a palette's textured medium, else itself.
    int32_t family(int32_t medium) const {
        return medium >= 0 && size_t(medium) < family_.size() ? family_[size_t(medium)] : medium;
    }
    // Whether `medium`, one of the scene's, has a palette.
    bool textured(int32_t medium) const {
        return medium >= 0 && size_t(medium) < first_.size() && first_[size_t(medium)] >= 0;
    }
    // The palette's medium for a path that enters the textured `medium` at `at`.
    int32_t entered(int32_t medium, const TexturePoint& at) const;

private:
    std::vector<int32_t> first_;   // by scene medium: its palette's first index, -1 if none
    std::vector<int32_t> family_;  // by index, palettes' included: the scene medium it stands for
    std::vector<const MediumReflectance*> reflectance_;  // by scene medium
};

}  // namespace photon
