// A stand-in for libnavlink's side of the plugin ABI: a host table serving fixed level triangles and
// recording set_error and log calls, and a sink that copies the navmesh it is given.
#pragma once

#include <cstdint>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "navlink/navlink.h"
#include "navlink/plugin.h"
#include "navlink/recast.h"

namespace nl::test {

class FakeHost {
public:
    FakeHost() = default;
    FakeHost(std::vector<float> vertices, std::vector<uint32_t> indices);
    static FakeHost from_obj(const std::filesystem::path& path);

    // The table handed to the plugin; points at this object.
    nl_plugin_host table();

    const std::vector<float>& vertices() const { return vertices_; }
    size_t triangle_count() const { return indices_.size() / 3; }
    void bounds(float* min, float* max) const;

    std::vector<std::string> errors() const;
    std::vector<std::string> logs() const;
    std::string last_error() const;

private:
    static void log(void* context, nl_log_level level, const char* message);
    static void set_error(void* context, const char* message);
    static nl_status get_level_triangles(void* context, float* vertices, uint32_t vertex_capacity,
                                         uint32_t* out_vertex_count, uint32_t* indices, uint32_t triangle_capacity,
                                         uint32_t* out_triangle_count);

    std::vector<float> vertices_;
    std::vector<uint32_t> indices_;
    mutable std::mutex mutex_;
    std::vector<std::string> errors_;
    std::vector<std::string> logs_;
};

// A navmesh as the sink received it, copied.
struct CapturedMesh {
    std::vector<float> vertices;
    std::vector<uint32_t> indices;
    std::vector<uint8_t> vertex_counts;
    std::vector<uint8_t> areas;
    std::vector<float> detail_vertices;
    std::vector<uint32_t> detail_triangles;
    std::vector<uint32_t> detail_starts;
    uint32_t size = 0;
    uint32_t vertex_stride = 0;
    float weld_tolerance = -1.0f;
    nl_agent_type agent{};

    uint32_t polygon_count() const { return static_cast<uint32_t>(vertex_counts.size()); }
    uint32_t vertex_count() const { return static_cast<uint32_t>(vertices.size() / 3); }
    bool operator==(const CapturedMesh& o) const;
};

struct BuildOutcome {
    nl_status status = 0;
    int sink_calls = 0;
    CapturedMesh mesh;
    std::string error;  // the host's last set_error message, "" if none
    double milliseconds = 0.0;
};

// Agent and build def as libnavlink's defaults give them (the plugin is tested without the library).
nl_agent_type default_agent();
nl_navmesh_build_def default_build_def();
nl_navmesh_build_def json_build_def(const std::string& json);  // borrows json

// Gets the builder through plugin_entry and runs one build on `host`. The sink returns sink_status.
BuildOutcome run_build(FakeHost& host, const nl_navmesh_build_def& def, nl_status sink_status = NL_STATUS_SUCCESS);

// The shared level of that stem ("nav_test"), or an empty path when the levels are not here.
std::filesystem::path shared_level(const std::string& stem);

}  // namespace nl::test
