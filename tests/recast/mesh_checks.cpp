#include "mesh_checks.h"

#include <doctest/doctest.h>

#include <sstream>
#include <string>

namespace nl::test {
namespace {

// Collects the first problem of each kind, so a broken mesh gives one readable failure per check.
class Problems {
public:
    template <typename... Parts>
    void add(Parts&&... parts) {
        if (count_++ > 0) return;
        std::ostringstream out;
        (out << ... << parts);
        first_ = out.str();
    }
    int count() const { return count_; }
    const std::string& first() const { return first_; }

private:
    int count_ = 0;
    std::string first_;
};

bool within(const float* p, const float* min, const float* max, float cs, float y_slack) {
    const float slack[3] = {cs, y_slack, cs};
    for (int k = 0; k < 3; ++k) {
        if (p[k] < min[k] - slack[k] || p[k] > max[k] + slack[k]) return false;
    }
    return true;
}

}  // namespace

void check_navmesh(const CapturedMesh& m, const FakeHost& host, const nl_agent_type& agent, float cs, float ch) {
    CHECK(m.size == sizeof(nl_navmesh_def));
    CHECK((m.vertex_stride == 0 || m.vertex_stride == 12));
    CHECK(m.weld_tolerance == 0.0f);
    CHECK(m.agent.radius == agent.radius);
    CHECK(m.agent.height == agent.height);
    CHECK(m.agent.max_climb == agent.max_climb);
    CHECK(m.agent.max_slope == agent.max_slope);
    REQUIRE(m.polygon_count() > 0);
    REQUIRE(m.vertex_count() >= 3);

    Problems sizes, indices, repeated, areas;
    size_t corner = 0;
    for (uint32_t p = 0; p < m.polygon_count(); ++p) {
        const uint32_t n = m.vertex_counts[p];
        if (n < 3 || n > 6) sizes.add("polygon ", p, " has ", n, " corners");
        for (uint32_t k = 0; k < n; ++k) {
            const uint32_t v = m.indices[corner + k];
            if (v >= m.vertex_count()) indices.add("polygon ", p, " corner ", k, " is vertex ", v);
            for (uint32_t j = 0; j < k; ++j) {
                if (m.indices[corner + j] == v) repeated.add("polygon ", p, " repeats vertex ", v);
            }
        }
        corner += n;
        if (!m.areas.empty() && m.areas[p] != 0) areas.add("polygon ", p, " has area ", int(m.areas[p]));
    }
    INFO(sizes.first());
    CHECK(sizes.count() == 0);
    INFO(indices.first());
    CHECK(indices.count() == 0);
    INFO(repeated.first());
    CHECK(repeated.count() == 0);
    INFO(areas.first());
    CHECK(areas.count() == 0);  // everything Recast marks walkable is our area 0
    CHECK(corner == m.indices.size());

    // Detail: polygon_count + 1 monotonic offsets ending at the triangle count, indices in range.
    REQUIRE(m.detail_starts.size() == m.polygon_count() + 1);
    CHECK(m.detail_starts.front() == 0);
    Problems order, empty, detail_indices;
    for (uint32_t p = 0; p < m.polygon_count(); ++p) {
        if (m.detail_starts[p + 1] < m.detail_starts[p]) order.add("detail starts decrease at polygon ", p);
        if (m.detail_starts[p + 1] == m.detail_starts[p]) empty.add("polygon ", p, " has no detail triangle");
    }
    CHECK(m.detail_starts.back() * 3 == m.detail_triangles.size());
    const uint32_t detail_vertex_count = static_cast<uint32_t>(m.detail_vertices.size() / 3);
    for (size_t i = 0; i < m.detail_triangles.size(); ++i) {
        if (m.detail_triangles[i] >= detail_vertex_count)
            detail_indices.add("detail triangle ", i / 3, " uses vertex ", m.detail_triangles[i], " of ",
                               detail_vertex_count);
    }
    INFO(order.first());
    CHECK(order.count() == 0);
    INFO(empty.first());
    CHECK(empty.count() == 0);
    INFO(detail_indices.first());
    CHECK(detail_indices.count() == 0);

    // Every vertex inside the level's bounds, up to Recast's grid snapping: x and z round to a cell;
    // polygon heights are span tops (up to a cell_height above the surface) and rcBuildPolyMeshDetail
    // adds one more cell_height to detail heights ("Is this offset necessary?" in RecastMeshDetail.cpp).
    float min[3], max[3];
    host.bounds(min, max);
    Problems outside;
    for (size_t i = 0; i < m.vertices.size(); i += 3) {
        if (!within(&m.vertices[i], min, max, cs, ch))
            outside.add("vertex ", i / 3, " (", m.vertices[i], ", ", m.vertices[i + 1], ", ", m.vertices[i + 2], ")");
    }
    for (size_t i = 0; i < m.detail_vertices.size(); i += 3) {
        if (!within(&m.detail_vertices[i], min, max, cs, 2 * ch))
            outside.add("detail vertex ", i / 3, " (", m.detail_vertices[i], ", ", m.detail_vertices[i + 1], ", ",
                        m.detail_vertices[i + 2], ")");
    }
    INFO("level bounds (", min[0], ", ", min[1], ", ", min[2], ") .. (", max[0], ", ", max[1], ", ", max[2],
         "); first outside: ", outside.first());
    CHECK(outside.count() == 0);
}

uint32_t count_upward_polygons(const CapturedMesh& m) {
    uint32_t up = 0;
    size_t corner = 0;
    for (uint32_t p = 0; p < m.polygon_count(); ++p) {
        const uint32_t n = m.vertex_counts[p];
        // The y component of the polygon's Newell normal: sum of (z_i - z_j)(x_i + x_j) over edges.
        double ny = 0.0;
        for (uint32_t k = 0; k < n; ++k) {
            const float* a = &m.vertices[m.indices[corner + k] * 3];
            const float* b = &m.vertices[m.indices[corner + (k + 1) % n] * 3];
            ny += (double(a[2]) - b[2]) * (double(a[0]) + b[0]);
        }
        if (ny > 0.0) ++up;
        corner += n;
    }
    return up;
}

}  // namespace nl::test
