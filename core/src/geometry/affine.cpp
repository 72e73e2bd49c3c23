#include "geometry/affine.hpp"

#include <glm/matrix.hpp>

#include <cmath>
#include <numbers>

namespace jt {

namespace {

bool all_finite(const glm::dmat3& m) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

bool all_finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Exact zeros for the multiples of 90 degrees, so that a quarter turn maps axes
// onto axes without a 6e-17 residue.
void sin_cos_degrees(double degrees, double& s, double& c) {
    double turns = std::fmod(degrees, 360.0);
    if (turns < 0) turns += 360.0;
    if (turns == 0.0) {
        s = 0.0;
        c = 1.0;
        return;
    }
    if (turns == 90.0) {
        s = 1.0;
        c = 0.0;
        return;
    }
    if (turns == 180.0) {
        s = 0.0;
        c = -1.0;
        return;
    }
    if (turns == 270.0) {
        s = -1.0;
        c = 0.0;
        return;
    }
    double radians = degrees * std::numbers::pi / 180.0;
    s = std::sin(radians);
    c = std::cos(radians);
}

}  // namespace

Affine affine_of(const TransformOp& op) {
    Affine a;
    double s = 0.0, c = 1.0;
    // glm matrices are column-major: m[column][row].
    switch (op.kind) {
        case TransformKind::translate:
            a.translation = op.vector;
            break;
        case TransformKind::scale:
            a.linear = glm::dmat3(op.vector.x, 0, 0, 0, op.vector.y, 0, 0, 0, op.vector.z);
            break;
        case TransformKind::xrotate:
            sin_cos_degrees(op.degrees, s, c);
            a.linear = glm::dmat3(1, 0, 0, 0, c, s, 0, -s, c);
            break;
        case TransformKind::yrotate:
            sin_cos_degrees(op.degrees, s, c);
            a.linear = glm::dmat3(c, 0, -s, 0, 1, 0, s, 0, c);
            break;
        case TransformKind::zrotate:
            sin_cos_degrees(op.degrees, s, c);
            a.linear = glm::dmat3(c, s, 0, -s, c, 0, 0, 0, 1);
            break;
    }
    return a;
}

Affine then(const Affine& a, const Affine& b) {
    return Affine{b.linear * a.linear, b.linear * a.translation + b.translation};
}

Affine compose_transforms(const std::vector<TransformOp>& ops) {
    Affine m;
    for (const TransformOp& op : ops) m = then(m, affine_of(op));
    return m;
}

std::optional<AffineInverse> invert(const Affine& a) {
    if (!all_finite(a.linear) || !all_finite(a.translation)) return std::nullopt;
    double det = glm::determinant(a.linear);
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return std::nullopt;
    glm::dmat3 inv = glm::inverse(a.linear);
    if (!all_finite(inv)) return std::nullopt;
    AffineInverse result;
    result.inverse.linear = inv;
    result.inverse.translation = -(inv * a.translation);
    result.normal_matrix = glm::transpose(inv);
    if (!all_finite(result.inverse.translation)) return std::nullopt;
    return result;
}

std::optional<double> similarity_scale(const glm::dmat3& linear) {
    glm::dmat3 gram = glm::transpose(linear) * linear;
    double s2 = (gram[0][0] + gram[1][1] + gram[2][2]) / 3.0;
    if (!(s2 > 0.0) || !std::isfinite(s2)) return std::nullopt;
    const double tolerance = 1e-12 * s2;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (std::abs(gram[c][r] - (c == r ? s2 : 0.0)) > tolerance) return std::nullopt;
    return std::sqrt(s2);
}

}  // namespace jt
