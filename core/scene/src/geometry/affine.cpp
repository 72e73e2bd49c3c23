#include "jtracer/affine.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
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

bool flattens(const TransformOp& op) {
    return op.kind == TransformKind::scale &&
           (op.vector.x == 0.0 || op.vector.y == 0.0 || op.vector.z == 0.0);
}

namespace {

// The map undoing `op`, exact up to one rounding an entry.
Affine inverse_of(const TransformOp& op) {
    Affine a;
    switch (op.kind) {
        case TransformKind::translate:
            a.translation = -op.vector;
            break;
        case TransformKind::scale:
            a.linear = glm::dmat3(1.0 / op.vector.x, 0, 0, 0, 1.0 / op.vector.y, 0, 0, 0,
                                  1.0 / op.vector.z);
            break;
        case TransformKind::xrotate:
        case TransformKind::yrotate:
        case TransformKind::zrotate:
            a.linear = glm::transpose(affine_of(op).linear);
            break;
    }
    return a;
}

bool all_finite(const Affine& a) {
    return all_finite(a.linear) && jt::all_finite(a.translation);
}

}  // namespace

std::variant<ObjectTransform, LeftOut> object_transform(const std::vector<TransformOp>& ops) {
    for (std::size_t k = 0; k < ops.size(); ++k)
        if (flattens(ops[k])) return LeftOut{LeftOut::Reason::zero_scale, k};
    ObjectTransform m;
    for (std::size_t k = 0; k < ops.size(); ++k) {
        m.to_world = then(m.to_world, affine_of(ops[k]));
        m.to_object = then(inverse_of(ops[k]), m.to_object);
        if (!all_finite(m.to_world) || !all_finite(m.to_object))
            return LeftOut{LeftOut::Reason::out_of_range, k};
        if (ops[k].kind == TransformKind::scale)
            for (int axis = 0; axis < 3; ++axis)
                if (ops[k].vector[axis] < 0.0) m.mirrors = !m.mirrors;
    }
    m.normal_matrix = glm::transpose(m.to_object.linear);
    return m;
}

std::optional<Vec3> unit_length(const Vec3& v) {
    if (!all_finite(v)) return std::nullopt;
    // In this range no square of a component leaves the normal doubles by
    // more than the rounding of the sum can show.
    double length = glm::length(v);
    if (length > 1e-150 && length < 1e150) return v / length;
    double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (!(largest > 0.0)) return std::nullopt;
    // Scaling by a power of two is exact: the largest component becomes 1..2.
    const int exponent = std::ilogb(largest);
    Vec3 w(std::scalbn(v.x, -exponent), std::scalbn(v.y, -exponent), std::scalbn(v.z, -exponent));
    return w / glm::length(w);
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
