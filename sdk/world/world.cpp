#include "world/world.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <string>

#include <nlohmann/json.hpp>

#include "io/json_input.h"
#include "io/navmesh_file.h"
#include "level/level_hash.h"
#include "links/link_placement.h"
#include "links/tile_links.h"

namespace nl {

World::World(WorldSettings settings)
    : handle_tag_(HandleTag::acquire()),
      logger_(std::move(settings.logger)),
      tasks_(settings.tasks ? std::move(settings.tasks) : make_tbb_task_system(settings.worker_count)),
      level_(std::make_unique<Level>(*tasks_, handle_tag_.value())),
      navmeshes_(handle_tag_.value()),
      plugins_(handle_tag_.value()),
      paths_(handle_tag_.value(), settings.path_worker_count),
      agents_(handle_tag_.value(), settings.agents) {}

World::~World() { paths_.shutdown(); }

void World::log_repairs(const NavMesh& navmesh) const {
    const NavMeshRepairs& r = navmesh.repairs();
    if (r.flipped_polygons || r.dropped_polygons || r.non_manifold_edges) {
        logger_.log(LogLevel::Warning,
                    concat("repaired the navmesh: ", r.flipped_polygons, " polygons turned to face up, ",
                           r.dropped_polygons, " degenerate polygons dropped, ", r.non_manifold_edges,
                           " edges shared by 3+ polygons left unconnected"));
    }
}

Transform World::carrier_placement(Handle carrier) const {
    MeshInfo info;
    try {
        info = level_->info(carrier);
    } catch (const Error& e) {
        if (e.code() != ErrorCode::InvalidHandle) throw;
        fail_field(ErrorCode::InvalidHandle, "carrier", ": ", e.what());
    }
    if (!(info.flags & kMeshMovable))
        fail_field(ErrorCode::InvalidArgument, "carrier",
                   " is not a movable mesh (NL_MESH_MOVABLE): only those carry navmeshes");
    if (!is_rigid(info.transform)) fail_field(ErrorCode::InvalidArgument, "carrier", "'s transform", kNotRigid);
    return info.transform;
}

Handle World::add_on_carrier(std::shared_ptr<const NavMesh> navmesh, Handle carrier, NavMeshProvenance made_for,
                             TileInputs tiles) {
    if (carrier == Handle{})
        return navmeshes_.add(std::move(navmesh), Handle{}, Transform::Identity(), std::move(made_for),
                              std::move(tiles));
    std::lock_guard lock(carrier_moves_);
    return navmeshes_.add(std::move(navmesh), carrier, carrier_placement(carrier), std::move(made_for),
                          std::move(tiles));
}

Handle World::add_navmesh(const NavMeshInput& input, Handle carrier) {
    if (carrier != Handle{}) {
        std::lock_guard lock(carrier_moves_);
        carrier_placement(carrier);  // a bad carrier before the polygons' work
    }
    // A host's tile is a tiled navmesh of one tile, which add_tile grows: joined as every tiled navmesh is,
    // so that it is the navmesh its tiles make whatever came and went.
    TileInputs tiles;
    if (input.tiles.grid.tiled() && input.tiles.tiles.size() == 1) {
        nl::build_navmesh(input);  // the tile's own fields, named as the caller gave them
        tiles.push_back(std::make_shared<NavMeshInput>(input));
    }
    std::shared_ptr<const NavMesh> navmesh = nl::build_navmesh(tiles.empty() ? input : join_tiles(tiles));
    log_repairs(*navmesh);
    return add_on_carrier(std::move(navmesh), carrier, {}, std::move(tiles));
}

namespace {

// A builder's run as the caller sees it: progress within 0..1 and never going back, whatever the
// builder reports, and a stop remembered: a builder that goes on after it still adds nothing.
class GuardedBuild {
public:
    explicit GuardedBuild(const NavMeshBuildRequest& request) : forwarded_(request), caller_(request.progress) {
        forwarded_.progress = [this](float fraction, const char* stage) {
            if (cancelled_) return false;
            if (std::isfinite(fraction)) reached_ = std::clamp(fraction, reached_, 1.0f);
            cancelled_ = caller_ && !caller_(reached_, stage ? stage : "building");
            return !cancelled_;
        };
        report(0.0f, "starting");
    }
    GuardedBuild(const GuardedBuild&) = delete;
    GuardedBuild& operator=(const GuardedBuild&) = delete;

    BuiltNavMesh run(NavMeshBuilder& builder, World& world) {
        BuiltNavMesh built;
        try {
            built = builder.build(world, forwarded_);
        } catch (const Error&) {
            fail_if_cancelled();  // a builder stopped by the callback may say so in its own words
            throw;
        }
        fail_if_cancelled();
        return built;
    }
    // Tells the caller (throws Cancelled when it asks to stop).
    void report(float fraction, const char* stage) {
        forwarded_.progress(fraction, stage);
        fail_if_cancelled();
    }

private:
    void fail_if_cancelled() const {
        if (cancelled_) fail(ErrorCode::Cancelled, "the navmesh build was cancelled by its progress callback");
    }

    NavMeshBuildRequest forwarded_;
    std::function<bool(float, const char*)> caller_;
    bool cancelled_ = false;
    float reached_ = 0.0f;
};

// The tiles of a tiled navmesh; InvalidArgument for a solo one.
TileInputs tiles_of(const NavMeshRegistry& navmeshes, Handle navmesh) {
    TileInputs tiles = navmeshes.tile_inputs(navmesh);
    if (tiles.empty())
        fail(ErrorCode::InvalidArgument,
             "the navmesh is not tiled: it was built, added or loaded whole (build it with a tile size, or add a "
             "tile)");
    return tiles;
}

// The movable mesh a navmesh rides; null for one that rides none.
Handle carrier_of(const NavMeshRegistry& navmeshes, Handle navmesh) {
    const auto frame = navmeshes.frame(navmesh);
    return frame ? frame->mesh() : Handle{};
}

std::string describe(const TileGrid& g) {
    return concat("tiles of ", g.tile_width, " m from (", g.origin_x, ", ", g.origin_z, ")");
}

}  // namespace

NavMeshBuilder& World::builder_named(const std::string& name) const {
    NavMeshBuilder* builder = plugins_.find_navmesh_builder(name);
    if (!builder)
        fail(ErrorCode::NotFound, "no navmesh builder named '", name,
             "' (loaded: ", listed_names(plugins_.navmesh_builder_names()), ")");
    return *builder;
}

void World::publish_tiles(Handle navmesh, TileInputs tiles, const std::vector<TileCoord>& arrived,
                          const TileLinks* given) {
    std::shared_ptr<const NavMesh> joined = nl::build_navmesh(join_tiles(tiles));
    const LastGeneration last = navmeshes_.last_generation(navmesh);
    // Paths were asked for on the navmesh: the new one's graph is built below, by the thread that
    // changed the tiles (a host's streaming), not by the next path request (a game's frame).
    const bool searched = navmeshes_.has_path_graph(navmesh);
    if (given || !last.tile_settings || arrived.empty()) {
        navmeshes_.replace_tiles(navmesh, std::move(tiles), std::move(joined), given);
    } else {
        // Links were generated on the navmesh: the tiles that arrived, and those within reach of them,
        // have theirs generated again over the tiles as they are now (tile_links.h), published with
        // the navmesh.
        TileLinks regenerated;
        regenerated.owners = tiles_within_reach(joined->tiles().grid, joined->tiles().tiles, arrived,
                                                tile_link_reach(*last.tile_settings));
        LinkGenerationReport report;
        regenerated.links = generate_tile_links(tiles, regenerated.owners, *level_, *tasks_, *last.tile_settings,
                                                report, [](float, const char*) { return true; });
        navmeshes_.replace_tiles(navmesh, std::move(tiles), std::move(joined), &regenerated);
    }
    if (!searched) return;
    try {
        navmeshes_.path_graph(navmesh);
    } catch (const std::bad_alloc&) {
        // The tiles are published; the next path request builds the graph, and says what failed.
    }
}

void World::add_tile(Handle navmesh, const NavMeshInput& tile, Handle carrier) {
    if (carrier != Handle{}) carrier_placement(carrier);  // a bad id is named as nl_navmesh_add names it
    const Handle rides = carrier_of(navmeshes_, navmesh);
    if (carrier != rides)
        fail_field(ErrorCode::InvalidArgument, "carrier: not the mesh the navmesh rides (",
                   rides != Handle{} ? "a tile's polygons are in its carrier's space: give the navmesh's carrier"
                                     : "the navmesh rides none: give the null id",
                   ")");
    nl::build_navmesh(tile);  // its own polygons and agent checked first, named as the caller gave them
    insert_tile(navmesh, tile, nullptr);
}

void World::insert_tile(Handle navmesh, const NavMeshInput& tile, const TileLinks* given) {
    const auto turn = navmeshes_.take_generation_turn(navmesh);
    TileInputs tiles = tiles_of(navmeshes_, navmesh);
    const NavMeshInput& first = *tiles.front();
    if (!tile.tiles.grid.tiled() || tile.tiles.tiles.size() != 1)
        fail_field(ErrorCode::InvalidArgument, "tile_width: the def is not a tile (tile_width is 0)");
    if (tile.tiles.grid != first.tiles.grid)
        fail_field(ErrorCode::InvalidArgument, "tile_width: the tile is on another grid (", describe(tile.tiles.grid),
                   ") than the navmesh's (", describe(first.tiles.grid), ")");
    if (!same_agent_type(tile.agent_type, first.agent_type))
        fail_field(ErrorCode::InvalidArgument, "agent_type: the tile was made for another agent type than the navmesh");
    const TileCoord at = tile.tiles.tiles.front();
    const auto place = std::lower_bound(tiles.begin(), tiles.end(), at,
                                        [](const auto& t, const TileCoord& c) { return t->tiles.tiles.front() < c; });
    if (place != tiles.end() && (*place)->tiles.tiles.front() == at)
        fail_field(ErrorCode::InvalidArgument, "tile_x, tile_z: tile (", at.x, ", ", at.z,
                   ") is loaded already: remove it first");
    tiles.insert(place, std::make_shared<NavMeshInput>(tile));
    publish_tiles(navmesh, std::move(tiles), {at}, given);
}

void World::build_tiles(Handle navmesh, NavMeshBuildRequest request, const Aabb& box) {
    NavMeshBuilder& builder = builder_named(request.builder);
    if (!within_coordinate_limit(box.min) || !within_coordinate_limit(box.max) || box.min.x() > box.max.x() ||
        box.min.z() > box.max.z())
        fail(ErrorCode::InvalidArgument, "the box is not finite, beyond the coordinate limit, or has min > max");
    naming_fields("agent_type.", [&] { validate_agent(request.agent_type); });
    const auto turn = navmeshes_.take_generation_turn(navmesh);
    TileInputs tiles = tiles_of(navmeshes_, navmesh);
    const NavMeshInput& first = *tiles.front();
    if (!same_agent_type(request.agent_type, first.agent_type))
        fail_field(ErrorCode::InvalidArgument, "agent_type: not the navmesh's agent type");
    const TileGrid& grid = first.tiles.grid;
    // Counted in doubles first: a box far off a grid of small tiles is refused, not clamped.
    const double x0 = std::floor((double(box.min.x()) - grid.origin_x) / grid.tile_width),
                 x1 = std::floor((double(box.max.x()) - grid.origin_x) / grid.tile_width),
                 z0 = std::floor((double(box.min.z()) - grid.origin_z) / grid.tile_width),
                 z1 = std::floor((double(box.max.z()) - grid.origin_z) / grid.tile_width);
    const double columns = x1 - x0 + 1.0, rows = z1 - z0 + 1.0;
    if (columns * rows > double(1 << 22) || std::fabs(x0) > kMaxTileIndex || std::fabs(x1) > kMaxTileIndex ||
        std::fabs(z0) > kMaxTileIndex || std::fabs(z1) > kMaxTileIndex)
        fail(ErrorCode::InvalidArgument, "the box holds ", columns, " x ", rows, " tiles from tile (", x0, ", ", z0,
             "); at most 2^22 at once, with indices within 2^30");
    const TileCoord lo{int32_t(x0), int32_t(z0)}, hi{int32_t(x1), int32_t(z1)};
    request.carrier = carrier_of(navmeshes_, navmesh);  // the level it was built from: its carrier's, or the static one
    request.only_tiles = NavMeshBuildRequest::Tiles{grid, lo, uint32_t(columns), uint32_t(rows)};
    GuardedBuild guarded(request);
    BuiltNavMesh built = guarded.run(builder, *this);
    const auto in_box = [&](const auto& t) {
        const TileCoord at = t->tiles.tiles.front();
        return at.x >= lo.x && at.x <= hi.x && at.z >= lo.z && at.z <= hi.z;
    };
    for (const auto& tile : built.tiles) {
        if (tile->tiles.grid != grid || !in_box(tile))
            fail(ErrorCode::Internal, "builder '", request.builder, "' handed over tile (", tile->tiles.tiles.front().x,
                 ", ", tile->tiles.tiles.front().z, ") of ", describe(tile->tiles.grid), ", not one asked for");
    }
    // The tiles outside the box stay; those in it are what the builder made of them now.
    const size_t loaded = tiles.size();
    tiles.erase(std::remove_if(tiles.begin(), tiles.end(), in_box), tiles.end());
    if (tiles.size() == loaded && built.tiles.empty()) return;  // nothing there, before or now
    tiles.insert(tiles.end(), built.tiles.begin(), built.tiles.end());
    sort_in_row_order(tiles);
    if (tiles.empty())
        fail(ErrorCode::InvalidArgument,
             "no tile would be left: the box held every tile, and none has a walkable "
             "surface now (remove the navmesh instead)");
    guarded.report(1.0f, "joining the tiles");
    std::vector<TileCoord> arrived;
    for (const auto& tile : built.tiles) arrived.push_back(tile->tiles.tiles.front());
    publish_tiles(navmesh, std::move(tiles), arrived);
}

void World::remove_tile(Handle navmesh, TileCoord coord) {
    const auto turn = navmeshes_.take_generation_turn(navmesh);
    TileInputs tiles = tiles_of(navmeshes_, navmesh);
    const auto found =
        std::find_if(tiles.begin(), tiles.end(), [&](const auto& t) { return t->tiles.tiles.front() == coord; });
    if (found == tiles.end()) fail(ErrorCode::NotFound, "no tile (", coord.x, ", ", coord.z, ") is loaded");
    if (tiles.size() == 1)
        fail(ErrorCode::InvalidArgument, "tile (", coord.x, ", ", coord.z,
             ") is the navmesh's last: remove the navmesh instead");
    tiles.erase(found);
    // Its generated links go with it (they come back with it: from its file, or generated again).
    const TileLinks none{{coord}, {}};
    publish_tiles(navmesh, std::move(tiles), {}, &none);
}

Handle World::add_agent(AgentDef def) {
    if (within_coordinate_limit(def.position)) {
        const Ray down{def.position + Vec3(0.0f, 0.5f, 0.0f), Vec3(0.0f, -1.0f, 0.0f), 3.0f};
        RayHit hit;
        level_->cast_rays(&down, 1, &hit);
        if (hit.hit && navmeshes_.contains(def.navmesh)) {
            const auto navmesh = navmeshes_.navmesh(def.navmesh);
            const Handle on = navmeshes_.riding(hit.mesh, navmesh->agent());
            if (on != Handle{}) def.navmesh = on;
        }
    }
    const Handle agent = agents_.add(navmeshes_, def);
    warn_if_wider_than_navmesh(def);
    return agent;
}

void World::warn_if_wider_than_navmesh(const AgentDef& def) {
    float navmesh_radius = 0.0f;
    try {
        const auto navmesh = navmeshes_.navmesh(def.navmesh);
        navmesh_radius = navmesh->agent().radius;
    } catch (const Error& e) {
        if (e.code() != ErrorCode::InvalidHandle) throw;
        return;  // removed since the agent was added: nothing to say of it
    }
    const float radius = def.capabilities.radius;
    if (!(radius > navmesh_radius)) return;
    {
        std::lock_guard lock(wide_bodies_mutex_);
        if (!wide_bodies_warned_.insert({def.navmesh.packed(), radius}).second) return;
    }
    logger_.log(
        LogLevel::Warning,
        concat("agents of radius ", radius, " m on a navmesh built for radius ", navmesh_radius, " m (nl_navmesh_id {",
               def.navmesh.index1 & kHandleSlotMask, ", ", def.navmesh.revision, "}) keep ", radius - navmesh_radius,
               " m more from walls than the navmesh's edges, and cannot pass where the navmesh is narrower than ",
               2.0f * (radius - navmesh_radius),
               " m of width; when their paths fall short, nl_path_explain says "
               "whether that is why (a navmesh built for their radius serves them best)"));
}

void World::set_mesh_transform(Handle mesh, const Transform& transform) {
    std::lock_guard lock(carrier_moves_);
    if (navmeshes_.carried_by(mesh) && !is_rigid(transform))
        fail_field(ErrorCode::InvalidArgument, "transform", kNotRigid);
    level_->set_transform(mesh, transform);
    navmeshes_.move_carrier(mesh, transform);
}

void World::remove_mesh(Handle mesh) {
    std::lock_guard lock(carrier_moves_);
    if (navmeshes_.carried_by(mesh))
        fail(ErrorCode::InvalidArgument, "the mesh carries a navmesh (it rides the mesh): remove the navmesh first");
    level_->remove_mesh(mesh);
}

namespace {

// What builder `name` said it used, as a compact JSON object; Internal (a builder bug) for anything else.
std::string settings_record(const std::string& name, const std::string& said) {
    nlohmann::json used;
    try {
        used = parse_json(said, "the settings it used");
    } catch (const Error& e) {
        fail(ErrorCode::Internal, "builder '", name, "' said it used settings that are not JSON: ", e.what());
    }
    if (!used.is_object())
        fail(ErrorCode::Internal, "builder '", name,
             "' said it used settings that are not a JSON object: ", json_excerpt(used));
    return used.dump();
}

}  // namespace

Handle World::build_navmesh(const NavMeshBuildRequest& request) {
    NavMeshBuilder& builder = builder_named(request.builder);
    if (request.carrier != Handle{}) {
        std::lock_guard lock(carrier_moves_);
        carrier_placement(request.carrier);
    }
    // Said before the build: a level in the wrong units can take long to build, or fail for it.
    const BuildTriangles triangles = level_->triangles_to_build(request.carrier);
    const uint64_t built_from = level_hash(triangles);
    NavMeshProvenance made_for;
    warn_of_level(triangles, built_from, request.agent_type, made_for);
    NavMeshBuildRequest shown = request;  // the builder is shown what was just read, not a second copy
    shown.level = &triangles;
    shown.level_hash = built_from;
    GuardedBuild guarded(shown);
    BuiltNavMesh built = guarded.run(builder, *this);
    if (!built.navmesh)
        fail(ErrorCode::Internal, "builder '", request.builder, "' succeeded without handing over a navmesh");
    made_for.builder = request.builder;
    if (!built.settings_used.empty()) {
        made_for.builder_settings = settings_record(request.builder, built.settings_used);
    } else if (request.settings_json) {
        made_for.builder_settings.assign(request.settings_json, request.settings_json_length);
    }
    std::shared_ptr<const NavMesh> navmesh = std::move(built.navmesh);
    log_repairs(*navmesh);
    made_for.level_hash = built.level_hash != 0 ? built.level_hash : built_from;
    guarded.report(1.0f, "adding the navmesh");
    return add_on_carrier(std::move(navmesh), request.carrier, std::move(made_for), std::move(built.tiles));
}

Handle World::load_navmesh(const NavMeshFile& file, Handle carrier) {
    if (carrier != Handle{}) {
        std::lock_guard lock(carrier_moves_);
        carrier_placement(carrier);
    }
    if (file.rides_carrier != (carrier != Handle{}))
        fail_field(ErrorCode::InvalidArgument, "carrier: ",
                   file.rides_carrier
                       ? "the file's navmesh rode a moving mesh (its coordinates are in that mesh's space): "
                         "give the mesh it rides"
                       : "the file's navmesh rode no moving mesh (its coordinates are in the world)");
    // What the file holds is not the caller's input: its failures say so, and are about no field.
    const auto in_the_file = [](const std::string& what, auto&& fn) {
        try {
            return fn();
        } catch (const Error& e) {
            throw Error(e.code(), concat("the file's ", what, e.what()));
        }
    };
    // A tile's file: a tiled navmesh of that tile (add_tile_file adds the others).
    TileInputs tiles;
    if (file.is_tile) tiles.push_back(std::make_shared<NavMeshInput>(file.navmesh));
    std::shared_ptr<const NavMesh> navmesh =
        in_the_file("navmesh: ", [&] { return nl::build_navmesh(tiles.empty() ? file.navmesh : join_tiles(tiles)); });
    log_repairs(*navmesh);
    std::vector<Link> links = file.links;
    for (size_t i = 0; i < links.size(); ++i)
        if (!file.is_tile ||
            (links[i].start_tile == links[i].end_tile && *links[i].end_tile == navmesh->tiles().tiles[0]))
            in_the_file(concat("links[", i, "]."), [&] { place_saved_link(*navmesh, links[i]); });
    // (a tile's link to another tile is parked until that tile is added)
    const Handle h = add_on_carrier(std::move(navmesh), carrier, file.made_for, std::move(tiles));
    try {
        navmeshes_.replace_links(h, links, file.made_for.links);
    } catch (...) {
        navmeshes_.remove(h);  // out of memory: the world keeps what it had
        throw;
    }
    return h;
}

}  // namespace nl
