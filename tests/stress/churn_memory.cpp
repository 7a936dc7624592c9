// navlink-churn-memory: what a long-running host does all day (navmeshes, links, meshes and path
// tickets added and removed by the hundred thousand) must not make the library grow. Each kind is
// churned in rounds; after a warm-up round the heap in use (glibc's mallinfo2) may not grow by more
// than a few bytes per cycle. Exits 0 on success, 1 naming the kind that grew.
#include <navlink/navlink.h>

#include <malloc.h>

#include <cstdio>
#include <functional>
#include <string>

#include "cell_navmesh.h"

namespace {

int failures = 0;

long long heap_in_use() { return static_cast<long long>(mallinfo2().uordblks); }

// Runs `cycle` `count` times per round for three rounds; the last two may grow the heap by at most
// `max_bytes_per_cycle` each on average (the first warms up tables that then stay their size).
void churn(const char* kind, int count, double max_bytes_per_cycle, const std::function<bool()>& cycle) {
    std::string figures;
    for (int round = 0; round < 3; ++round) {
        const long long before = heap_in_use();
        for (int i = 0; i < count; ++i) {
            if (!cycle()) {
                std::fprintf(stderr, "navlink-churn-memory: %s: a call failed: %s\n", kind,
                             nl_get_last_error_message());
                ++failures;
                return;
            }
        }
        const double per_cycle = double(heap_in_use() - before) / count;
        figures += " " + std::to_string(per_cycle);
        if (round > 0 && per_cycle > max_bytes_per_cycle) {
            std::fprintf(stderr, "navlink-churn-memory: %s: the heap grew by %.1f bytes per cycle in round %d\n", kind,
                         per_cycle, round);
            ++failures;
        }
    }
    std::printf("%s: bytes per cycle by round:%s\n", kind, figures.c_str());
}

}  // namespace

int main() {
    nl_world_def def = nl_default_world_def();
    def.worker_count = 1;
    def.path_worker_count = 0;
    nl_world* world = nullptr;
    if (nl_world_create(&def, &world) != NL_STATUS_SUCCESS) return 1;
    const nl::test::CellNavmesh cells({"....", "....", "....", "...."}, 0.0f);
    nl_navmesh_id navmesh{};
    if (nl_navmesh_add(world, &cells.def, &navmesh) != NL_STATUS_SUCCESS) return 1;

    churn("navmesh add/remove", 50000, 2.0, [&] {
        nl_navmesh_id id{};
        return nl_navmesh_add(world, &cells.def, &id) == NL_STATUS_SUCCESS &&
               nl_navmesh_remove(world, id) == NL_STATUS_SUCCESS;
    });
    churn("link add/remove", 50000, 2.0, [&] {
        nl_link_def link = nl_default_link_def();
        link.start[0] = 0.5f, link.start[2] = 0.5f;
        link.end[0] = 3.5f, link.end[2] = 3.5f;
        nl_link_id id{};
        return nl_link_add(world, navmesh, &link, &id) == NL_STATUS_SUCCESS &&
               nl_link_remove(world, id) == NL_STATUS_SUCCESS;
    });
    const float floor[] = {0, 0, 0, 0, 0, 4, 4, 0, 0};
    const uint32_t triangle[] = {0, 1, 2};
    churn("mesh add/remove", 20000, 2.0, [&] {
        nl_mesh_def mesh = nl_default_mesh_def();
        mesh.vertices = floor, mesh.vertex_count = 3, mesh.indices = triangle, mesh.triangle_count = 1;
        nl_mesh_id id{};
        return nl_mesh_add(world, &mesh, &id) == NL_STATUS_SUCCESS && nl_mesh_remove(world, id) == NL_STATUS_SUCCESS;
    });
    churn("path request/process/release", 50000, 2.0, [&] {
        nl_path_request_def request = nl_default_path_request_def();
        request.navmesh = navmesh;
        request.start[0] = 0.5f, request.start[2] = 0.5f;
        request.goal[0] = 3.5f, request.goal[2] = 3.5f;
        request.capabilities.radius = 0.0f;
        nl_path_ticket ticket{};
        uint32_t done = 0;
        nl_path_budget one = nl_default_path_budget();
        one.max_requests = 1;
        return nl_path_request(world, &request, &ticket) == NL_STATUS_SUCCESS &&
               nl_path_process(world, &one, &done) == NL_STATUS_SUCCESS &&
               nl_path_release(world, ticket) == NL_STATUS_SUCCESS;
    });
    // Released before anything plans them (no path workers, no nl_path_process): nothing may stay.
    churn("path request/release, never planned", 50000, 2.0, [&] {
        nl_path_request_def request = nl_default_path_request_def();
        request.navmesh = navmesh;
        request.start[0] = 0.5f, request.start[2] = 0.5f;
        request.goal[0] = 3.5f, request.goal[2] = 3.5f;
        nl_path_ticket ticket{};
        return nl_path_request(world, &request, &ticket) == NL_STATUS_SUCCESS &&
               nl_path_release(world, ticket) == NL_STATUS_SUCCESS;
    });
    nl_world_destroy(world);
    std::printf("failures=%d\n", failures);
    return failures == 0 ? 0 : 1;
}
