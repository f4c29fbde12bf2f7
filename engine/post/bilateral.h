// The bilateral filter (Tomasi & Manduchi 1998):
//   BF[I]_p = 1/W_p sum_q G_s(|p - q|) G_r(|I_p - I_q|) I_q,   W_p = sum of the weights,
// with Gaussians G. Optional guide images add their own range terms (the cross or joint
// bilateral filter: Eisemann & Durand 2004; Petschnigg et al. 2004): a neighbour counts
// only where it also looks like the same material (albedo) facing the same way (normal),
// so geometric and texture edges stay sharp even where noise hides them in I itself.
#pragma once
#include <photon/image.h>

namespace photon {

struct BilateralParams {
    float sigmaSpatial = 1.5f;  // pixels
    // On the difference of log colours, ln(I + eps) per channel, root-mean-square over
    // the channels. Rendered images are HDR: a light and the ceiling beside it differ by
    // a factor of 30, a shadow and the wall by 3, while noise is a fraction of the local
    // level. A log difference measures every one of these as a ratio, whatever the
    // exposure, so one sigma suits dark and bright regions alike; an absolute difference
    // would either blur the shadows or leave the bright regions noisy. eps (1% of the
    // image's mean luminance) keeps near-black pixels from looking infinitely far apart.
    float sigmaRange = 1.0f;
    float sigmaAlbedo = 0.1f;   // on the albedo difference, root-mean-square over channels
    float sigmaNormal = 0.2f;   // on the Euclidean distance of the normals
};

// Either guide may be null (no term); each must have the image's size.
struct BilateralGuides {
    const Image* albedo = nullptr;
    const Image* normal = nullptr;
};

// The window's half-width: ceil(3 sigma), beyond which the spatial Gaussian is < 1.1%.
int bilateralRadius(float sigmaSpatial);

// Parallel over rows; each output pixel depends only on the inputs, so the result is
// the same for any thread count. The window is clipped at the image border.
Image bilateralFilter(const Image& image, const BilateralParams& params, const BilateralGuides& guides = {});

}  // namespace photon
