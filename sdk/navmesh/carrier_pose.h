// Where a navmesh that rides a movable mesh is now. Its polygons, links and the agents on it are kept
// in the mesh's own space (the carrier space); a pose carries points between that space and the
// world at one moment, so moving the mesh changes one transform and no snapshot.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>

#include "level/geometry.h"
#include "util/handle.h"

namespace nl {

// Whether `t` is a rotation and a translation: no scale, shear or mirror (within 1e-4 per matrix
// entry), so lengths, radii and clearances mean the same in carrier space as in the world. Only such
// transforms place a navmesh.
bool is_rigid(const Transform& t);
// What a refusal says after the transform's name.
inline constexpr const char* kNotRigid =
    " is not a rotation and a translation (a navmesh rides the mesh: scale, shear or a mirror would change its lengths "
    "and radii)";

// A carrier's placement at one moment. The identity pose (a static navmesh) converts nothing: its
// points come back bit for bit.
class CarrierPose {
public:
    CarrierPose() = default;
    explicit CarrierPose(const Transform& to_world);

    bool is_identity() const { return identity_; }
    const Transform& to_world() const { return to_world_; }
    Vec3 world_point(const Vec3& p) const { return identity_ ? p : Vec3(to_world_ * p); }
    Vec3 carrier_point(const Vec3& p) const { return identity_ ? p : Vec3(to_carrier_ * p); }
    Vec3 world_vector(const Vec3& v) const { return identity_ ? v : Vec3(to_world_.linear() * v); }
    Vec3 carrier_vector(const Vec3& v) const { return identity_ ? v : Vec3(to_carrier_.linear() * v); }
    // The half extents, in carrier axes, of a box that holds the world-axis box of half extents `h`.
    Vec3 carrier_extents(const Vec3& h) const { return identity_ ? h : Vec3(to_carrier_.linear().cwiseAbs() * h); }
    // The world box that holds a carrier-space box.
    Aabb world_box(const Aabb& carrier_box) const;

private:
    Transform to_world_ = Transform::Identity();
    Transform to_carrier_ = Transform::Identity();
    bool identity_ = true;
};

// The one current pose of a movable mesh, shared by every navmesh that rides it (and read by the
// path graphs and agents on them). Thread-safe: the host's thread sets it while path workers and the
// step read it; each read is one whole pose.
class CarrierFrame {
public:
    CarrierFrame(Handle mesh, const Transform& to_world) : mesh_(mesh), pose_(to_world) {}

    Handle mesh() const { return mesh_; }
    CarrierPose pose() const {
        std::lock_guard lock(mutex_);
        return pose_;
    }
    // How many times it was moved: a reader that saw count n and sees n again saw no move between.
    uint64_t moves() const {
        std::lock_guard lock(mutex_);
        return moves_;
    }
    void move(const Transform& to_world) {
        const CarrierPose pose(to_world);
        std::lock_guard lock(mutex_);
        pose_ = pose;
        ++moves_;
    }

private:
    const Handle mesh_;
    mutable std::mutex mutex_;
    CarrierPose pose_;
    uint64_t moves_ = 0;
};

// The pose of `frame` now; the identity for a navmesh that rides nothing (null).
inline CarrierPose pose_of(const std::shared_ptr<const CarrierFrame>& frame) {
    return frame ? frame->pose() : CarrierPose{};
}

}  // namespace nl
