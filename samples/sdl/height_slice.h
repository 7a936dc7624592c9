// Roofs cut away: a height field over the navmesh, seen from above, below which level surfaces are
// drawn. Each cell's cut is the topmost navmesh surface within kReach of it plus kClearance; cells
// with no navmesh that near are cut at the highest navmesh surface anywhere plus kClearance. So a
// roof or a ceiling over a walkable floor goes (every ceiling over a navmesh is at least a body's
// height above it), a floor under an upper floor stays hidden by it (that floor has a navmesh of its
// own), and steps, kerbs and crates lower than kClearance stay.
#pragma once

#include <array>
#include <vector>

#include "navmesh_contents.h"

namespace nl::picture {

class HeightSlice {
public:
    static constexpr float kClearance = 1.5f;  // metres above the navmesh
    static constexpr float kReach = 1.0f;      // metres around the navmesh: its rim, eroded by a body's radius

    // Nothing is cut for an empty navmesh.
    explicit HeightSlice(const samples::NavmeshContents& navmesh);

    bool active() const { return !cut_.empty(); }
    // The height above which level surfaces at (x, z) are cut away.
    float cut_at(float x, float z) const;
    // Whether a point of a level surface is above the cut (drawn only with roofs on).
    bool above(const float p[3]) const { return active() && p[1] > cut_at(p[0], p[2]); }
    float cell_size() const { return cell_; }
    // The cut where no navmesh is near: the highest navmesh surface plus kClearance.
    float top() const { return fallback_; }

private:
    float origin_[2] = {0, 0};  // x, z of cell (0, 0)'s corner
    float cell_ = 1.0f;
    int columns_ = 0, rows_ = 0;
    float fallback_ = 0.0f;
    std::vector<float> cut_;  // per cell, row by row (z); -inf where no navmesh is near
};

}  // namespace nl::picture
