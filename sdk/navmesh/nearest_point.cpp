#include "navmesh/nearest_point.h"

#include <algorithm>
#include <cmath>

namespace nl {

void NearestPoint::consider(uint32_t p) {
    // Outside its bounds a point is never over a polygon, and ranks by distance.
    const bool over_box = navmesh_.over_bounds(p, point_.x(), point_.z());
    // A polygon's rank is at least its box's distance (less a climb when the point is over the box,
    // where it may be over the polygon), less the float rounding of a closest point at these
    // coordinates: nothing beyond the best rank can beat it, nor anything at it but a lower index.
    if (best_.found && skip_by_bounds_) {
        const Aabb& box = navmesh_.polygon_bounds(p);
        const float box_distance = (point_.cwiseMax(box.min).cwiseMin(box.max) - point_).norm();
        const float rounding = 1e-6f * (point_scale_ + box.max.cwiseAbs().cwiseMax(box.min.cwiseAbs()).maxCoeff());
        const float least_rank =
            std::max(0.0f, box_distance - rounding - (over_box ? navmesh_.agent().max_climb : 0.0f));
        if (least_rank > best_rank_ || (least_rank == best_rank_ && p > best_.polygon)) return;
    }
    const Vec3 q = navmesh_.closest_point_on_polygon(p, point_);
    const float d = (q - point_).norm();
    const bool over = over_box && q.x() == point_.x() && q.z() == point_.z();
    const float rank = over ? std::max(0.0f, std::fabs(q.y() - point_.y()) - navmesh_.agent().max_climb) : d;
    if (!best_.found || rank < best_rank_ || (rank == best_rank_ && p < best_.polygon)) {
        best_ = NavPoint{true, q, d, p};
        best_rank_ = rank;
    }
}

}  // namespace nl
