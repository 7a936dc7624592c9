// Grids over the x-z plane listing the polygons whose bounds overlap each cell: point location
// visits a few cells instead of every polygon.
//
// One grid per polygon size, cells 4 times wider at each level, each polygon in the finest level in
// which it spans at most 4 cells (so it is listed in at most 25): the entries stay bounded whatever
// the mix of sizes, where a single grid sized for small polygons lists a polygon spanning the
// navmesh in every one of its cells. Only the levels that hold polygons exist, and the finest has at
// most about 4 cells per polygon, so there are about 4.3 cells per polygon in all.
#pragma once

#include <cstdint>
#include <vector>

#include "level/geometry.h"
#include "util/function_ref.h"

namespace nl {

class PolygonGrid {
public:
    // `bounds` per polygon, `all` around them. Throws OutOfMemory when the grid would need more
    // entries or cells than 32-bit offsets address (far more polygons than memory holds).
    void build(const std::vector<Aabb>& polygon_bounds, const Aabb& all);

    // Calls visit(polygon) once for every polygon whose x-z bounds overlap [lo, hi] in x-z
    // (callers test y themselves).
    void visit(const Vec3& lo, const Vec3& hi, const std::vector<Aabb>& polygon_bounds,
               FunctionRef<void(uint32_t)> visit) const;

    size_t memory_bytes() const {
        return levels_.capacity() * sizeof(Level) +
               (cell_start_.capacity() + cell_polygons_.capacity()) * sizeof(uint32_t);
    }

private:
    struct Level {
        double inverse_cell;
        int columns, rows;
        uint32_t first_cell;  // its columns * rows cells start here in cell_start_

        int cell_x(float x, float origin) const;
        int cell_z(float z, float origin) const;
    };

    float origin_x_ = 0.0f, origin_z_ = 0.0f;
    std::vector<Level> levels_;         // finest first
    std::vector<uint32_t> cell_start_;  // every level's cells, then one end: offsets into cell_polygons_
    std::vector<uint32_t> cell_polygons_;
};

}  // namespace nl
