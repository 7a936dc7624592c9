// Worlds, levels and navmeshes for tests that drive the C++ core (nl::World) alone, with no C ABI:
// a procedural or OBJ level added as nl_mesh_add and nl_mesh_add_obj_file add it, a navmesh built
// by the Recast builder as nl_navmesh_build builds it, and cell-map navmeshes (cell_map.h). Core types
// only. The Recast builder is a C plugin, so core_world.cpp speaks the plugin ABI (plugin.h) to it, as
// the C layer's adapter does; it links navlink_recast_plugin, never the C ABI's objects.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "level_generator.h"
#include "links/link_snapshot.h"
#include "navmesh/navmesh_builder.h"
#include "world/world.h"

namespace nl::test {

// A world with `workers` threads for batch work and `path_workers` path threads (0: process() only).
std::unique_ptr<World> make_world(int workers = 1, unsigned path_workers = 0);

// Adds a procedural level's triangles to the world's level, as nl_mesh_add does (degenerate
// triangles skipped by the level).
Handle add_level(World& world, const levelgen::GeneratedLevel& level, uint32_t flags = 0,
                 const Transform& transform = Transform::Identity());
// Adds the triangles of an OBJ file, as nl_mesh_add_obj_file does.
Handle add_obj_file(World& world, const std::filesystem::path& path);

// The Recast builder (plugins/recast, the built-in builder of every C world) registered in `world`
// under its name, "recast", as a C++ plugin: once per world, later calls do nothing.
void add_recast_builder(World& world);
// Builds a navmesh for `agent` from the world's level with the Recast builder and its default
// settings (those in `settings_json` changed: {"tile_size": 32} builds tiles), and adds it: the
// navmesh nl_navmesh_build makes with nl_default_navmesh_build_def(). Throws as
// World::build_navmesh; a failure of the builder is an nl::Error with its code and reason.
Handle build_recast_navmesh(World& world, const AgentType& agent = AgentType{}, const std::string& settings_json = "");

// A world of `workers` threads holding `level` and the navmesh the Recast builder makes of it
// (default agent and settings): what the link generator's tests start from.
struct RecastWorld {
    std::unique_ptr<World> world;
    Handle navmesh;
    std::shared_ptr<const NavMesh> mesh;  // the navmesh itself
};
RecastWorld recast_world(const levelgen::GeneratedLevel& level, int workers);

// The navmesh's links as they are now, in the order added (a snapshot's links, as
// nl_navmesh_get_links lists them).
std::vector<StoredLink> links_of(const World& world, Handle navmesh);
// A progress callback that lets a generation run to the end.
inline constexpr auto keep_going = [](float, const char*) { return true; };
// The navmesh's links as a links file, and a links file loaded in their place (what
// nl_navmesh_save_links_json and nl_navmesh_load_links_json do); returns the count loaded.
std::string save_links_json(const World& world, Handle navmesh);
size_t load_links_json(World& world, Handle navmesh, const std::string& json);

// A host navmesh drawn as a map of 1 m cells (cell_map.h), for an agent of that radius: the input
// nl_navmesh_add makes of cell_navmesh.h's CellNavmesh def.
NavMeshInput cell_navmesh(const std::vector<std::string>& rows, float agent_radius);

// Whether two navmeshes are the same, bit for bit: vertices, corners, neighbours and tiles.
bool same_navmesh(const NavMesh& a, const NavMesh& b);

}  // namespace nl::test
