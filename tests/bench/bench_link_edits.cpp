// navlink-bench-link-edits [COUNT]: what a link edit costs as links accumulate. COUNT (20,000)
// manual links are added one nl_link_add at a time to a 100 m x 100 m navmesh, then the same links
// are loaded with one nl_navmesh_load_links_json. One line:
//   links=N add_ms=X first_us_per_add=X last_us_per_add=X load_json_ms=X
// (first/last: the mean cost of an add over the first and the last tenth of the adds; equal when
// an add does not depend on how many links the navmesh has).
#include <navlink/navlink.h>

#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "cell_navmesh.h"
#include "clock.h"

namespace {

int failed(const char* what) {
    std::fprintf(stderr, "navlink-bench-link-edits: %s: %s\n", what, nl_get_last_error_message());
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    const int count = argc > 1 ? std::atoi(argv[1]) : 20000;
    if (count < 10) {
        std::fprintf(stderr, "usage: navlink-bench-link-edits [COUNT >= 10]\n");
        return 2;
    }
    nl_world* world = nullptr;
    const nl_world_def world_def = nl_default_world_def();
    if (NL_FAILED(nl_world_create(&world_def, &world))) return failed("world");
    const nl::test::CellNavmesh cells(std::vector<std::string>(100, std::string(100, '.')), 0.4f);
    nl_navmesh_id navmesh{};
    if (NL_FAILED(nl_navmesh_add(world, &cells.def, &navmesh))) return failed("navmesh");

    std::mt19937 rng(1);
    std::uniform_real_distribution<float> xz(0.5f, 99.5f);
    std::vector<double> add_ms(static_cast<size_t>(count));
    const double start = nl::samples::now_ms();
    for (int i = 0; i < count; ++i) {
        nl_link_def def = nl_default_link_def();
        def.start[0] = xz(rng), def.start[2] = xz(rng);
        def.end[0] = xz(rng), def.end[2] = xz(rng);
        nl_link_id id{};
        const double before = nl::samples::now_ms();
        if (NL_FAILED(nl_link_add(world, navmesh, &def, &id))) return failed("nl_link_add");
        add_ms[size_t(i)] = nl::samples::now_ms() - before;
    }
    const double all_ms = nl::samples::now_ms() - start;
    const int tenth = count / 10;
    double first = 0.0, last = 0.0;
    for (int i = 0; i < tenth; ++i) first += add_ms[size_t(i)], last += add_ms[size_t(count - 1 - i)];

    size_t length = 0;
    if (NL_FAILED(nl_navmesh_save_links_json(world, navmesh, nullptr, 0, &length))) return failed("save");
    std::string json(length + 1, '\0');
    if (NL_FAILED(nl_navmesh_save_links_json(world, navmesh, json.data(), json.size(), &length))) return failed("save");
    const double load_start = nl::samples::now_ms();
    uint32_t loaded = 0;
    if (NL_FAILED(nl_navmesh_load_links_json(world, navmesh, json.data(), length, 0, &loaded))) return failed("load");
    const double load_ms = nl::samples::now_ms() - load_start;

    std::printf("links=%d add_ms=%.1f first_us_per_add=%.2f last_us_per_add=%.2f load_json_ms=%.1f\n", count, all_ms,
                1000.0 * first / tenth, 1000.0 * last / tenth, load_ms);
    nl_world_destroy(world);
    return loaded == uint32_t(count) ? 0 : 1;
}
