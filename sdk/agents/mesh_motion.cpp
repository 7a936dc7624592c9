#include "agents/mesh_motion.h"

#include <algorithm>
#include <utility>

namespace nl {

Transform MeshMotion::after(float ahead) const {
    Transform out = now;
    const float rate = turn.norm();
    if (rate > 0.0f) out.linear() = Eigen::AngleAxisf(rate * ahead, turn / rate).toRotationMatrix() * now.linear();
    out.translation() += velocity * ahead;
    return out;
}

namespace {

bool by_mesh(const MovableMesh& a, const MovableMesh& b) { return a.mesh.packed() < b.mesh.packed(); }

}  // namespace

void MeshMotions::remember(std::vector<MovableMesh> now, float dt) {
    last_ = std::move(now);
    std::sort(last_.begin(), last_.end(), by_mesh);
    dt_ = dt;
}

MeshMotion MeshMotions::motion(const MovableMesh& now) const {
    MeshMotion m{now.mesh, now.transform, Vec3::Zero(), Vec3::Zero(), now.reach};
    if (!(dt_ > 0.0f)) return m;
    const auto found = std::lower_bound(last_.begin(), last_.end(), now, by_mesh);
    if (found != last_.end() && found->mesh == now.mesh) {
        const MovableMesh& before = *found;
        m.velocity = (now.transform.translation() - before.transform.translation()) / dt_;
        // The rotation part of each (a movable mesh may be scaled): the turn over the step, about
        // the origin, as an angle of at most half a turn.
        const Eigen::AngleAxisf turned(
            Eigen::Matrix3f(now.transform.rotation() * before.transform.rotation().transpose()));
        if (turned.angle() > 0.0f) m.turn = turned.axis() * (turned.angle() / dt_);
    }
    return m;
}

std::vector<MeshMotion> MeshMotions::motions(const std::vector<MovableMesh>& now) const {
    std::vector<MeshMotion> out;
    out.reserve(now.size());
    for (const MovableMesh& m : now) out.push_back(motion(m));
    return out;
}

}  // namespace nl
