// A uniform grid over the x-z plane listing the polygons whose bounds overlap each cell: point
// location visits a few cells instead of every polygon.
#pragma once

#include <cstdint>
#include <vector>

#include "level/geometry.h"
#include "util/function_ref.h"

namespace nl {

class PolygonGrid {
public:
    // `bounds` per polygon; the cell size follows the polygons' typical size.
    void build(const std::vector<Aabb>& polygon_bounds, const Aabb& all);

    // Calls visit(polygon) once for every polygon whose x-z bounds overlap [lo, hi] in x-z
    // (callers test y themselves).
    void visit(const Vec3& lo, const Vec3& hi, const std::vector<Aabb>& polygon_bounds,
               FunctionRef<void(uint32_t)> visit) const;

    size_t memory_bytes() const {
        return (cell_start_.capacity() + cell_polygons_.capacity()) * sizeof(uint32_t);
    }

private:
    int cell_x(float x) const;
    int cell_z(float z) const;

    float origin_x_ = 0.0f, origin_z_ = 0.0f, inverse_cell_ = 1.0f;
    int columns_ = 0, rows_ = 0;
    std::vector<uint32_t> cell_start_;  // columns * rows + 1 offsets into cell_polygons_
    std::vector<uint32_t> cell_polygons_;
};

}  // namespace nl
