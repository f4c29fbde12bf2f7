// Pixel filters (camera.filter): the samples a pixel draws weigh the image as the filter
// says, f(d) / integral(f), checked two ways:
// - the sampler alone, against each filter's integrals computed here by quadrature from
//   pbrt-v4's definitions (and in closed form for the box and the triangle);
// - whole renders of a sharp edge (a light filling half the view): a pixel's value is the
//   share of its filter on the lit side, for the path tracer and for SPPM alike.
#include <gtest/gtest.h>
#include <cmath>
#include <functional>
#include <photon/render.h>
#include "camera/pixel_filter.h"
#include "materials/material.h"
#include "scene/scene.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon {
namespace {

using Kind = PixelFilterDescription::Kind;

PixelFilterDescription filter(Kind kind, float radius) {
    PixelFilterDescription d;
    d.kind = kind;
    d.radius = {radius, radius};
    return d;
}

// One axis of each filter, from pbrt-v4's definitions (sec. 8.8), negative lobes cut.
std::function<double(double)> axisOf(const PixelFilterDescription& d) {
    const double r = d.radius.x;
    switch (d.kind) {
        case Kind::Box: return [r](double x) { return std::abs(x) <= r ? 1.0 : 0.0; };
        case Kind::Triangle: return [r](double x) { return std::max(r - std::abs(x), 0.0); };
        case Kind::Gaussian: {
            const double s = d.sigma;
            auto g = [s](double x) { return std::exp(-x * x / (2 * s * s)) / std::sqrt(2 * M_PI * s * s); };
            return [g, r](double x) { return std::abs(x) <= r ? std::max(g(x) - g(r), 0.0) : 0.0; };
        }
        case Kind::Mitchell: {
            const double b = d.b, c = d.c;
            return [b, c, r](double x) {
                const double t = std::abs(2 * x / r);
                double v = 0;
                if (t <= 1) v = ((12 - 9 * b - 6 * c) * t * t * t + (-18 + 12 * b + 6 * c) * t * t + (6 - 2 * b)) / 6;
                else if (t <= 2) v = ((-b - 6 * c) * t * t * t + (6 * b + 30 * c) * t * t + (-12 * b - 48 * c) * t + (8 * b + 24 * c)) / 6;
                return std::max(v, 0.0);
            };
        }
        case Kind::Lanczos: {
            const double tau = d.tau;
            auto sinc = [](double x) { return std::abs(x) < 1e-9 ? 1.0 : std::sin(M_PI * x) / (M_PI * x); };
            return [sinc, tau, r](double x) { return std::abs(x) <= r ? std::max(sinc(x) * sinc(x / tau), 0.0) : 0.0; };
        }
    }
    return {};
}

// The integral of g over [-r, r] by the midpoint rule on 200,000 steps.
double integrate(const std::function<double(double)>& g, double r) {
    const int n = 200000;
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += g(-r + 2 * r * (i + 0.5) / n);
    return sum * 2 * r / n;
}

TEST(PixelFilter, SamplesWeighTheImageAsTheFilterDoes) {
    PixelFilterDescription mitchell = filter(Kind::Mitchell, 2), lanczos = filter(Kind::Lanczos, 4);
    PixelFilterDescription gaussian = filter(Kind::Gaussian, 1.5f);
    for (const PixelFilterDescription& d :
         {filter(Kind::Box, 0.5f), filter(Kind::Box, 1.5f), filter(Kind::Triangle, 1), filter(Kind::Triangle, 2),
          gaussian, mitchell, lanczos}) {
        SCOPED_TRACE(testing::Message() << "kind " << static_cast<int>(d.kind) << ", radius " << d.radius.x);
        const PixelFilter f(d);
        const auto g = axisOf(d);
        const double r = d.radius.x, total = integrate(g, r);
        // Moments of the normalised filter along x: its mass (1), its spread, and its share
        // left of r / 3 (what a pixel that far from an edge sees of the edge's bright side).
        const double second = integrate([&](double x) { return x * x * g(x); }, r) / total;
        const double left = integrate([&](double x) { return x < r / 3 ? g(x) : 0.0; }, r) / total;
        // A Fibonacci lattice of sample points (Korobov's rank-1 lattice on F_30 = 832,040
        // points, generator F_29): an error near 1e-5 where the weights jump between cells,
        // far below the bounds, where a 512 x 512 grid's was 1e-3.
        const int64_t count = 832040, generator = 514229;
        double mass = 0, spread = 0, share = 0, largest = 0;
        for (int64_t i = 0; i < count; ++i) {
            const float ux = static_cast<float>((i + 0.5) / count);
            const float uy = static_cast<float>((static_cast<double>((i * generator) % count) + 0.5) / count);
            const PixelFilter::Sample s = f.sample({ux, uy});
            ASSERT_LE(std::abs(s.offset.x), r);
            ASSERT_LE(std::abs(s.offset.y), r);
            ASSERT_GE(s.weight, 0.0f);
            mass += s.weight;
            spread += s.weight * s.offset.x * s.offset.x;
            share += s.offset.x < r / 3 ? s.weight : 0.0;
            largest = std::max(largest, static_cast<double>(s.weight));
        }
        EXPECT_NEAR(mass / count, 1.0, 2e-4);
        EXPECT_NEAR(spread / count, second, 2e-3 * r * r);
        EXPECT_NEAR(share / count, left, 5e-4);
        // The box and the triangle are sampled exactly; the others from a table, whose cells
        // near a zero of the filter (its radius, a cut lobe) hold samples up to about twice
        // their cell's mean value, bounded all the same.
        if (d.kind == Kind::Box || d.kind == Kind::Triangle) EXPECT_EQ(largest, 1.0);
        else EXPECT_LT(largest, 2.5 * 2.5);
        // normalised() is the filter over its integral.
        EXPECT_NEAR(f.normalised({0.3f, -0.2f}), g(0.3) * g(-0.2) / (total * total), 1e-3 * g(0) * g(0) / (total * total));
    }
    // Closed forms: the triangle's spread is r^2 / 6, the box's r^2 / 3.
    EXPECT_NEAR(integrate([](double x) { return x * x * std::max(2 - std::abs(x), 0.0); }, 2) / 4, 4.0 / 6, 1e-6);
}

// A light of radiance 1 fills the left half of the view (x < 0 on the plane z = -1, seen by
// a camera at the origin looking down -z), so the edge falls between pixel columns
// kWidth / 2 - 1 and kWidth / 2. A pixel whose centre is at c from the edge (positive on
// the lit side) reads the filter's share left of c.
constexpr int kWidth = 8, kHeight = 8;

Image renderEdge(const PixelFilterDescription& filter, IntegratorKind integrator, int passes) {
    SceneDescription d;
    d.camera = test::camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 30, kWidth, kHeight);
    d.camera.filter = filter;
    d.materials = {makeDiffuse(Color(0.0f))};
    d.materialNames = {"black"};
    d.shapes = {test::quad({-10, -10, -1}, {10, 0, 0}, {0, 20, 0}, 0, Color(1.0f))};
    d.render.integrator = integrator;
    d.render.passes = passes;
    d.render.photonsPerPass = 1000;
    return test::renderImage(std::move(d));
}

TEST(PixelFilter, ASharpEdgeIsBlurredByTheFilter) {
    PixelFilterDescription gaussian = filter(Kind::Gaussian, 1.5f);
    struct Case {
        PixelFilterDescription filter;
        IntegratorKind integrator;
    };
    for (const Case& c : {Case{filter(Kind::Box, 0.5f), IntegratorKind::Path},
                          Case{filter(Kind::Triangle, 1), IntegratorKind::Path},
                          Case{filter(Kind::Triangle, 1), IntegratorKind::Sppm}, Case{gaussian, IntegratorKind::Path},
                          Case{gaussian, IntegratorKind::Sppm}}) {
        SCOPED_TRACE(testing::Message() << "kind " << static_cast<int>(c.filter.kind) << ", integrator "
                                        << static_cast<int>(c.integrator));
        const int passes = 2048;
        const Image image = renderEdge(c.filter, c.integrator, passes);
        const auto g = axisOf(c.filter);
        const double r = c.filter.radius.x, total = integrate(g, r);
        for (int x = kWidth / 2 - 3; x < kWidth / 2 + 3; ++x) {
            const double centre = kWidth / 2 - (x + 0.5);  // from the edge, positive on the lit side
            const double expected = integrate([&](double t) { return t < centre ? g(t) : 0.0; }, r) / total;
            // The column's mean over its 8 pixels: 16,384 samples of 0 or about 1, so a
            // standard error below 0.004; 0.015 is four of them.
            double mean = 0;
            for (int y = 0; y < kHeight; ++y) mean += image.at(x, y).x;
            mean /= kHeight;
            EXPECT_NEAR(mean, expected, 0.015) << "column " << x;
        }
    }
    // For the record, the triangle of radius 1 half a pixel from the edge: 1 - 0.5^2 / 2.
    const auto tent = axisOf(filter(Kind::Triangle, 1));
    EXPECT_NEAR(integrate([&](double t) { return t < 0.5 ? tent(t) : 0.0; }, 1), 0.875, 1e-6);
}

}  // namespace
}  // namespace photon
