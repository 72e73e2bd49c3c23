#include "jtracer/smooth_normals.hpp"

#include "jtracer/limits.hpp"
#include "jtracer/value_text.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <mutex>
#include <numbers>
#include <string>
#include <utility>

namespace jt {

namespace {

bool has_normal(const Model& model, std::uint32_t vertex) {
    return !model.normals.empty() && model.normals[vertex] != glm::vec3(0.0f);
}

// One corner of one triangle: where it lies, and 3 * triangle + corner.
struct CornerAt {
    glm::vec3 position;
    std::uint32_t corner;
};

// By position, then in file order. Floats compare as numbers, so -0 and 0 sort
// as one position, as the language says corners match (docs/language.md §14.4).
bool before(const CornerAt& a, const CornerAt& b) {
    if (a.position.x != b.position.x) return a.position.x < b.position.x;
    if (a.position.y != b.position.y) return a.position.y < b.position.y;
    if (a.position.z != b.position.z) return a.position.z < b.position.z;
    return a.corner < b.corner;
}

}  // namespace

std::size_t corners_without_normals(const Model& model) {
    std::size_t count = 0;
    for (const auto& triangle : model.triangles)
        for (const std::uint32_t vertex : triangle)
            if (!has_normal(model, vertex)) ++count;
    return count;
}

std::size_t smooth_normal_comparisons(const Model& model) {
    return kSmoothNormalComparisons +
           kSmoothNormalComparisonsPerCorner * 3 * model.triangles.size();
}

Expected<CornerNormals> smooth_corner_normals(const Model& model, double degrees) {
    const std::size_t count = model.triangles.size();
    // The language's order: cos(A * pi / 180) - 1e-12, in double precision.
    const double threshold = std::cos(degrees * std::numbers::pi / 180.0) - 1e-12;
    std::vector<Vec3> area(count), unit(count);  // cross(b - a, c - a) and its direction
    CornerNormals normals(count);
    std::vector<CornerAt> corners;
    corners.reserve(3 * count);
    for (std::size_t t = 0; t < count; ++t) {
        const auto& triangle = model.triangles[t];
        const Vec3 a(model.positions[triangle[0]]), b(model.positions[triangle[1]]),
            c(model.positions[triangle[2]]);
        area[t] = glm::cross(b - a, c - a);
        unit[t] = glm::normalize(area[t]);
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t vertex = triangle[k];
            if (has_normal(model, vertex)) normals[t][k] = Vec3(model.normals[vertex]);
            corners.push_back({model.positions[vertex], static_cast<std::uint32_t>(3 * t + k)});
        }
    }
    std::sort(corners.begin(), corners.end(), before);

    const std::size_t allowed = smooth_normal_comparisons(model);
    std::size_t compared = 0;
    // The sums made at one position, by the direction of the triangle they are
    // for: the sum depends on nothing else, and flat regions repeat directions.
    std::vector<std::pair<Vec3, Vec3>> made;
    for (std::size_t first = 0, end = 0; first < corners.size(); first = end) {
        end = first + 1;
        while (end < corners.size() && corners[end].position == corners[first].position) ++end;
        made.clear();
        for (std::size_t i = first; i < end; ++i) {
            const std::uint32_t t = corners[i].corner / 3, k = corners[i].corner % 3;
            if (has_normal(model, model.triangles[t][k])) continue;
            const auto known = std::find_if(made.begin(), made.end(),
                                            [&](const auto& m) { return m.first == unit[t]; });
            if (known != made.end()) {
                normals[t][k] = known->second;
                continue;
            }
            compared += end - first;
            if (compared > allowed) {
                return Error{"smooth_angle would compare more than " + std::to_string(allowed) +
                             " pairs of its triangles: " + std::to_string(end - first) +
                             " triangles meet at " + vector_text(Vec3(corners[first].position)) +
                             ", facing " + std::to_string(made.size() + 1) + " or more directions"};
            }
            // In file order: the corners of one position are sorted by triangle.
            Vec3 sum(0.0);
            for (std::size_t j = first; j < end; ++j) {
                const std::uint32_t other = corners[j].corner / 3;
                if (other == t || glm::dot(unit[t], unit[other]) >= threshold) sum += area[other];
            }
            const Vec3 n = sum == Vec3(0.0) ? unit[t] : glm::normalize(sum);
            made.emplace_back(unit[t], n);
            normals[t][k] = n;
        }
    }
    return normals;
}

Expected<std::shared_ptr<const CornerNormals>> shared_corner_normals(
    const std::shared_ptr<const Model>& model, double degrees) {
    using Result = Expected<std::shared_ptr<const CornerNormals>>;
    // A handful: a scene's few smooth meshes between validation and render.
    // Each entry holds its model, so the address cannot name another one.
    struct Entry {
        std::shared_ptr<const Model> model;
        double degrees;
        Result result;
    };
    constexpr std::size_t kept = 4;
    static std::mutex mutex;
    static std::deque<Entry> recent;
    {
        const std::lock_guard<std::mutex> lock(mutex);
        for (const Entry& e : recent)
            if (e.model == model && e.degrees == degrees) return e.result;
    }
    // Made outside the lock: another model's render need not wait for this one.
    Expected<CornerNormals> made = smooth_corner_normals(*model, degrees);
    Result result = made ? Result(std::make_shared<const CornerNormals>(std::move(*made)))
                         : Result(made.error());
    const std::lock_guard<std::mutex> lock(mutex);
    recent.push_front({model, degrees, result});
    if (recent.size() > kept) recent.pop_back();
    return result;
}

}  // namespace jt
