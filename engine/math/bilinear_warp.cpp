#include "math/bilinear_warp.h"
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace photon {

namespace {

// t in [0, 1] at which the integral of the linear density (1 - t) c0 + t c1 from 0 reaches
// s: c0 t + (c1 - c0) t^2 / 2 = s, in the form that stays exact as c1 -> c0.
float invertLinearIntegral(float c0, float c1, float s) {
    const float root = std::sqrt(std::max(0.0f, c0 * c0 + 2.0f * (c1 - c0) * s));
    const float denominator = c0 + root;
    if (!(denominator > 0)) return 0.0f;
    return std::clamp(2.0f * s / denominator, 0.0f, 1.0f);
}

// The grid cell holding coordinate x in [0, 1] of an n-sample axis and the fraction across it.
struct CellAt {
    int index;
    float t;
};
CellAt cellAt(float x, int n) {
    const float scaled = std::clamp(x, 0.0f, 1.0f) * float(n - 1);
    const int index = std::min(int(scaled), n - 2);
    return {index, scaled - float(index)};
}

// The slices' bilinear interpolant at p, blended.
template <class T>
T bilerpSlices(const T* values, int nx, int ny, Vec2 p, const SliceBlend& blend) {
    const CellAt x = cellAt(p.x, nx), y = cellAt(p.y, ny);
    const size_t sliceSize = size_t(nx) * size_t(ny);
    T sum{};
    for (int k = 0; k < blend.count; ++k) {
        const T* v = values + blend.slice[k] * sliceSize + size_t(y.index) * nx + x.index;
        const T bottom = v[0] * (1.0f - x.t) + v[1] * x.t;
        const T top = v[nx] * (1.0f - x.t) + v[nx + 1] * x.t;
        sum = sum + (bottom * (1.0f - y.t) + top * y.t) * blend.weight[k];
    }
    return sum;
}

void checkGrid(int nx, int ny, size_t values) {
    if (nx < 2 || ny < 2 || values == 0 || values % (size_t(nx) * size_t(ny)) != 0)
        throw std::invalid_argument("a bilinear table needs at least 2 x 2 samples a slice and whole slices");
}

}  // namespace

SliceAxes::SliceAxes(std::vector<std::vector<float>> axes) : axes_(std::move(axes)) {
    if (axes_.size() > 3) throw std::invalid_argument("at most three parameter axes");
    for (const auto& axis : axes_) {
        if (axis.empty()) throw std::invalid_argument("a parameter axis has no values");
        for (size_t i = 0; i < axis.size(); ++i)
            if (!std::isfinite(axis[i]) || (i > 0 && !(axis[i] > axis[i - 1])))
                throw std::invalid_argument("a parameter axis's values must be finite and ascending");
        slices_ *= axis.size();
    }
}

SliceBlend SliceAxes::blend(std::span<const float> params) const {
    SliceBlend b;
    b.count = 1;
    b.weight[0] = 1;
    size_t stride = slices_;
    for (size_t d = 0; d < axes_.size(); ++d) {
        const auto& axis = axes_[d];
        stride /= axis.size();
        if (axis.size() == 1) continue;
        const float p = d < params.size() ? params[d] : axis.front();
        const size_t upper = size_t(std::upper_bound(axis.begin(), axis.end(), p) - axis.begin());
        const size_t index = std::min(upper == 0 ? 0 : upper - 1, axis.size() - 2);
        const float t = std::clamp((p - axis[index]) / (axis[index + 1] - axis[index]), 0.0f, 1.0f);
        // Each slice chosen so far splits into its two neighbours along this axis.
        for (int k = 0; k < b.count; ++k) {
            b.slice[k + b.count] = b.slice[k] + uint32_t((index + 1) * stride);
            b.weight[k + b.count] = b.weight[k] * t;
            b.slice[k] += uint32_t(index * stride);
            b.weight[k] *= 1.0f - t;
        }
        b.count *= 2;
    }
    return b;
}

SliceBlend singleSlice() {
    SliceBlend b;
    b.count = 1;
    b.weight[0] = 1;
    return b;
}

template <class T>
BilinearTable<T>::BilinearTable(int nx, int ny, std::vector<T> values) : nx_(nx), ny_(ny), values_(std::move(values)) {
    checkGrid(nx, ny, values_.size());
}

template <class T>
T BilinearTable<T>::eval(Vec2 p, const SliceBlend& blend) const {
    return bilerpSlices(values_.data(), nx_, ny_, p, blend);
}

template class BilinearTable<float>;
template class BilinearTable<Color>;

BilinearWarp2D::BilinearWarp2D(int nx, int ny, std::vector<float> values) : nx_(nx), ny_(ny), values_(std::move(values)) {
    checkGrid(nx, ny, values_.size());
    for (float v : values_)
        if (!(v >= 0) || !std::isfinite(v)) throw std::invalid_argument("a density's samples must be finite and >= 0");
    const size_t sliceSize = size_t(nx) * size_t(ny), slices = values_.size() / sliceSize;
    rowCdf_.resize(values_.size());
    marginalCdf_.resize(slices * size_t(ny));
    for (size_t s = 0; s < slices; ++s) {
        float* v = values_.data() + s * sliceSize;
        float* rows = rowCdf_.data() + s * sliceSize;
        float* marginal = marginalCdf_.data() + s * size_t(ny);
        std::vector<double> rowTotal(ny, 0.0);
        auto integrate = [&] {
            double total = 0;
            for (int j = 0; j < ny; ++j) {
                double sum = 0;
                for (int i = 0; i + 1 < nx; ++i) sum += 0.5 * (double(v[j * nx + i]) + v[j * nx + i + 1]);
                rowTotal[j] = sum;
                if (j > 0) total += 0.5 * (rowTotal[j - 1] + rowTotal[j]);
            }
            return total;
        };
        double total = integrate();
        if (!(total > 0)) {
            std::fill(v, v + sliceSize, 1.0f);
            total = integrate();
        }
        const double scale = 1.0 / total;
        double margin = 0;
        for (int j = 0; j < ny; ++j) {
            if (j > 0) margin += 0.5 * (rowTotal[j - 1] + rowTotal[j]);
            marginal[j] = float(margin * scale);
            double sum = 0;
            for (int i = 0; i < nx; ++i) {
                if (i > 0) sum += 0.5 * (double(v[j * nx + i - 1]) + v[j * nx + i]);
                rows[j * nx + i] = float(sum * scale);
            }
        }
        for (size_t k = 0; k < sliceSize; ++k) v[k] = float(v[k] * scale);
    }
}

float BilinearWarp2D::blended(const std::vector<float>& table, size_t sliceSize, size_t index,
                              const SliceBlend& blend) const {
    float sum = 0;
    for (int k = 0; k < blend.count; ++k) sum += table[blend.slice[k] * sliceSize + index] * blend.weight[k];
    return sum;
}

BilinearWarp2D::Warped BilinearWarp2D::sample(Vec2 u, const SliceBlend& blend) const {
    const size_t sliceSize = size_t(nx_) * size_t(ny_);
    auto marginal = [&](int j) { return blended(marginalCdf_, ny_, j, blend); };
    auto row = [&](int j, int i) { return blended(rowCdf_, sliceSize, size_t(j) * nx_ + i, blend); };
    auto value = [&](int j, int i) { return blended(values_, sliceSize, size_t(j) * nx_ + i, blend); };
    // The row: the last one whose running integral is at most u.y, then the point in it.
    const float uy = std::clamp(u.y, 0.0f, 1.0f) * marginal(ny_ - 1);
    int lo = 0, hi = ny_ - 2;
    while (lo < hi) {
        const int mid = (lo + hi + 1) / 2;
        if (marginal(mid) <= uy) lo = mid;
        else hi = mid - 1;
    }
    const int j = lo;
    const float r0 = row(j, nx_ - 1), r1 = row(j + 1, nx_ - 1);
    const float ty = invertLinearIntegral(r0, r1, uy - marginal(j));
    // The column, under the row's integral at that height.
    auto rowAt = [&](int i) { return (1.0f - ty) * row(j, i) + ty * row(j + 1, i); };
    const float ux = std::clamp(u.x, 0.0f, 1.0f) * rowAt(nx_ - 1);
    lo = 0;
    hi = nx_ - 2;
    while (lo < hi) {
        const int mid = (lo + hi + 1) / 2;
        if (rowAt(mid) <= ux) lo = mid;
        else hi = mid - 1;
    }
    const int i = lo;
    const float c0 = (1.0f - ty) * value(j, i) + ty * value(j + 1, i);
    const float c1 = (1.0f - ty) * value(j, i + 1) + ty * value(j + 1, i + 1);
    const float tx = invertLinearIntegral(c0, c1, ux - rowAt(i));
    const float cells = float(nx_ - 1) * float(ny_ - 1);
    return {{(float(i) + tx) / float(nx_ - 1), (float(j) + ty) / float(ny_ - 1)}, ((1.0f - tx) * c0 + tx * c1) * cells};
}

BilinearWarp2D::Warped BilinearWarp2D::invert(Vec2 p, const SliceBlend& blend) const {
    const size_t sliceSize = size_t(nx_) * size_t(ny_);
    auto row = [&](int j, int i) { return blended(rowCdf_, sliceSize, size_t(j) * nx_ + i, blend); };
    auto value = [&](int j, int i) { return blended(values_, sliceSize, size_t(j) * nx_ + i, blend); };
    const CellAt x = cellAt(p.x, nx_), y = cellAt(p.y, ny_);
    const int i = x.index, j = y.index;
    const float c0 = (1.0f - y.t) * value(j, i) + y.t * value(j + 1, i);
    const float c1 = (1.0f - y.t) * value(j, i + 1) + y.t * value(j + 1, i + 1);
    const float r0 = row(j, nx_ - 1), r1 = row(j + 1, nx_ - 1);
    const float rowTotal = (1.0f - y.t) * r0 + y.t * r1;
    const float before = (1.0f - y.t) * row(j, i) + y.t * row(j + 1, i);
    const float inRow = before + x.t * (c0 + 0.5f * x.t * (c1 - c0));
    const float ux = rowTotal > 0 ? std::clamp(inRow / rowTotal, 0.0f, 1.0f) : x.t;
    const float uy = blended(marginalCdf_, ny_, j, blend) + y.t * (r0 + 0.5f * y.t * (r1 - r0));
    const float cells = float(nx_ - 1) * float(ny_ - 1);
    return {{ux, std::clamp(uy / blended(marginalCdf_, ny_, ny_ - 1, blend), 0.0f, 1.0f)},
            ((1.0f - x.t) * c0 + x.t * c1) * cells};
}

float BilinearWarp2D::density(Vec2 p, const SliceBlend& blend) const {
    return bilerpSlices(values_.data(), nx_, ny_, p, blend) * float(nx_ - 1) * float(ny_ - 1);
}

}  // namespace photon
