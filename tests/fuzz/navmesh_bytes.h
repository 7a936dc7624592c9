// A host navmesh (nl_navmesh_def's arrays) as fuzz bytes, both ways: the nl_navmesh_add target
// decodes any bytes into a def, and the seed maker encodes real navmeshes into seeds.
//
// Little endian, every count capped so no input allocates much; bytes missing at the end read as 0:
//   u8 flags (1: corner counts given, 2: areas given, 4: detail given, 8: tolerance and agent given)
//   u16 vertex_count, u16 polygon_count
//   [8] f32 weld_tolerance, f32 radius, height, max_climb, max_slope
//   f32 x y z per vertex
//   [1] u8 corners per polygon (else 3)
//   u16 index per corner (not reduced: an index past the vertices is for the library to refuse)
//   [2] u8 area per polygon
//   [4] u16 detail_vertex_count, u16 detail_triangle_count, f32 x y z per detail vertex,
//       u16 x 3 per detail triangle, u16 per polygon + 1 (the starts)
#pragma once

#include <navlink/navlink.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace nl::fuzz {

constexpr uint32_t kMaxVertices = 1024;
constexpr uint32_t kMaxPolygons = 512;

enum NavmeshFlags : uint8_t { kCounts = 1, kAreas = 2, kDetail = 4, kAgent = 8 };

class ByteReader {
public:
    ByteReader(const uint8_t* data, size_t size) : data_(data), size_(size) {}
    template <typename T>
    T read() {
        T value{};
        const size_t n = at_ < size_ ? std::min(sizeof(T), size_ - at_) : 0;
        if (n) std::memcpy(&value, data_ + at_, n);
        at_ += sizeof(T);
        return value;
    }

private:
    const uint8_t* data_;
    size_t size_;
    size_t at_ = 0;
};

// The arrays a decoded def points into.
struct NavmeshBytes {
    std::vector<float> vertices;
    std::vector<uint32_t> indices;
    std::vector<uint8_t> counts, areas;
    std::vector<float> detail_vertices;
    std::vector<uint32_t> detail_triangles, detail_starts;
    nl_navmesh_def def = nl_default_navmesh_def();

    NavmeshBytes(const uint8_t* data, size_t size) {
        ByteReader in(data, size);
        const uint8_t flags = in.read<uint8_t>();
        const uint32_t vertex_count = std::min<uint32_t>(in.read<uint16_t>(), kMaxVertices);
        const uint32_t polygon_count = std::min<uint32_t>(in.read<uint16_t>(), kMaxPolygons);
        if (flags & kAgent) {
            def.weld_tolerance = in.read<float>();
            def.agent_type = nl_agent_type{in.read<float>(), in.read<float>(), in.read<float>(), in.read<float>()};
        }
        for (uint32_t i = 0; i < 3 * vertex_count; ++i) vertices.push_back(in.read<float>());
        size_t corners = 0;
        for (uint32_t p = 0; p < polygon_count; ++p) {
            counts.push_back(flags & kCounts ? in.read<uint8_t>() : 3);
            corners += counts.back();
        }
        for (size_t k = 0; k < corners; ++k) indices.push_back(in.read<uint16_t>());
        if (flags & kAreas)
            for (uint32_t p = 0; p < polygon_count; ++p) areas.push_back(in.read<uint8_t>());
        if (flags & kDetail) {
            const uint32_t dv = in.read<uint16_t>() % kMaxVertices, dt = in.read<uint16_t>() % kMaxPolygons;
            for (uint32_t i = 0; i < 3 * dv; ++i) detail_vertices.push_back(in.read<float>());
            for (uint32_t i = 0; i < 3 * dt; ++i) detail_triangles.push_back(in.read<uint16_t>());
            for (uint32_t p = 0; p <= polygon_count; ++p) detail_starts.push_back(in.read<uint16_t>());
            def.detail_vertices = detail_vertices.data();
            def.detail_vertex_count = dv;
            def.detail_triangles = detail_triangles.data();
            def.detail_triangle_count = dt;
            def.detail_triangle_starts = detail_starts.data();
        }
        def.vertices = vertices.data();
        def.vertex_count = vertex_count;
        def.indices = indices.data();
        def.polygon_vertex_counts = flags & kCounts ? counts.data() : nullptr;
        def.polygon_count = polygon_count;
        def.areas = flags & kAreas ? areas.data() : nullptr;
    }
};

// Triangles (3 indices each into `vertices`, x y z each) as bytes NavmeshBytes decodes: no detail,
// the default agent, at most kMaxVertices and kMaxPolygons (the rest left out).
inline std::string triangles_as_bytes(const std::vector<float>& vertices, const std::vector<uint32_t>& triangles) {
    std::string out;
    auto put = [&](const auto& value) { out.append(reinterpret_cast<const char*>(&value), sizeof value); };
    const auto vertex_count = static_cast<uint16_t>(std::min<size_t>(vertices.size() / 3, kMaxVertices));
    std::vector<uint32_t> kept;
    for (size_t t = 0; t + 2 < triangles.size() && kept.size() < 3 * size_t(kMaxPolygons); t += 3) {
        if (triangles[t] < vertex_count && triangles[t + 1] < vertex_count && triangles[t + 2] < vertex_count)
            kept.insert(kept.end(), {triangles[t], triangles[t + 1], triangles[t + 2]});
    }
    put(uint8_t{0});
    put(vertex_count);
    put(static_cast<uint16_t>(kept.size() / 3));
    for (size_t i = 0; i < 3 * size_t(vertex_count); ++i) put(vertices[i]);
    for (const uint32_t index : kept) put(static_cast<uint16_t>(index));
    return out;
}

}  // namespace nl::fuzz
