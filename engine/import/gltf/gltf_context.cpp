#include "import/gltf/gltf_context.h"
#include <cmath>
#include <photon/errors.h>

namespace photon::gltf {

Matrix4 Matrix4::identity() {
    Matrix4 r;
    for (int i = 0; i < 4; ++i) r.m[i][i] = 1;
    return r;
}

Matrix4 Matrix4::ofNode(const tinygltf::Node& node) {
    Matrix4 r = identity();
    if (node.matrix.size() == 16) {
        for (int row = 0; row < 4; ++row)
            for (int column = 0; column < 4; ++column) r.m[row][column] = node.matrix[column * 4 + row];
        return r;
    }
    // T * R * S: the rotation is a unit quaternion (x, y, z, w).
    double x = 0, y = 0, z = 0, w = 1;
    if (node.rotation.size() == 4) {
        x = node.rotation[0], y = node.rotation[1], z = node.rotation[2], w = node.rotation[3];
        const double n = std::sqrt(x * x + y * y + z * z + w * w);
        if (n > 0) x /= n, y /= n, z /= n, w /= n;
    }
    const double rotation[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                                   {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                                   {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    const double scale[3] = {node.scale.size() == 3 ? node.scale[0] : 1, node.scale.size() == 3 ? node.scale[1] : 1,
                             node.scale.size() == 3 ? node.scale[2] : 1};
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 3; ++column) r.m[row][column] = rotation[row][column] * scale[column];
        if (node.translation.size() == 3) r.m[row][3] = node.translation[row];
    }
    return r;
}

Matrix4 Matrix4::operator*(const Matrix4& b) const {
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) r.m[i][j] += m[i][k] * b.m[k][j];
    return r;
}

std::array<double, 3> Matrix4::point(double x, double y, double z) const {
    auto d = direction(x, y, z);
    return {d[0] + m[0][3], d[1] + m[1][3], d[2] + m[2][3]};
}

std::array<double, 3> Matrix4::direction(double x, double y, double z) const {
    return {m[0][0] * x + m[0][1] * y + m[0][2] * z, m[1][0] * x + m[1][1] * y + m[1][2] * z,
            m[2][0] * x + m[2][1] * y + m[2][2] * z};
}

double Matrix4::determinant3() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

Json Matrix4::rowMajor() const {
    Json a = Json::array();
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column) a.push_back(row == 3 ? (column == 3 ? 1.0 : 0.0) : m[row][column]);
    return a;
}

void Context::fail(const std::string& pointer, const std::string& message) const {
    throw SceneError(pointer.empty() ? fileName : fileName + ": " + pointer, message);
}

void Context::warn(const std::string& pointer, const std::string& message) {
    out.warnings.push_back(fileName + ": " + (pointer.empty() ? "" : pointer + ": ") + message);
}

double numberIn(const tinygltf::Value& object, const char* key, double fallback) {
    if (!object.IsObject() || !object.Has(key)) return fallback;
    const tinygltf::Value& v = object.Get(key);
    return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

}  // namespace photon::gltf
