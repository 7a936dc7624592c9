// nl::World: the owner of everything a NavLink world holds, and the one composition root of the core.
// The C layer holds a pointer to one and maps ids and structs; agents and moving surfaces plug in
// here (docs/architecture.md, "The world").
//
// What it owns, created in this order and destroyed in reverse: the tag its handles carry, the task
// system (batch work), the level (Embree scene of the host's meshes), the navmeshes with everything
// that belongs to each (NavMeshRegistry: links, last generation, path graph, under one lock), the
// plugins, the path queue (its workers stop first) and the agents.
//
// Thread-safety: every method may be called from any thread at once, except the destructor, which
// must not run with any other call. Methods here span several parts (a build uses a plugin and adds a
// navmesh; a generation reads the level and stores links); the parts' own methods (level(),
// navmeshes(), paths()) are thread-safe as documented on them.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "agents/agents.h"
#include "level/level.h"
#include "level/frame_check.h"
#include "level/winding_check.h"
#include "links/generate_links.h"
#include "links/link_settings.h"
#include "path/path_queue.h"
#include "util/handle_tag.h"
#include "util/log.h"
#include "util/task_system.h"
#include "registry/navmesh_registry.h"
#include "world/plugin_registry.h"
#include "io/plugin_settings.h"

namespace nl {

struct NavMeshFile;
struct LinksFile;

struct WorldSettings {
    int worker_count = 1;            // threads for batch work, the caller included (>= 1)
    unsigned path_worker_count = 0;  // threads that plan queued path requests; 0: PathQueue::process only
    AgentsSettings agents;
    Logger logger;
    std::unique_ptr<TaskSystem> tasks;  // the host's scheduler; null: TBB with worker_count threads
};

class World {
public:
    // Throws OutOfMemory when every handle tag is held by a live world.
    explicit World(WorldSettings settings);
    // Stops the path queue first (queued requests finish as cancelled; their callbacks may still use
    // the queue), then destroys the plugins, the navmeshes, the level and the task system.
    ~World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    uint32_t handle_tag() const noexcept { return handle_tag_.value(); }
    const Logger& logger() const noexcept { return logger_; }
    TaskSystem& tasks() const noexcept { return *tasks_; }  // runs work; holds none of the world's state
    Level& level() noexcept { return *level_; }
    const Level& level() const noexcept { return *level_; }
    NavMeshRegistry& navmeshes() noexcept { return navmeshes_; }
    const NavMeshRegistry& navmeshes() const noexcept { return navmeshes_; }
    PluginRegistry& plugins() noexcept { return plugins_; }
    const PluginRegistry& plugins() const noexcept { return plugins_; }
    PathQueue& paths() noexcept { return paths_; }
    const PathQueue& paths() const noexcept { return paths_; }
    Agents& agents() noexcept { return agents_; }
    const Agents& agents() const noexcept { return agents_; }

    // Adds an agent (Agents::add) where it stands: when a ray down from def.position (from half a
    // metre above, 3 m long) first meets a movable mesh that a navmesh for the same body as
    // def.navmesh rides, the agent goes on that navmesh (it rides the platform it was put on).
    Handle add_agent(AgentDef def);

    // Advances every agent by dt seconds on the world's task system (Agents::step).
    void step(float dt) { agents_.step(dt, navmeshes_, *level_, *tasks_); }

    // A host's navmesh: validated, repaired (logged as a warning) and added. Throws as build_navmesh.
    // `carrier`: the movable mesh it rides (null: none); its polygons are then in that mesh's own
    // space, and it follows the mesh's transform. Throws InvalidArgument (about "carrier") for a mesh
    // that is not movable or whose transform is not rigid, InvalidHandle for a stale one.
    Handle add_navmesh(const NavMeshInput& input, Handle carrier = Handle{});
    // Builds a navmesh with the named builder plugin from the level (request.carrier: from that
    // movable mesh in its own space, riding it) and adds it. Throws NotFound (no such builder) and the
    // builder's failures.
    Handle build_navmesh(const NavMeshBuildRequest& request);
    // Adds a baked navmesh and its links (read_navmesh_file), on `carrier` for a file whose navmesh
    // rode one (its coordinates are in that mesh's space). Every link is placed before anything is
    // added (place_saved_link; "links[i].start" named); nothing changes when anything is refused:
    // InvalidArgument (a carrier given for a file that rode none, or none for one that did; the
    // polygons, as add_navmesh), InvalidHandle (the carrier).
    Handle load_navmesh(const NavMeshFile& file, Handle carrier = Handle{});

    // Tiles of a tiled navmesh (built in tiles, or added from a tile), each change one step for
    // everything else (NavMeshRegistry::replace_tiles): paths in flight finish on the navmesh they
    // started on; agents standing on a removed tile wait (AgentReason::TileUnloaded) until it is back,
    // those whose path crossed it plan again; a link with an end on a removed tile is out of every path
    // until the tile is back. The navmesh is joined again from its tiles (tile_join.h) whatever the
    // order they came in. Adds `tile` (its place in tile.tiles, on the navmesh's grid, for its agent
    // type). Throws InvalidArgument: a navmesh that is not tiled, a tile of another grid or agent type,
    // a tile loaded already at that place (remove it first), the tile's polygons (as add_navmesh);
    // InvalidHandle for a navmesh removed meanwhile.
    // `carrier`: the mesh the tile's polygons are in the space of, which must be the navmesh's carrier
    // (null for a navmesh that rides none): InvalidHandle (about "carrier") for a stale one,
    // InvalidArgument for another.
    void add_tile(Handle navmesh, const NavMeshInput& tile, Handle carrier = Handle{});
    // Removes the tile at `coord`. Throws NotFound when no tile is loaded there, InvalidArgument for a
    // navmesh that is not tiled or for its last tile (remove the navmesh instead).
    void remove_tile(Handle navmesh, TileCoord coord);
    // Baked tiles (tile_bake.cpp). The file of the tile at `coord` (navmesh_file.h, write_tile_file):
    // its polygons as built or handed over, the generated links it owns, what it was made for, and
    // its content hash (tile_content_hash). Throws NotFound (no tile there), InvalidArgument (a
    // navmesh that is not tiled, or rides a moving mesh: save it whole).
    std::vector<uint8_t> save_tile(Handle navmesh, TileCoord coord) const;
    // Adds the tile a tile's file holds, with its links, as add_tile (no link is generated: they come
    // with it). Throws InvalidArgument as add_tile, and for a file that is not a tile's, or a tile
    // made with another builder, builder settings or link settings than the navmesh.
    void add_tile_file(Handle navmesh, const NavMeshFile& file);
    // The hash of everything the tile at `coord` of the navmesh's grid is made from as the world holds
    // it now: the level's triangles in the columns its links and its neighbours' polygons can reach,
    // the builder and its settings, the link settings and the body. Never 0.
    uint64_t tile_content_hash(Handle navmesh, TileCoord coord) const;
    // Builds the tiles of the navmesh's grid that overlap `box` (x-z) with the builder of `request`
    // (only_tiles is set from the navmesh), and puts them in as one step: loaded tiles there are
    // replaced, those that come out empty removed. Throws InvalidArgument (a navmesh that is not
    // tiled, a box not finite or of more than 2^22 tiles, another agent type, tiles of another width
    // from the builder, no tile left), NotFound (no such builder), Cancelled, the builder's failures.
    void build_tiles(Handle navmesh, NavMeshBuildRequest request, const Aabb& box);

    // Moves a mesh, and the navmeshes that ride it with it (no rebuild, no new snapshot). A mesh that
    // carries a navmesh takes rigid transforms only (InvalidArgument otherwise, nothing moved).
    void set_mesh_transform(Handle mesh, const Transform& transform);
    // Removes a mesh; one that carries a navmesh is refused (InvalidArgument): remove the navmesh first.
    void remove_mesh(Handle mesh);

    // Links made outside the generator (the host's), placed on their navmesh (place_link; a bad end
    // is a failure about the field "start" or "end").
    Handle add_link(Handle navmesh, Link link);
    void update_link(Handle link, Link replacement);
    // A link and its navmesh, the link in world space (on a navmesh that rides a moving mesh, where
    // the mesh is now). Links of such a navmesh are added and updated in world space too, and kept in
    // the mesh's space; links files hold them in the mesh's space. A link whose landing_navmesh is
    // set leads to that navmesh (a cross link: start and end each kept in its navmesh's space, the
    // place it was added at remembered; one-way; InvalidHandle about "landing_navmesh" for a stale
    // one, InvalidArgument for its own navmesh, a two-way link or a bad tolerance).
    std::pair<Handle, Link> link_in_world(Handle link) const;
    // A link of `navmesh` (as stored) in world space now.
    Link in_world(Handle navmesh, const Link& link) const;
    // Whether a link of `navmesh` can be taken as its navmeshes stand now (cross_link_holds; always
    // for a link within one navmesh).
    bool link_holds(Handle navmesh, const Link& link) const;
    // The navmesh's pose now; the identity for one that rides nothing or is gone.
    CarrierPose navmesh_pose(Handle navmesh) const;
    // Replaces every link of the navmesh with those of a links file made with `made_with` (empty:
    // not said) (place_saved_link; an end off the navmesh is a failure about
    // "links[i].start"); nothing changes when one is refused.
    void load_links(Handle navmesh, std::vector<Link> links, LinkProvenance made_with = {});
    // The same for a links file that may say the body its links were generated for: one made for
    // another body than the navmesh's (same_body) is refused (InvalidArgument, both bodies named), or,
    // with `any_body`, loaded with a warning to the log.
    void load_links_file(Handle navmesh, LinksFile file, bool any_body);

    // Generates the navmesh's links (jumps, drops, and each link-kind plugin's) against the level and
    // replaces its generated links with them; manual links stay. The generation is kept for
    // update_links_in_box. Throws InvalidHandle (also when the navmesh was removed meanwhile: nothing
    // is kept), Cancelled (progress said stop: nothing changes), InvalidArgument (settings; plugin
    // settings for a kind no loaded plugin provides, found before any work; a call from inside another
    // generation's callbacks), and Internal naming a plugin that failed.
    LinkGenerationReport generate_links(Handle navmesh, const LinkSettings& settings, PluginSettings plugin_settings,
                                        GenerationProgress progress);
    // Generates the jumps and drops between two navmeshes (either may ride a moving mesh) for where
    // they stand now, each way, as cross links that hold within `tolerance` of this placement, and
    // replaces the generated cross links between the two that hold now (made for this placement)
    // with them; those made for another placement (a platform's other stop) and the navmeshes' own
    // links stay. Only the
    // polygons within a link's reach of the other navmesh are looked at, so a platform's links cost
    // what its neighbourhood does: call it when a carrier comes to rest, or has moved beyond the
    // tolerance, as often as the host likes. Both navmeshes must be made for the same body. Throws
    // InvalidHandle, InvalidArgument (one navmesh twice, another body, a bad tolerance), Cancelled
    // (nothing changes). Two calls for the same pair at once store one's result or the other's, whole.
    LinkGenerationReport generate_cross_links(Handle first, Handle second, const LinkSettings& settings,
                                              float tolerance, GenerationProgress progress);
    // Generates again what level geometry inside `box` can have changed, continuing the last
    // generation (the plugins' links are proposed again in full). Throws InvalidArgument for a box
    // not finite, beyond the coordinate limit or inverted, NotFound when there is no generation to
    // continue (never generated, or its links removed or replaced since), and as generate_links.
    LinkGenerationReport update_links_in_box(Handle navmesh, const Aabb& box, GenerationProgress progress);
    // InvalidArgument naming a kind of `settings` that no loaded link-kind plugin provides: settings
    // for a plugin that is not there would change nothing, silently (a misspelt or unloaded one).
    // generate_links checks its own; a caller that takes plugin settings without running the plugins
    // (cross links) checks them the same way.
    void check_plugin_settings(const PluginSettings& settings) const;

private:
    // The link-kind plugins' links for `mesh`, and what ran (LinkProvenance::plugins).
    struct PluginLinks {
        std::vector<Link> links;
        std::string made_with;
    };
    PluginLinks plugin_links(Handle navmesh, const NavMesh& mesh, const PluginSettings& settings,
                             LinkGenerationReport& report);
    void log_repairs(const NavMesh& navmesh) const;
    // What a build's input looks wrong in (winding_check.h, frame_check.h), each said in a warning
    // in the log: the meshes that look wound clockwise, and NavMeshProvenance::warnings.
    // `hash`: level_hash(triangles). The estimates behind the warnings are kept, by what they were
    // made from, for the next build: a rebuild of a level that did not change measures nothing again.
    void warn_of_level(const BuildTriangles& triangles, uint64_t hash, const AgentType& agent,
                       NavMeshProvenance& made_for);
    std::vector<Handle> warn_turned_over(const BuildTriangles& triangles, const AgentType& agent);
    uint32_t warn_of_frame(const BuildTriangles& triangles, uint64_t hash, const AgentType& agent);
    // InvalidArgument for a navmesh that rides a moving mesh: the generator proves links against the
    // level as it stands, so they would hold at one placement only.
    void refuse_generation_on_carrier(Handle navmesh) const;
    // Puts a host's link (world space) on its navmesh, or across to its landing navmesh.
    void place_host_link(Handle navmesh, Link& link) const;
    // The carrier's transform now, checked as a navmesh's placement; needs carrier_moves_ held.
    Transform carrier_placement(Handle carrier) const;
    // The navmesh builder plugin called `name`; NotFound naming those loaded.
    NavMeshBuilder& builder_named(const std::string& name) const;
    // Joins `tiles` (under the navmesh's generation turn) and publishes the navmesh they make in its
    // place, with the links of the tiles within reach of those that `arrived` generated again if the
    // navmesh's links were generated tile by tile.
    // `given`: the links of tiles given with them (a baked tile's; a removed tile's: none), which
    // replace those tiles' generated links instead of a generation. When paths were asked for on the
    // navmesh, the new navmesh's path graph is built before returning.
    void publish_tiles(Handle navmesh, TileInputs tiles, const std::vector<TileCoord>& arrived,
                       const TileLinks* given = nullptr);
    // add_tile after its caller's own checks, with the tile's links if given.
    void insert_tile(Handle navmesh, const NavMeshInput& tile, const TileLinks* given);
    Handle add_on_carrier(std::shared_ptr<const NavMesh> navmesh, Handle carrier, NavMeshProvenance made_for = {},
                          TileInputs tiles = {});

    HandleTag handle_tag_;  // released last, after every handle it tagged
    Logger logger_;
    std::unique_ptr<TaskSystem> tasks_;
    std::unique_ptr<Level> level_;
    NavMeshRegistry navmeshes_;
    PluginRegistry plugins_;
    PathQueue paths_;
    Agents agents_;
    // Mesh moves and removals, and navmeshes placed on a mesh, one at a time: a mesh and the
    // navmeshes riding it never end in different places.
    std::mutex carrier_moves_;
    // The (navmesh, body radius) pairs warned of as a body wider than its navmesh's: once each, so
    // a thousand tanks on a navmesh for people say it once. Owned by add_agent, under its mutex.
    std::mutex wide_bodies_mutex_;
    std::set<std::pair<uint64_t, float>> wide_bodies_warned_;  // (Handle::packed(), radius)
    // The estimates behind a build's warnings, by what each was made from: per mesh, its winding
    // (the mesh, the hash of its triangles as built, the body's max slope and height); per level, its
    // frame (the level's hash, which of its meshes said their units and up axis, the body). A build does not
    // measure what did not change again (the house level of 4,500 triangles: 7 ms a build). Owned
    // by warn_turned_over and warn_of_frame, under this mutex; each emptied past kMaxEstimates.
    std::mutex estimates_mutex_;
    std::map<std::tuple<uint64_t, uint64_t, float, float>, WindingEstimate> winding_estimates_;
    std::map<std::tuple<uint64_t, uint64_t, float, float>, FrameEstimate> frame_estimates_;
    static constexpr size_t kMaxEstimates = 1 << 16;
    void warn_if_wider_than_navmesh(const AgentDef& def);
};

}  // namespace nl
