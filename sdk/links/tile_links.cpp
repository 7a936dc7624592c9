#include "links/tile_links.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "links/link_generation.h"
#include "navmesh/navmesh_builder.h"

namespace nl {
namespace {

constexpr float kDegrees = 3.14159265358979f / 180.0f;

// A jump is found from whichever of its ends the generation sampled first, which differs between two
// tiles' generations: it is turned to start at its lower end in (x, z, y) order, so that one tile, and
// the same one whoever found it, owns it. A drop starts at its top in every generation.
Link canonical(Link l) {
    const auto order = [](const Vec3& p) { return std::make_tuple(p.x(), p.z(), p.y()); };
    if (l.kind != LinkKind::Jump || !l.bidirectional || order(l.start) <= order(l.end)) return l;
    std::swap(l.start, l.end);
    std::swap(l.start_polygon, l.end_polygon);
    std::swap(l.requirements.rise, l.requirements.drop);
    return l;
}

void add(LinkGenerationReport& total, const LinkGenerationReport& one) {
    for (uint32_t LinkGenerationReport::*count :
         {&LinkGenerationReport::edges, &LinkGenerationReport::groups, &LinkGenerationReport::samples,
          &LinkGenerationReport::takeoff_points, &LinkGenerationReport::jump_candidates,
          &LinkGenerationReport::drop_candidates, &LinkGenerationReport::rejected_wall,
          &LinkGenerationReport::rejected_not_ledge, &LinkGenerationReport::rejected_distance,
          &LinkGenerationReport::rejected_rise, &LinkGenerationReport::rejected_angle,
          &LinkGenerationReport::rejected_no_landing, &LinkGenerationReport::rejected_clearance,
          &LinkGenerationReport::rejected_duplicate, &LinkGenerationReport::rejected_walkable,
          &LinkGenerationReport::rejected_too_shallow, &LinkGenerationReport::rejected_too_deep})
        total.*count += one.*count;
    for (uint64_t LinkGenerationReport::*count :
         {&LinkGenerationReport::rays_cast, &LinkGenerationReport::box_queries, &LinkGenerationReport::body_tests})
        total.*count += one.*count;
    for (double LinkGenerationReport::*ms :
         {&LinkGenerationReport::milliseconds_edges, &LinkGenerationReport::milliseconds_takeoff,
          &LinkGenerationReport::milliseconds_jumps, &LinkGenerationReport::milliseconds_drops,
          &LinkGenerationReport::milliseconds_merge, &LinkGenerationReport::milliseconds_total})
        total.*ms += one.*ms;
}

// The x-z distance from a tile's square to a box.
double apart(const TileGrid& grid, const TileCoord& t, double min_x, double max_x, double min_z, double max_z) {
    const double dx = std::max({0.0, grid.line_x(t.x) - max_x, min_x - grid.line_x(int64_t(t.x) + 1)});
    const double dz = std::max({0.0, grid.line_z(t.z) - max_z, min_z - grid.line_z(int64_t(t.z) + 1)});
    return std::hypot(dx, dz);
}

}  // namespace

float tile_link_reach(const LinkSettings& s) {
    // A jump's other end: as far as JumpFinding's pair reach. A walk that makes a jump needless:
    // walk_factor x the longest candidate (its gap plus both rims, each at most falloff_distance out
    // along the permissive forward angle) + walk_distance. Links within merge_distance of each other
    // are one, so that much more.
    const float pair_reach = 2.0f * s.max_jump_gap + 2.0f * s.falloff_distance + s.max_jump_up;
    const float rim = s.falloff_distance / std::max(std::cos(s.permissive_forward_angle * kDegrees), 1e-3f);
    const float walk = s.walk_factor * (s.max_jump_gap + 2.0f * rim) + s.walk_distance;
    return std::max(pair_reach, walk) + s.merge_distance;
}

TileCoord owner_tile(const TileGrid& grid, const Link& link) {
    return link.start_tile ? *link.start_tile : grid.tile_at(link.start.x(), link.start.z());
}

std::vector<TileCoord> tiles_within_reach(const TileGrid& grid, const std::vector<TileCoord>& loaded,
                                          const std::vector<TileCoord>& around, float reach) {
    std::vector<TileCoord> out;
    for (const TileCoord& t : loaded) {
        const bool near = std::any_of(around.begin(), around.end(), [&](const TileCoord& a) {
            return apart(grid, t, grid.line_x(a.x), grid.line_x(int64_t(a.x) + 1), grid.line_z(a.z),
                         grid.line_z(int64_t(a.z) + 1)) <= reach;
        });
        if (near) out.push_back(t);
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<TileCoord> tiles_within_reach(const TileGrid& grid, const std::vector<TileCoord>& loaded, const Aabb& box,
                                          float reach) {
    std::vector<TileCoord> out;
    for (const TileCoord& t : loaded)
        if (apart(grid, t, box.min.x(), box.max.x(), box.min.z(), box.max.z()) <= reach) out.push_back(t);
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<Link> generate_tile_links(const TileInputs& loaded, const std::vector<TileCoord>& owners,
                                      const Level& level, TaskSystem& tasks, const LinkSettings& settings,
                                      LinkGenerationReport& report, GenerationProgress progress) {
    validate(settings);
    report = LinkGenerationReport{};
    if (loaded.empty()) return {};
    const TileGrid grid = loaded.front()->tiles.grid;
    std::vector<TileCoord> coords;
    for (const auto& t : loaded) coords.push_back(t->tiles.tiles.front());
    std::sort(coords.begin(), coords.end());
    std::vector<TileCoord> sorted_owners = owners;
    std::sort(sorted_owners.begin(), sorted_owners.end());
    const float reach = tile_link_reach(settings);
    std::vector<Link> out;
    for (size_t n = 0; n < sorted_owners.size(); ++n) {
        const TileCoord owner = sorted_owners[n];
        if (!std::binary_search(coords.begin(), coords.end(), owner)) continue;  // not loaded: it owns nothing
        const std::vector<TileCoord> near = tiles_within_reach(grid, coords, {owner}, reach);
        std::vector<const NavMeshInput*> inputs;
        for (const auto& t : loaded)
            if (std::binary_search(near.begin(), near.end(), t->tiles.tiles.front())) inputs.push_back(t.get());
        const std::shared_ptr<const NavMesh> neighbourhood = build_navmesh(join_tiles(inputs));
        // Each tile's share of the progress, in order.
        auto within = [&](float fraction, const char* stage) {
            return progress((float(n) + fraction) / float(sorted_owners.size()), stage);
        };
        LinkGeneration generation(neighbourhood, settings, GenerationMethod::Indexed);
        LinkGenerationReport one;
        const TileLayout& layout = neighbourhood->tiles();
        for (const Link& found : generation.run(level, tasks, one, within)) {
            Link l = canonical(found);
            l.start_tile = layout.tiles[neighbourhood->tile_of(l.start_polygon)];
            l.end_tile = layout.tiles[neighbourhood->tile_of(l.end_polygon)];
            if (owner_tile(grid, l) != owner) continue;
            (l.kind == LinkKind::Drop ? report.drop_links : report.jump_links) += 1;
            out.push_back(l);
        }
        add(report, one);
    }
    return out;
}

}  // namespace nl
