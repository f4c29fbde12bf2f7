// render.lobe_choice "learned": at the first vertex of a pixel's camera path where the path
// chooses between a material's diffuse base (stop, store the visible point) and its other
// lobes (follow the coat's or plastic's highlight), or between a smooth dielectric's
// reflection ("others") and refraction, the probability of the others comes from what that
// choice brought in the pixel's earlier passes, not from the material's albedos or the
// Fresnel factor alone.
//
// Choosing branch b with probability q_b and weighting what it brings, C_b, by 1 / q_b has
// second moment sum_b M_b / q_b with M_b = E[C_b^2]; minimised under sum_b q_b = 1 (one
// Lagrange multiplier) it gives q_b proportional to sqrt(M_b). A pass that took branch b and
// brought L = C_b / q_b from it adds L^2 q_b = C_b^2 / q_b to b's sum, the other branch's
// sum nothing: over passes, each sum is an unbiased estimate of its M_b times the passes.
// The sums are read over the pixel and its eight neighbours, as a highlight covers many
// pixels and one pixel takes the rarer branch seldom. The probabilities depend on earlier
// passes only, and every choice is weighted by the probability it was made with, so each
// pass stays unbiased; they come from per-pixel figures alone, so they are the same for a
// seed on any thread count.
#pragma once
#include <cstdint>
#include <istream>
#include <ostream>
#include <vector>

namespace photon {

// One pass's choice at a pixel, as the learning reads it: the probability of the branch
// taken in 15 bits and whether it was the others in the 16th (0: no choice), and the
// luminance of the direct light found before the choice as a float's upper 16 bits
// (bfloat16: 8 bits of precision, 0.4%).
struct LobeChoiceRecord {
    uint16_t branch = 0;
    uint16_t directBefore = 0;

    static LobeChoiceRecord of(bool others, float probability, float directBefore);
    bool made() const { return branch != 0; }
    bool others() const { return (branch & 0x8000u) != 0; }
    float probability() const { return static_cast<float>(branch & 0x7fffu) / 32767.0f; }
    float directBeforeChoice() const;
};

class LearnedLobeChoice {
public:
    LearnedLobeChoice() = default;
    LearnedLobeChoice(int width, int height)
        : width_(width), height_(height), moments_(static_cast<size_t>(width) * height) {}

    // The probability of following the other lobes at pixel `pixel`, given the material's own
    // (`materialOthers`): the learned one once passes have taught it, within [half the
    // material's, 0.95] and never below 0.05, so that neither branch's weight grows
    // beyond 20 times, nor far beyond what the material alone would give it.
    float othersProbability(size_t pixel, float materialOthers) const;
    // A pass's choice at `pixel`: the branch it took (others or the diffuse base), the
    // probability it was taken with and the luminance the branch brought, its weight included.
    void add(size_t pixel, bool others, float probability, float luminance) {
        Moments& m = moments_[pixel];
        const float second = luminance * luminance * probability;
        (others ? m.others : m.base) += second;
    }
    // Counts a pass as added (after its pixels).
    void countPass() { ++passes_; }
    int64_t passes() const { return passes_; }

    void save(std::ostream& out) const;
    // Reads the block save() wrote if the stream is at one, else starts learning anew;
    // throws CheckpointError on a damaged block.
    void restore(std::istream& in, int64_t renderPasses);

    // Passes before the learned probability is used: till then the material's.
    static constexpr int64_t kWarmUpPasses = 4;
    static constexpr size_t kBytesPerPixel = 8;

private:
    struct Moments {
        float others = 0, base = 0;  // the two branches' second moments, summed over passes
    };
    int width_ = 0, height_ = 0;
    int64_t passes_ = 0;
    std::vector<Moments> moments_;
    static_assert(sizeof(Moments) == kBytesPerPixel);
};

}  // namespace photon
