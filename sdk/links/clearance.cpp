#include "links/clearance.h"

#include <algorithm>
#include <cmath>

namespace nl {

JumpArc jump_arc(const Vec3& start, const Vec3& end, float apex_above, unsigned pieces) {
    // y(t) = start.y + b t + c t^2 over the horizontal fraction t, through end at t = 1, topping out at
    // h above start.y: c solves c^2 + (4h - 2dy) c + dy^2 = 0 on its negative root.
    const double dy = double(end.y()) - start.y();
    const double h = std::max(double(start.y()), double(end.y())) + apex_above - start.y();
    const double c = -(2.0 * h - dy) - 2.0 * std::sqrt(std::max(0.0, h * (h - dy)));
    const double b = dy - c;
    const double t_apex = c < 0.0 ? std::clamp(-b / (2.0 * c), 0.0, 1.0) : 0.5;
    auto at = [&](double t) {
        const Vec3 flat = start + static_cast<float>(t) * (end - start);
        return Vec3(flat.x(), static_cast<float>(start.y() + b * t + c * t * t), flat.z());
    };
    JumpArc arc;
    for (unsigned i = 0; i <= pieces; ++i) arc.points.push_back(at(double(i) / pieces));
    arc.apex = at(t_apex);
    return arc;
}

void append_body_sweep(const std::vector<Vec3>& path, const Body& body, float margin, std::vector<Segment>& out) {
    float total = 0.0f;
    for (size_t i = 1; i < path.size(); ++i) total += (path[i] - path[i - 1]).norm();
    if (total <= 0.0f) return;
    const float keep_from = margin * total, keep_to = (1.0f - margin) * total;
    // One sideways direction for the whole path: its horizontal heading.
    Vec3 heading = path.back() - path.front();
    heading.y() = 0.0f;
    const Vec3 side = heading.norm() > 1e-4f ? Vec3(-heading.z(), 0.0f, heading.x()).normalized() : Vec3::UnitX();
    const float heights[kSweepHeights] = {std::min(0.3f, 0.25f * body.height), 0.5f * body.height,
                                          std::max(0.5f * body.height, body.height - 0.1f)};

    float walked = 0.0f;
    for (size_t i = 1; i < path.size(); ++i) {
        const Vec3 a = path[i - 1], b = path[i];
        const float length = (b - a).norm();
        const float from = std::max(walked, keep_from), to = std::min(walked + length, keep_to);
        walked += length;
        if (to <= from || length <= 0.0f) continue;
        const Vec3 p = a + (b - a) * ((from - (walked - length)) / length);
        const Vec3 q = a + (b - a) * ((to - (walked - length)) / length);
        for (float y : heights) {
            for (float x : kSweepOffsets) {
                const Vec3 offset = side * (x * body.radius) + Vec3(0.0f, y, 0.0f);
                out.push_back(Segment{p + offset, q + offset});
                out.push_back(Segment{q + offset, p + offset});
            }
        }
    }
}

}  // namespace nl
