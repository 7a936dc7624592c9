#include "generation_report_text.h"

namespace nl::cli {

void print_generation_report(std::FILE* out, const nl_link_generation_report& r, const std::vector<nl_link>& links,
                             const GenerationTimes& times) {
    uint32_t jumps = 0, drops = 0, manual = 0, plugin = 0, one_way = 0;
    for (const nl_link& l : links) {
        jumps += l.kind == NL_LINK_JUMP;
        drops += l.kind == NL_LINK_DROP;
        manual += l.kind == NL_LINK_MANUAL;
        plugin += l.kind >= NL_LINK_FIRST_PLUGIN_KIND;
        one_way += !l.bidirectional;
    }
    std::fprintf(out, "links: %zu (%u jump, %u drop, %u manual, %u plugin; %u one-way)\n", links.size(), jumps, drops,
                 manual, plugin, one_way);
    std::fprintf(out, "  from %u boundary edges, %u short-edge groups, %u samples, %u take-off points\n", r.edges,
                 r.groups, r.samples, r.takeoff_points);
    std::fprintf(out, "  candidates: %u jumps, %u drops\n", r.jump_candidates, r.drop_candidates);
    std::fprintf(out, "rejected:\n");
    const struct {
        const char* reason;
        uint32_t count;
    } rejected[] = {
        {"wall between edge and rim", r.rejected_wall},
        {"not a ledge", r.rejected_not_ledge},
        {"distance", r.rejected_distance},
        {"rise", r.rejected_rise},
        {"angle", r.rejected_angle},
        {"no landing", r.rejected_no_landing},
        {"body touches the level", r.rejected_clearance},
        {"duplicate", r.rejected_duplicate},
        {"walking is about as short", r.rejected_walkable},
        {"drop too shallow (walked)", r.rejected_too_shallow},
        {"drop too deep", r.rejected_too_deep},
    };
    for (const auto& item : rejected) std::fprintf(out, "  %-26s %8u\n", item.reason, item.count);
    std::fprintf(out, "time (ms):\n");
    const struct {
        const char* stage;
        double ms;
    } stages[] = {
        {"level load", times.load_ms},        {"navmesh", times.navmesh_ms},
        {"link edges", r.milliseconds_edges}, {"take-off points", r.milliseconds_takeoff},
        {"jumps", r.milliseconds_jumps},      {"drops", r.milliseconds_drops},
        {"merge", r.milliseconds_merge},      {"links total", r.milliseconds_total},
    };
    for (const auto& item : stages) std::fprintf(out, "  %-26s %8.1f\n", item.stage, item.ms);
    std::fprintf(out, "  %-26s %8llu\n", "rays cast", static_cast<unsigned long long>(r.rays_cast));
    std::fprintf(out, "  %-26s %8llu\n", "box queries", static_cast<unsigned long long>(r.box_queries));
    std::fprintf(out, "  %-26s %8llu\n", "exact body tests", static_cast<unsigned long long>(r.body_tests));
}

}  // namespace nl::cli
