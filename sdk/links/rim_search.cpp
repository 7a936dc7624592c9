#include "links/rim_search.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/task_system.h"

namespace nl {
namespace {

// Whether the vertical segment from `top` down `reach` crosses the (static, world-space) triangle a
// millimetre inside its edges and ends (more far from the origin, where floats are coarser), so that
// casting it could only report a hit.
bool crosses_well_inside(const std::array<Vec3, 3>& t, const Vec3& top, float reach) {
    const float kInside = 1e-3f + 16.0f * std::numeric_limits<float>::epsilon() * top.cwiseAbs().maxCoeff();
    const Eigen::Vector2f a(t[0].x(), t[0].z()), b(t[1].x(), t[1].z()), c(t[2].x(), t[2].z()), p(top.x(), top.z());
    auto cross = [](const Eigen::Vector2f& u, const Eigen::Vector2f& v) { return u.x() * v.y() - u.y() * v.x(); };
    const float area = cross(b - a, c - a);
    if (std::fabs(area) < 1e-6f) return false;  // (nearly) vertical as seen from above
    const float side = area > 0.0f ? 1.0f : -1.0f;
    const Eigen::Vector2f corners[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) {
        const Eigen::Vector2f& from = corners[i];
        const Eigen::Vector2f& to = corners[(i + 1) % 3];
        const float length = (to - from).norm();
        if (side * cross(to - from, p - from) < kInside * length) return false;
    }
    const float u = cross(p - a, c - a) / area, v = cross(b - a, p - a) / area;
    const float y = t[0].y() + u * (t[1].y() - t[0].y()) + v * (t[2].y() - t[0].y());
    return y <= top.y() - kInside && y >= top.y() - reach + kInside;
}

Vec3 probe_top(const RimQuery& q, float distance, const RimProbing& probing) {
    const Vec3 out = q.from + q.heading * distance;
    return Vec3(out.x(), q.ground_y + probing.lift, out.z());
}

Segment probe_at(const RimQuery& q, float distance, const RimProbing& probing) {
    const Vec3 top = probe_top(q, distance, probing);
    return Segment{top, top - Vec3(0, probing.step_reach, 0)};
}

uint32_t step_count(const RimQuery& q) { return static_cast<uint32_t>(std::ceil(q.reach / RimSearch::kStep)); }

}  // namespace

std::vector<float> find_rims(const Level& level, TaskSystem& tasks, std::vector<RimQuery> queries,
                             const RimProbing& probing, uint64_t& rays_cast) {
    const size_t count = queries.size();
    std::vector<float> ground(count, 0.0f), air(count, -1.0f);  // distances out known on ground and off it
    auto distance_of = [&](size_t k, uint32_t step) {
        return std::min(static_cast<float>(step) * RimSearch::kStep, queries[k].reach);
    };

    // One step out at a time, for the queries still on ground: only a hit or a miss is needed, and a
    // query stops at its rim or its reach.
    std::vector<size_t> looking(count);
    for (size_t k = 0; k < count; ++k) looking[k] = k;
    for (uint32_t j = 1; !looking.empty(); ++j) {
        looking.erase(
            std::remove_if(looking.begin(), looking.end(), [&](size_t k) { return j > step_count(queries[k]); }),
            looking.end());
        std::vector<uint8_t> on_ground(looking.size(), 1), proven(looking.size(), 0);
        if (probing.floor_shortcut)
            tasks.parallel_for(static_cast<uint32_t>(looking.size()), 512, [&](uint32_t begin, uint32_t end) {
                for (uint32_t n = begin; n < end; ++n) {
                    const RimQuery& q = queries[looking[n]];
                    proven[n] =
                        q.floor && crosses_well_inside(*q.floor, probe_top(q, distance_of(looking[n], j), probing),
                                                       probing.step_reach);
                }
            });
        std::vector<Segment> below;
        std::vector<size_t> cast_for;  // positions in `looking` of the probes cast
        for (size_t n = 0; n < looking.size(); ++n) {
            if (proven[n]) continue;
            below.push_back(probe_at(queries[looking[n]], distance_of(looking[n], j), probing));
            cast_for.push_back(n);
        }
        rays_cast += below.size();
        if (probing.floor_shortcut) {
            // Cast for the triangle too: the next step out may cross it.
            std::vector<RayHit> hits(below.size());
            level.segments_first_hit(below.data(), static_cast<uint32_t>(below.size()), hits.data());
            std::vector<std::optional<std::array<Vec3, 3>>> found(hits.size());
            level.static_triangles(hits.data(), static_cast<uint32_t>(hits.size()), found.data());
            for (size_t c = 0; c < cast_for.size(); ++c) {
                on_ground[cast_for[c]] = hits[c].hit;
                if (hits[c].hit) queries[looking[cast_for[c]]].floor = found[c];
            }
        } else {
            std::vector<uint8_t> blocked(below.size());
            level.segments_blocked(below.data(), static_cast<uint32_t>(below.size()), blocked.data());
            for (size_t c = 0; c < cast_for.size(); ++c) on_ground[cast_for[c]] = blocked[c];
        }
        size_t still = 0;
        for (size_t n = 0; n < looking.size(); ++n) {
            const size_t k = looking[n];
            if (on_ground[n]) {
                looking[still++] = k;
            } else {
                air[k] = distance_of(k, j);
                ground[k] = static_cast<float>(j - 1) * RimSearch::kStep;
            }
        }
        looking.resize(still);
    }

    // The rim lies between the last step out on ground and the first without: halve that step a few
    // times, every query in one batch per halving.
    std::vector<size_t> found;
    for (size_t k = 0; k < count; ++k)
        if (air[k] >= 0.0f) found.push_back(k);
    std::vector<Segment> below(found.size());
    std::vector<uint8_t> hit(found.size());
    for (int halving = 0; halving < RimSearch::kHalvings; ++halving) {
        for (size_t n = 0; n < found.size(); ++n)
            below[n] = probe_at(queries[found[n]], 0.5f * (ground[found[n]] + air[found[n]]), probing);
        level.segments_blocked(below.data(), static_cast<uint32_t>(below.size()), hit.data());
        rays_cast += below.size();
        for (size_t n = 0; n < found.size(); ++n) {
            const size_t k = found[n];
            (hit[n] ? ground[k] : air[k]) = 0.5f * (ground[k] + air[k]);
        }
    }
    return air;
}

Aabb rim_search_bounds(const RimQuery& query, const RimProbing& probing) {
    Aabb box;
    for (const float distance : {0.0f, query.reach}) {
        const Segment probe = probe_at(query, distance, probing);
        box.grow(probe.from);
        box.grow(probe.to);
    }
    return box;
}

}  // namespace nl
