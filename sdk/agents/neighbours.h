// Who is near whom at the start of a step's move: a grid of the agents on the ground, read by every
// agent's avoidance at once (built before the parallel phase, never written during it).
#pragma once

#include <cstdint>
#include <vector>

#include "level/geometry.h"
#include "util/function_ref.h"

namespace nl {

class NeighbourGrid {
public:
    // Agents i with `grounded[i]`, at positions[i]; cells `cell` metres wide.
    void build(const std::vector<Vec3>& positions, const std::vector<uint8_t>& grounded, float cell);
    // Calls visit(j) for every grounded agent within `range` of `p` in x-z (any order, each once).
    void visit(const Vec3& p, float range, FunctionRef<void(uint32_t)> visit) const;
    // The `most` (at most 16) grounded agents other than `self` nearest to `p` in x-z within `range`,
    // nearest first, the lower index on a tie: written to `out`, their count returned. The answer
    // does not depend on the grid's cells: they are visited in rings around p's, and the search stops
    // once no cell farther out can hold a nearer agent (in a dense crowd, long before `range`).
    size_t nearest(const Vec3& p, float range, uint32_t self, uint32_t* out, size_t most) const;

private:
    float cell_ = 1.0f;
    float origin_x_ = 0.0f, origin_z_ = 0.0f;
    int columns_ = 0, rows_ = 0;
    std::vector<uint32_t> cell_start_;  // columns * rows + 1 offsets into members_
    std::vector<uint32_t> members_;
    const std::vector<Vec3>* positions_ = nullptr;
};

}  // namespace nl
