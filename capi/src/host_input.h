// Reading what the host hands over: ids by value and strided vertex arrays.
#pragma once

#include <cmath>
#include <cstring>
#include <vector>

#include "level/geometry.h"
#include "level/mesh_validation.h"
#include "util/error.h"
#include "util/handle.h"

namespace nl::capi {

// Every nl_*_id is {index1, revision}, as a core Handle.
template <typename Id>
Handle to_handle(Id id) {
    return Handle{id.index1, id.revision};
}

template <typename Id>
Id to_id(Handle h) {
    return Id{h.index1, h.revision};
}

// A position the host passed (3 floats), refused when not finite or beyond the coordinate limit;
// `name` parts spell the field for the message ("rays", "[", 3, "].origin"; a failure about a field).
template <typename... Name>
Vec3 read_position(const float* p, const Name&... name) {
    const Vec3 v(p[0], p[1], p[2]);
    if (!v.allFinite()) fail_field(ErrorCode::InvalidArgument, name..., " is not finite");
    if (!within_coordinate_limit(v))
        fail_field(ErrorCode::InvalidArgument, name..., " is beyond the coordinate limit of +-", kCoordinateLimit,
                   " m");
    return v;
}

// An amount the host passed (a distance, a cost), refused when negative or not finite; `name` parts
// spell the field for the message.
template <typename... Name>
float read_amount(float value, const Name&... name) {
    if (!(value >= 0.0f) || !std::isfinite(value))
        fail_field(ErrorCode::InvalidArgument, name..., " is ", value, " (must be finite and >= 0)");
    return value;
}

// Copies `count` positions that start every `stride` bytes (0 = packed), the fields `vertices`,
// `vertex_count` and `vertex_stride` of a def (a failure names them: fail_field). The host's stride
// need not keep floats aligned, hence the byte copies.
inline std::vector<Vec3> read_vertices(const float* vertices, uint32_t count, uint32_t stride) {
    if (!vertices) fail_field(ErrorCode::InvalidArgument, "vertices is null");
    if (count == 0) fail_field(ErrorCode::InvalidArgument, "vertex_count is 0");
    const uint32_t step = stride == 0 ? 3 * sizeof(float) : stride;
    if (step < 3 * sizeof(float))
        fail_field(ErrorCode::InvalidArgument, "vertex_stride is ", stride, " (at least 12 bytes, or 0)");
    std::vector<Vec3> out(count);
    const auto* bytes = reinterpret_cast<const unsigned char*>(vertices);
    for (uint32_t i = 0; i < count; ++i) {
        float xyz[3];
        std::memcpy(xyz, bytes + size_t(i) * step, sizeof xyz);
        out[i] = Vec3(xyz[0], xyz[1], xyz[2]);
    }
    return out;
}

}  // namespace nl::capi
