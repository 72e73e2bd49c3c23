#include "render/shape_groups.hpp"

#include "render/listed_shapes.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <span>

namespace jt {

namespace {

double max_abs(const Vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// Splits `order` (lanes by index) into runs of at most sphere_batch that lie
// near each other: halves along the axis where the centres spread most, the
// first half a whole number of groups, so that few groups are part full.
void split(std::span<std::uint32_t> order, const std::vector<WorldSphere>& lanes,
           std::vector<std::span<std::uint32_t>>& runs) {
    if (order.size() <= sphere_batch) {
        runs.push_back(order);
        return;
    }
    Vec3 lower(lanes[order[0]].center), upper(lower);
    for (const std::uint32_t k : order) {
        lower = glm::min(lower, lanes[k].center);
        upper = glm::max(upper, lanes[k].center);
    }
    const Vec3 spread = upper - lower;
    const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0
                     : spread.y >= spread.z                       ? 1
                                                                  : 2;
    // Ties by index: the same groups on every run.
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        const double ca = lanes[a].center[axis], cb = lanes[b].center[axis];
        return ca < cb || (ca == cb && a < b);
    });
    const std::size_t groups = (order.size() + sphere_batch - 1) / sphere_batch;
    const std::size_t first = (groups + 1) / 2 * sphere_batch;
    split(order.first(first), lanes, runs);
    split(order.subspan(first), lanes, runs);
}

void set_lane(SphereLanes& lanes, std::size_t k, const WorldSphere& s) {
    lanes.x[k] = s.center.x;
    lanes.y[k] = s.center.y;
    lanes.z[k] = s.center.z;
    lanes.r[k] = s.radius;
}

}  // namespace

ShapeGroups group_shapes(const std::vector<WorldSphere>& spheres,
                         const std::vector<TransformedShape>& shapes) {
    ShapeGroups out;
    const std::size_t total = spheres.size() + shapes.size();
    if (total == 0 || total > max_grouped_shapes) return out;
    // Every sphere as itself, every shape as its bounding sphere.
    std::vector<WorldSphere> all;
    std::vector<std::uint32_t> listed;
    all.reserve(total);
    for (std::uint32_t i = 0; i < spheres.size(); ++i) {
        all.push_back(spheres[i]);
        listed.push_back(i);
    }
    for (std::uint32_t i = 0; i < shapes.size(); ++i) {
        all.push_back({shapes[i].bounding_center, std::sqrt(shapes[i].bounding_radius_sq), 0});
        listed.push_back(i | shape_flag);
    }
    double magnitude = 0.0;
    for (const WorldSphere& s : all) {
        const double reach = max_abs(s.center) + s.radius;
        if (!std::isfinite(reach) || !(s.radius >= 0.0)) return out;
        magnitude = std::max(magnitude, reach);
    }
    if (!(magnitude > 0.0) || !std::isfinite(group_reach * magnitude)) return out;
    const double pad = group_pad * magnitude;

    std::vector<std::uint32_t> order(total);
    std::iota(order.begin(), order.end(), 0u);
    std::vector<std::span<std::uint32_t>> runs;
    split(order, all, runs);

    const std::size_t count = runs.size();
    out.members.resize(count);
    out.bounds.resize((count + sphere_batch - 1) / sphere_batch);
    for (std::size_t g = 0; g < count; ++g) {
        const std::span<std::uint32_t> run = runs[g];
        Vec3 lower(all[run[0]].center), upper(lower);
        for (const std::uint32_t k : run) {
            lower = glm::min(lower, all[k].center - all[k].radius);
            upper = glm::max(upper, all[k].center + all[k].radius);
        }
        const Vec3 centre = 0.5 * (lower + upper);
        double radius = 0.0;
        std::uint8_t used = 0, sphere_lanes = 0;
        SphereLanes& lanes = out.members[g];
        for (std::size_t j = 0; j < sphere_batch; ++j) {
            const std::uint32_t k = run[j < run.size() ? j : 0];
            set_lane(lanes, j, all[k]);
            out.listed.push_back(listed[k]);
            if (j >= run.size()) continue;
            used |= static_cast<std::uint8_t>(1u << j);
            if (!(listed[k] & shape_flag)) sphere_lanes |= static_cast<std::uint8_t>(1u << j);
            radius = std::max(radius, glm::length(all[k].center - centre) + all[k].radius);
        }
        out.used.push_back(used);
        out.spheres.push_back(sphere_lanes);
        // Rounded up well past the rounding of the sums above.
        set_lane(out.bounds[g / sphere_batch], g % sphere_batch,
                 {centre, radius * (1.0 + 1e-9) + pad, 0});
    }
    for (std::size_t g = count; g % sphere_batch != 0; ++g) {
        SphereLanes& last = out.bounds.back();
        const std::size_t from = (count - 1) % sphere_batch;
        set_lane(last, g % sphere_batch,
                 {Vec3(last.x[from], last.y[from], last.z[from]), last.r[from], 0});
    }
    out.reach = group_reach * magnitude;
    return out;
}

}  // namespace jt
