// How the level's movable meshes move, read from where they stood at the last two steps and carried
// on: where a mesh will be a moment from now, so that a jump onto a moving surface aims where its
// landing will be and its flight is checked against the level as it will be when the body passes.
#pragma once

#include <vector>

#include "level/level.h"

namespace nl {

// One movable mesh's motion: from its placement `now`, its origin moves at `velocity` and it turns
// at `turn` (the axis times radians per second, about its origin), both carried on unchanged.
struct MeshMotion {
    Handle mesh;
    Transform now = Transform::Identity();
    Vec3 velocity = Vec3::Zero();
    Vec3 turn = Vec3::Zero();
    float reach = 0.0f;  // how far its farthest point is from its origin

    bool moves() const { return velocity.squaredNorm() > 0.0f || turn.squaredNorm() > 0.0f; }
    // Where it will be `ahead` seconds from now.
    Transform after(float ahead) const;
    // How fast its fastest point moves (m/s).
    float fastest_point() const { return velocity.norm() + turn.norm() * reach; }
};

// Single owner: the agents' step (under the agents' exclusive lock).
class MeshMotions {
public:
    // Where the movable meshes are at the end of a step of `dt` seconds.
    void remember(std::vector<MovableMesh> now, float dt);
    // The motion of each of `now` since the last remember(): a mesh not seen then (or one seen
    // before a step of no time) stands still.
    std::vector<MeshMotion> motions(const std::vector<MovableMesh>& now) const;
    // The motion of one mesh that stands at `now` (a carrier's pose read by the step).
    MeshMotion motion(const MovableMesh& now) const;

private:
    std::vector<MovableMesh> last_;
    float dt_ = 0.0f;
};

}  // namespace nl
