#include "fake_host.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <limits>

#include "io/obj_reader.h"
#include "recast_builder.h"
#include "shared_levels.h"

namespace nl::test {

FakeHost::FakeHost(std::vector<float> vertices, std::vector<uint32_t> indices)
    : vertices_(std::move(vertices)), indices_(std::move(indices)) {}

FakeHost FakeHost::from_obj(const std::filesystem::path& path) {
    const TriangleMesh mesh = read_obj_file(path.string());
    std::vector<float> vertices;
    vertices.reserve(mesh.vertices.size() * 3);
    for (const Vec3& v : mesh.vertices) vertices.insert(vertices.end(), {v.x(), v.y(), v.z()});
    std::vector<uint32_t> indices;
    indices.reserve(mesh.triangles.size() * 3);
    for (const Triangle& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());
    return FakeHost(std::move(vertices), std::move(indices));
}

nl_plugin_host FakeHost::table() {
    nl_plugin_host h{};
    h.size = sizeof h;
    h.abi_version = NL_PLUGIN_ABI_VERSION;
    h.context = this;
    h.log = &FakeHost::log;
    h.set_error = &FakeHost::set_error;
    h.get_level_triangles = &FakeHost::get_level_triangles;
    return h;
}

void FakeHost::bounds(float* min, float* max) const {
    for (int k = 0; k < 3; ++k) {
        min[k] = std::numeric_limits<float>::infinity();
        max[k] = -std::numeric_limits<float>::infinity();
    }
    for (size_t i = 0; i < vertices_.size(); ++i) {
        min[i % 3] = std::min(min[i % 3], vertices_[i]);
        max[i % 3] = std::max(max[i % 3], vertices_[i]);
    }
}

std::vector<std::string> FakeHost::errors() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return errors_;
}
std::vector<std::string> FakeHost::logs() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return logs_;
}
std::string FakeHost::last_error() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return errors_.empty() ? std::string() : errors_.back();
}

void FakeHost::log(void* context, nl_log_level level, const char* message) {
    auto* self = static_cast<FakeHost*>(context);
    std::lock_guard<std::mutex> lock(self->mutex_);
    self->logs_.push_back(std::to_string(level) + " " + message);
}

void FakeHost::set_error(void* context, const char* message) {
    auto* self = static_cast<FakeHost*>(context);
    std::lock_guard<std::mutex> lock(self->mutex_);
    self->errors_.emplace_back(message);
}

// As plugin.h specifies: counts always written; BUFFER_TOO_SMALL (nothing copied) when either buffer is short.
nl_status FakeHost::get_level_triangles(void* context, float* vertices, uint32_t vertex_capacity,
                                        uint32_t* out_vertex_count, uint32_t* indices, uint32_t triangle_capacity,
                                        uint32_t* out_triangle_count) {
    auto* self = static_cast<FakeHost*>(context);
    if (!out_vertex_count || !out_triangle_count) return NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT;
    const auto vertex_count = static_cast<uint32_t>(self->vertices_.size() / 3);
    const auto triangle_count = static_cast<uint32_t>(self->indices_.size() / 3);
    *out_vertex_count = vertex_count;
    *out_triangle_count = triangle_count;
    if (vertex_capacity < vertex_count || triangle_capacity < triangle_count)
        return NL_STATUS_FAILURE | NL_STATUS_BUFFER_TOO_SMALL;
    if ((vertex_count && !vertices) || (triangle_count && !indices))
        return NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT;
    std::copy(self->vertices_.begin(), self->vertices_.end(), vertices);
    std::copy(self->indices_.begin(), self->indices_.end(), indices);
    return NL_STATUS_SUCCESS;
}

bool CapturedMesh::operator==(const CapturedMesh& o) const {
    return vertices == o.vertices && indices == o.indices && vertex_counts == o.vertex_counts && areas == o.areas &&
           detail_vertices == o.detail_vertices && detail_triangles == o.detail_triangles &&
           detail_starts == o.detail_starts;
}

nl_agent_type default_agent() { return nl_agent_type{0.6f, 2.0f, 0.9f, 45.0f}; }

nl_navmesh_build_def default_build_def() {
    nl_navmesh_build_def def{};
    def.size = sizeof def;
    def.builder = "recast";
    def.agent_type = default_agent();
    return def;
}

nl_navmesh_build_def json_build_def(const std::string& json) {
    nl_navmesh_build_def def = default_build_def();
    def.settings_json = json.data();
    def.settings_json_length = json.size();
    return def;
}

namespace {

struct SinkState {
    BuildOutcome* outcome;
    nl_status status;
};

nl_status capture(void* context, const nl_navmesh_def* def) {
    auto* state = static_cast<SinkState*>(context);
    BuildOutcome& out = *state->outcome;
    ++out.sink_calls;
    CapturedMesh& m = out.mesh;
    m.size = def->size;
    m.vertex_stride = def->vertex_stride;
    m.weld_tolerance = def->weld_tolerance;
    m.agent = def->agent_type;
    const uint32_t stride_floats = (def->vertex_stride ? def->vertex_stride : 12) / sizeof(float);
    m.vertices.clear();
    for (uint32_t v = 0; v < def->vertex_count; ++v)
        m.vertices.insert(m.vertices.end(), def->vertices + v * stride_floats, def->vertices + v * stride_floats + 3);
    m.vertex_counts.assign(def->polygon_vertex_counts, def->polygon_vertex_counts + def->polygon_count);
    size_t corners = 0;
    for (uint8_t c : m.vertex_counts) corners += c;
    m.indices.assign(def->indices, def->indices + corners);
    if (def->areas) m.areas.assign(def->areas, def->areas + def->polygon_count);
    if (def->detail_triangle_starts) {
        m.detail_starts.assign(def->detail_triangle_starts, def->detail_triangle_starts + def->polygon_count + 1);
        m.detail_vertices.assign(def->detail_vertices, def->detail_vertices + size_t{def->detail_vertex_count} * 3);
        m.detail_triangles.assign(def->detail_triangles,
                                  def->detail_triangles + size_t{def->detail_triangle_count} * 3);
    }
    return state->status;
}

}  // namespace

BuildOutcome run_build(FakeHost& host, const nl_navmesh_build_def& def, nl_status sink_status) {
    BuildOutcome out;
    const nl_plugin_host table = host.table();
    nl_plugin_info info{};
    info.size = sizeof info;
    REQUIRE(nl::recast::plugin_entry(NL_PLUGIN_ABI_VERSION, &table, &info) == NL_STATUS_SUCCESS);
    REQUIRE((info.navmesh_builder.build != nullptr));
    const size_t errors_before = host.errors().size();
    SinkState sink{&out, sink_status};
    const auto start = std::chrono::steady_clock::now();
    out.status = info.navmesh_builder.build(info.state, &table, &def, &capture, &sink);
    out.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const std::vector<std::string> errors = host.errors();
    if (errors.size() > errors_before) out.error = errors.back();
    return out;
}

std::filesystem::path shared_level(const std::string& stem) {
    const std::filesystem::path path = levels_dir() / (stem + ".obj");
    if (std::filesystem::exists(path)) return path;
    if (levels_required()) FAIL("shared level missing: " << path.string());
    return {};
}

}  // namespace nl::test
