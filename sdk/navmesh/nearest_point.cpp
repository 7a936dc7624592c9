#include "navmesh/nearest_point.h"

#include <algorithm>
#include <cmath>

namespace nl {

void NearestPoint::consider(uint32_t p) {
    // A polygon's rank is at least its box's distance (less a climb when the point is over the box,
    // where it may be over the polygon): nothing beyond the best rank can beat it, nor anything at it
    // but a lower index. "Over" within float rounding: over_polygon's float test can take a point a
    // hair outside the box for over the polygon.
    if (best_.found && skip_by_bounds_) {
        const Aabb& box = mesh_.polygon_bounds(p);
        const float box_distance = (point_.cwiseMax(box.min).cwiseMin(box.max) - point_).norm();
        const float slack = 1e-5f * (1.0f + std::max(std::fabs(point_.x()), std::fabs(point_.z())));
        const bool over_box = point_.x() >= box.min.x() - slack && point_.x() <= box.max.x() + slack &&
                              point_.z() >= box.min.z() - slack && point_.z() <= box.max.z() + slack;
        const float least_rank = over_box ? std::max(0.0f, box_distance - mesh_.agent().max_climb) : box_distance;
        if (least_rank > best_rank_ || (least_rank == best_rank_ && p > best_.polygon)) return;
    }
    const Vec3 q = mesh_.closest_point_on_polygon(p, point_);
    const float d = (q - point_).norm();
    const bool over = q.x() == point_.x() && q.z() == point_.z();
    const float rank = over ? std::max(0.0f, std::fabs(q.y() - point_.y()) - mesh_.agent().max_climb) : d;
    if (!best_.found || rank < best_rank_ || (rank == best_rank_ && p < best_.polygon)) {
        best_ = NavPoint{true, q, d, p};
        best_rank_ = rank;
    }
}

}  // namespace nl
