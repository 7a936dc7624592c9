#include "links/tile_links.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "links/generation_stage.h"
#include "links/link_generation.h"
#include "navmesh/navmesh_builder.h"

namespace nl {
namespace {

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
    const float rim = s.falloff_distance / std::max(std::cos(s.permissive_forward_angle * generation::kDegrees), 1e-3f);
    const float walk = s.walk_factor * (s.max_jump_gap + 2.0f * rim) + s.walk_distance;
    return std::max(pair_reach, walk) + s.merge_distance;
}

TileCoord owner_tile(const TileGrid& grid, const Link& link) {
    return link.start_tile ? *link.start_tile : grid.tile_at(link.start.x(), link.start.z());
}

std::vector<TileCoord> tiles_within_reach(const TileGrid& grid, const std::vector<TileCoord>& loaded,
                                          const std::vector<TileCoord>& around, float reach) {
    // Each loaded tile looks for the tiles of `around` in the block of tiles its reach can meet (every
    // tile against every other was quadratic: 15 s of a 4 km world's 21 s link generation).
    std::vector<TileCoord> sorted = around;
    std::sort(sorted.begin(), sorted.end());
    const int64_t span = int64_t(std::ceil(double(reach) / grid.tile_width)) + 1;
    const bool few = double(2 * span + 1) * double(2 * span + 1) > double(sorted.size());
    std::vector<TileCoord> out;
    for (const TileCoord& t : loaded) {
        const auto within = [&](const TileCoord& a) {
            return apart(grid, t, grid.line_x(a.x), grid.line_x(int64_t(a.x) + 1), grid.line_z(a.z),
                         grid.line_z(int64_t(a.z) + 1)) <= reach;
        };
        // Fewer tiles around than in the block: each of them.
        bool near = few && std::any_of(sorted.begin(), sorted.end(), within);
        for (int64_t dz = -span; dz <= span && !near && !few; ++dz)
            for (int64_t dx = -span; dx <= span && !near; ++dx) {
                const int64_t x = t.x + dx, z = t.z + dz;
                if (std::fabs(double(x)) > kMaxTileIndex || std::fabs(double(z)) > kMaxTileIndex) continue;
                const TileCoord a{int32_t(x), int32_t(z)};
                near = std::binary_search(sorted.begin(), sorted.end(), a) && within(a);
            }
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
    std::vector<TileCoord> kept;  // the owners that are loaded: the others own nothing
    for (const TileCoord& owner : owners)
        if (std::binary_search(coords.begin(), coords.end(), owner)) kept.push_back(owner);
    std::sort(kept.begin(), kept.end());
    kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
    if (kept.empty()) return {};
    // One generation over every tile within reach of an owner: an owner's links are those a generation
    // over its own reach finds, and a wider one finds the same (links_tests: a tile at a time and all
    // at once agree bit for bit), so the owners near each other share the work.
    const std::vector<TileCoord> near = tiles_within_reach(grid, coords, kept, tile_link_reach(settings));
    std::vector<const NavMeshInput*> inputs;
    for (const auto& t : loaded)
        if (std::binary_search(near.begin(), near.end(), t->tiles.tiles.front())) inputs.push_back(t.get());
    const std::shared_ptr<const NavMesh> neighbourhood = build_navmesh(join_tiles(inputs));
    LinkGeneration generation(neighbourhood, settings, GenerationMethod::Indexed);
    const TileLayout& layout = neighbourhood->tiles();
    std::vector<Link> out;
    for (const Link& found : generation.run(level, tasks, report, progress)) {
        Link l = canonical(found);
        l.start_tile = layout.tiles[neighbourhood->tile_of(l.start_polygon)];
        l.end_tile = layout.tiles[neighbourhood->tile_of(l.end_polygon)];
        if (std::binary_search(kept.begin(), kept.end(), *l.start_tile)) out.push_back(l);
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const Link& a, const Link& b) { return *a.start_tile < *b.start_tile; });
    report.jump_links = static_cast<uint32_t>(
        std::count_if(out.begin(), out.end(), [](const Link& l) { return l.kind != LinkKind::Drop; }));
    report.drop_links = static_cast<uint32_t>(out.size()) - report.jump_links;
    return out;
}

}  // namespace nl
