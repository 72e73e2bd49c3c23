#include "polygon.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdlib>
#include <numeric>
#include <optional>

namespace jt {

namespace {

using Triangle = std::array<std::uint32_t, 3>;

struct Point {
    double x = 0.0, y = 0.0;
    bool operator==(const Point&) const = default;
};

// Twice the signed area of (o, a, b): positive when it turns left.
double turn(const Point& o, const Point& a, const Point& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

void fan(std::span<const std::uint32_t> ring, std::vector<Triangle>& out) {
    for (std::size_t k = 2; k < ring.size(); ++k) out.push_back({ring[0], ring[k - 1], ring[k]});
}

// The polygon in the plane it lies in (Newell's normal: right for a polygon
// that is not quite flat, as a 3D tool's n-gon often is), seen from the side
// its winding is counter-clockwise from; empty when it has no area.
std::vector<Point> flattened(std::span<const glm::dvec3> corners) {
    glm::dvec3 normal(0.0);
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const glm::dvec3& a = corners[i];
        const glm::dvec3& b = corners[(i + 1) % corners.size()];
        normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x),
                             (a.x - b.x) * (a.y + b.y));
    }
    // Dropping the normal's largest axis keeps the polygon's shape and, with
    // the sign below, its winding.
    const glm::dvec3 size = glm::abs(normal);
    const int drop = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    if (!(size[drop] > 0.0) || !std::isfinite(size[drop])) return {};
    const int u = (drop + 1) % 3, v = (drop + 2) % 3;
    const double mirror = normal[drop] > 0.0 ? 1.0 : -1.0;
    std::vector<Point> points;
    points.reserve(corners.size());
    for (const glm::dvec3& c : corners) points.push_back({c[u], c[v] * mirror});
    return points;
}

// Whether no corner turns right, by more than rounding: a fan covers it.
bool convex(const std::vector<Point>& p) {
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Point& a = p[(i + n - 1) % n];
        const Point& b = p[i];
        const Point& c = p[(i + 1) % n];
        const double scale = std::hypot(b.x - a.x, b.y - a.y) * std::hypot(c.x - b.x, c.y - b.y);
        if (turn(a, b, c) < -1e-12 * scale) return false;
    }
    return true;
}

bool inside_or_on(const Point& a, const Point& b, const Point& c, const Point& p) {
    return turn(a, b, p) >= 0.0 && turn(b, c, p) >= 0.0 && turn(c, a, p) >= 0.0;
}

bool strictly_inside(const Point& a, const Point& b, const Point& c, const Point& p) {
    return turn(a, b, p) > 0.0 && turn(b, c, p) > 0.0 && turn(c, a, p) > 0.0;
}

class EarClipper {
  public:
    EarClipper(const std::vector<Point>& points, std::uint64_t& budget)
        : p_(points), budget_(budget), ring_(points.size()) {
        std::iota(ring_.begin(), ring_.end(), 0u);
    }

    std::vector<Triangle> run() {
        std::vector<Triangle> out;
        std::size_t at = 0;
        while (ring_.size() > 3) {
            // A polygon that touches itself (a ring joined to its hole by a
            // seam walked both ways) may have no ear by the strict test
            // while it has one by the loose one.
            std::optional<std::size_t> ear = find_ear(at, false);
            if (!ear) ear = find_ear(at, true);
            if (!ear) break;
            const std::size_t m = ring_.size();
            out.push_back({ring_[(*ear + m - 1) % m], ring_[*ear], ring_[(*ear + 1) % m]});
            ring_.erase(ring_.begin() + static_cast<std::ptrdiff_t>(*ear));
            at = *ear < ring_.size() ? *ear : 0;
        }
        fan(ring_, out);  // the last triangle, or what has no ear
        return out;
    }

  private:
    std::optional<std::size_t> find_ear(std::size_t from, bool loose) {
        const std::size_t m = ring_.size();
        for (std::size_t k = 0; k < m; ++k) {
            const std::size_t i = (from + k) % m;
            if (is_ear(i, loose)) return i;
            if (budget_ == 0) return std::nullopt;
        }
        return std::nullopt;
    }

    bool is_ear(std::size_t i, bool loose) {
        const std::size_t m = ring_.size();
        const Point& a = p_[ring_[(i + m - 1) % m]];
        const Point& b = p_[ring_[i]];
        const Point& c = p_[ring_[(i + 1) % m]];
        if (turn(a, b, c) <= 0.0) return false;  // a right turn, or no area
        budget_ = budget_ > m ? budget_ - m : 0;
        for (std::size_t k = 0; k < m; ++k) {
            const Point& q = p_[ring_[k]];
            // The ear's own corners, and corners at the same place (a seam).
            if (q == a || q == b || q == c) continue;
            if (loose ? strictly_inside(a, b, c, q) : inside_or_on(a, b, c, q)) return false;
        }
        return true;
    }

    const std::vector<Point>& p_;
    std::uint64_t& budget_;
    std::vector<std::uint32_t> ring_;
};

}  // namespace

std::vector<Triangle> triangulate_polygon(std::span<const glm::dvec3> corners,
                                          std::uint64_t& budget) {
    std::vector<std::uint32_t> ring(corners.size());
    std::iota(ring.begin(), ring.end(), 0u);
    std::vector<Triangle> out;
    if (corners.size() <= 3 || corners.size() > kMaxEarClippedCorners || budget == 0) {
        fan(ring, out);
        return out;
    }
    const std::vector<Point> points = flattened(corners);
    if (points.empty() || convex(points)) {
        fan(ring, out);
        return out;
    }
    return EarClipper(points, budget).run();
}

}  // namespace jt
