#include "navmesh/carrier_pose.h"

namespace nl {

bool is_rigid(const Transform& t) {
    const Eigen::Matrix3f r = t.linear();
    if (!r.allFinite() || !t.translation().allFinite()) return false;
    return (r.transpose() * r - Eigen::Matrix3f::Identity()).cwiseAbs().maxCoeff() <= 1e-4f && r.determinant() > 0.0f;
}

CarrierPose::CarrierPose(const Transform& to_world) : to_world_(to_world) {
    identity_ = to_world.matrix() == Eigen::Matrix4f::Identity();
    // The exact inverse of a rotation is its transpose; Eigen's general inverse would round differently.
    to_carrier_.linear() = to_world.linear().transpose();
    to_carrier_.translation() = -(to_carrier_.linear() * to_world.translation());
}

Aabb CarrierPose::world_box(const Aabb& b) const { return identity_ ? b : transformed_box(b, to_world_); }

}  // namespace nl
