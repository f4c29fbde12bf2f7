// pbrt-v4's procedural textures made of noise (perlin_noise.h): fbm, wrinkled, windy and
// marble, read at the point in the texture's space, and polka dots over a 2D mapping.
#include <algorithm>
#include <cmath>
#include <iterator>
#include "texture/perlin_noise.h"
#include "texture/textures.h"

namespace photon {
namespace {

// A colour of the point in the texture's space; its mean over a region of it.
class SolidNoiseTexture : public Texture {
public:
    explicit SolidNoiseTexture(const Transform& textureFromWorld) : textureFromWorld_(textureFromWorld) {}
    Color lookup(const TexturePoint& at) const override { return value(textureFromWorld_.point(at.p)); }
    Color average() const override { return average_; }

protected:
    virtual Color value(Vec3 q) const = 0;
    // The mean of value() over a 8 x 8 x 8 block of the texture's space, sampled on a
    // 32^3 grid (noise decorrelates within a unit): what light power and lobe choices use.
    void measureAverage() {
        constexpr int n = 32;
        constexpr float extent = 8;
        double sum[3] = {0, 0, 0};
        for (int k = 0; k < n; ++k)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const Color c = value(Vec3((i + 0.5f), (j + 0.5f), (k + 0.5f)) * (extent / n));
                    sum[0] += c.x, sum[1] += c.y, sum[2] += c.z;
                }
        const double cells = double(n) * n * n;
        average_ = Color(float(sum[0] / cells), float(sum[1] / cells), float(sum[2] / cells));
    }

private:
    Transform textureFromWorld_;
    Color average_{0.0f};
};

// Octaves of noise summed as fbm or as turbulence (perlin_noise.h).
class OctaveNoiseTexture final : public SolidNoiseTexture {
public:
    using Sum = float (*)(Vec3 p, float omega, int octaves);
    OctaveNoiseTexture(const Transform& textureFromWorld, Sum sum, int octaves, float roughness)
        : SolidNoiseTexture(textureFromWorld), sum_(sum), octaves_(octaves), roughness_(roughness) {
        measureAverage();
    }

private:
    Color value(Vec3 q) const override { return Color(sum_(q, roughness_, octaves_)); }
    Sum sum_;
    int octaves_;
    float roughness_;
};

// Waves whose height follows a slow wind: |fbm(q / 10, 1/2, 3)| fbm(q, 1/2, 6), pbrt-v4's
// WindyTexture.
class WindyTexture final : public SolidNoiseTexture {
public:
    explicit WindyTexture(const Transform& textureFromWorld) : SolidNoiseTexture(textureFromWorld) { measureAverage(); }

private:
    Color value(Vec3 q) const override {
        const float wind = fractalBrownianMotion(q * 0.1f, 0.5f, 3);
        const float waves = fractalBrownianMotion(q, 0.5f, 6);
        return Color(std::abs(wind) * waves);
    }
};

// Veins of stone: t = 1/2 + sin(y + variation fbm(q)) / 2 for q the point times `scale`,
// through a cubic Bezier spline over nine greys and a slate blue, times 1.5 (pbrt-v4's
// MarbleTexture, its colours and scale as there).
class MarbleTexture final : public SolidNoiseTexture {
public:
    MarbleTexture(const Transform& textureFromWorld, int octaves, float roughness, float scale, float variation)
        : SolidNoiseTexture(textureFromWorld), octaves_(octaves), roughness_(roughness), scale_(scale),
          variation_(variation) {
        measureAverage();
    }

    // The spline at t in [0, 1]: six segments, each the Bezier curve of four colours from
    // its first, evaluated by de Casteljau's steps.
    static Color spline(float t) {
        static const Color c[] = {{.58f, .58f, .6f}, {.58f, .58f, .6f}, {.58f, .58f, .6f},
                                  {.5f, .5f, .5f},   {.6f, .59f, .58f}, {.58f, .58f, .6f},
                                  {.58f, .58f, .6f}, {.2f, .2f, .33f},  {.58f, .58f, .6f}};
        constexpr int segments = int(std::size(c)) - 3;
        const int first = std::clamp(int(std::floor(t * segments)), 0, segments - 1);
        t = t * segments - float(first);
        auto lerp = [t](Color a, Color b) { return a * (1 - t) + b * t; };
        const Color a = lerp(c[first], c[first + 1]), b = lerp(c[first + 1], c[first + 2]),
                    d = lerp(c[first + 2], c[first + 3]);
        return lerp(lerp(a, b), lerp(b, d));
    }

private:
    Color value(Vec3 q) const override {
        q = q * scale_;
        const float marble = q.y + variation_ * fractalBrownianMotion(q, roughness_, octaves_);
        return spline(0.5f + 0.5f * std::sin(marble)) * 1.5f;
    }
    int octaves_;
    float roughness_, scale_, variation_;
};

// Whether (s, t) is inside a polka dot: the unit cells about integer (s, t) hold a dot
// where noise says so, of radius 0.35, shifted by noise up to 0.15 (pbrt-v4's
// InsidePolkaDot; its 2D noise reads z = 0.5).
bool insidePolkaDot(Vec2 st) {
    const float sCell = std::floor(st.x + 0.5f), tCell = std::floor(st.y + 0.5f);
    if (!(perlinNoise({sCell + 0.5f, tCell + 0.5f, 0.5f}) > 0)) return false;
    constexpr float radius = 0.35f, maxShift = 0.5f - radius;
    const float sCenter = sCell + maxShift * perlinNoise({sCell + 1.5f, tCell + 2.8f, 0.5f});
    const float tCenter = tCell + maxShift * perlinNoise({sCell + 4.5f, tCell + 9.8f, 0.5f});
    const float ds = st.x - sCenter, dt = st.y - tCenter;
    return ds * ds + dt * dt < radius * radius;
}

// The share of the (s, t) plane inside dots, over 64 x 64 cells sampled 16 x 16 each.
float dotCoverage() {
    static const float coverage = [] {
        constexpr int cells = 64, perCell = 16;
        int64_t inside = 0;
        for (int j = 0; j < cells * perCell; ++j)
            for (int i = 0; i < cells * perCell; ++i)
                inside += insidePolkaDot({(i + 0.5f) / perCell, (j + 0.5f) / perCell});
        return float(double(inside) / (double(cells * perCell) * (cells * perCell)));
    }();
    return coverage;
}

class DotsTexture final : public Texture {
public:
    DotsTexture(ColorParam inside, ColorParam outside, TextureMapping mapping)
        : inside_(std::move(inside)), outside_(std::move(outside)), mapping_(mapping),
          average_(inside_.average() * dotCoverage() + outside_.average() * (1 - dotCoverage())) {}
    Color lookup(const TexturePoint& at) const override {
        return insidePolkaDot(mapping_.apply(at)) ? inside_.eval(at) : outside_.eval(at);
    }
    // The dots' share of any large region (a unit square holds about one cell).
    Color average() const override { return average_; }

private:
    ColorParam inside_, outside_;
    TextureMapping mapping_;
    Color average_;
};

}  // namespace

std::shared_ptr<const Texture> makeFbmTexture(const Transform& textureFromWorld, int octaves, float roughness) {
    return std::make_shared<OctaveNoiseTexture>(textureFromWorld, fractalBrownianMotion, octaves, roughness);
}

std::shared_ptr<const Texture> makeWrinkledTexture(const Transform& textureFromWorld, int octaves, float roughness) {
    return std::make_shared<OctaveNoiseTexture>(textureFromWorld, turbulence, octaves, roughness);
}

std::shared_ptr<const Texture> makeWindyTexture(const Transform& textureFromWorld) {
    return std::make_shared<WindyTexture>(textureFromWorld);
}

std::shared_ptr<const Texture> makeMarbleTexture(const Transform& textureFromWorld, int octaves, float roughness,
                                                 float scale, float variation) {
    return std::make_shared<MarbleTexture>(textureFromWorld, octaves, roughness, scale, variation);
}

Color marbleSpline(float t) { return MarbleTexture::spline(t); }

std::shared_ptr<const Texture> makeDotsTexture(ColorParam inside, ColorParam outside, TextureMapping mapping) {
    return std::make_shared<DotsTexture>(std::move(inside), std::move(outside), mapping);
}

}  // namespace photon
