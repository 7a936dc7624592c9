// A placement of a movable mesh as nl_mesh_set_transform takes it (16 floats, column-major), and the
// point maps that check what rides the mesh: for programs that drive moving surfaces through the C
// ABI. Header-only, no Eigen (the shared library does not export it).
#pragma once

#include <cmath>
#include <cstring>

namespace nl::test {

// A rotation and a translation: what a mesh that carries a navmesh accepts.
struct RigidPose {
    float m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

    // Tilted by `roll` radians about x, then turned by `yaw` about y, then moved to (x, y, z).
    static RigidPose at(float x, float y, float z, float yaw, float roll = 0.0f) {
        const float cy = std::cos(yaw), sy = std::sin(yaw), cr = std::cos(roll), sr = std::sin(roll);
        RigidPose p;
        const float columns[16] = {cy, 0, -sy, 0, sy * sr, cr, cy * sr, 0, sy * cr, -sr, cy * cr, 0, x, y, z, 1};
        std::memcpy(p.m, columns, sizeof p.m);
        return p;
    }
    // A transform read back (nl_mesh_info.transform), taken to be rigid.
    static RigidPose of(const float* column_major) {
        RigidPose p;
        std::memcpy(p.m, column_major, sizeof p.m);
        return p;
    }

    bool operator==(const RigidPose& o) const { return std::memcmp(m, o.m, sizeof m) == 0; }
    bool operator!=(const RigidPose& o) const { return !(*this == o); }

    // The world point of a point in the mesh's own space.
    void to_world(const float* local, float* out) const {
        for (int i = 0; i < 3; ++i) out[i] = m[i] * local[0] + m[4 + i] * local[1] + m[8 + i] * local[2] + m[12 + i];
    }
    // Back into the mesh's space (the rotation's transpose is its inverse).
    void to_local(const float* world, float* out) const {
        const float d[3] = {world[0] - m[12], world[1] - m[13], world[2] - m[14]};
        for (int j = 0; j < 3; ++j) out[j] = m[4 * j] * d[0] + m[4 * j + 1] * d[1] + m[4 * j + 2] * d[2];
    }
};

}  // namespace nl::test
