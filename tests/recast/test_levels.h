// Small procedural levels with known answers: floors, slopes, walls, ceilings made of quads.
#pragma once

#include <array>
#include <vector>

#include "fake_host.h"

namespace nl::test {

using Point = std::array<float, 3>;

class QuadLevel {
public:
    // Adds quad a b c d as triangles (a, d, c) and (a, c, b): facing up when a -> b runs along +x and
    // b -> c along +z (Recast's walkable test looks at the triangle normal).
    QuadLevel& quad(Point a, Point b, Point c, Point d) {
        const auto base = static_cast<uint32_t>(vertices_.size() / 3);
        for (const Point& p : {a, b, c, d}) vertices_.insert(vertices_.end(), p.begin(), p.end());
        indices_.insert(indices_.end(), {base, base + 3, base + 2, base, base + 2, base + 1});
        return *this;
    }
    // A horizontal floor from (x0, y, z0) to (x1, y, z1), facing up.
    QuadLevel& floor(float x0, float z0, float x1, float z1, float y) {
        return quad({x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1});
    }
    // A horizontal ceiling, facing down.
    QuadLevel& ceiling(float x0, float z0, float x1, float z1, float y) {
        return quad({x0, y, z0}, {x0, y, z1}, {x1, y, z1}, {x1, y, z0});
    }
    FakeHost host() const { return FakeHost(vertices_, indices_); }

private:
    std::vector<float> vertices_;
    std::vector<uint32_t> indices_;
};

}  // namespace nl::test
