// What plugins give a world, as C++ interfaces: a navmesh builder and a link-kind provider. The core
// knows plugins only through these; capi/ adapts the C plugin ABI (capi/include/navlink/plugin.h)
// to them, and a C++ host or test may implement them directly.
#pragma once

#include <cstdint>
#include <memory>
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "links/link.h"
#include "navmesh/navmesh_builder.h"
#include "navmesh/tile_join.h"
#include "util/function_ref.h"
#include "util/handle.h"

namespace nl {

class World;

// What a navmesh build asks of a builder.
struct NavMeshBuildRequest {
    std::string builder;                     // the builder's name
    AgentType agent_type;                    // the body the navmesh is for
    Handle carrier;                          // a movable mesh to build on, in its own space; null: the static level
    const void* builder_settings = nullptr;  // the builder's own settings struct, borrowed; opaque here
    // The builder's settings as JSON text, borrowed; null: none. Handed over as given (a null text
    // with a length is the builder's to refuse).
    const char* settings_json = nullptr;
    size_t settings_json_length = 0;
    // Told of the build's progress (fraction 0..1, never going back; the stage's name); false
    // cancels the build. Empty: nobody asks.
    std::function<bool(float fraction, const char* stage)> progress;
    // Only these tiles of this grid (World::build_tiles), columns and rows > 0; otherwise the whole
    // navmesh (every tile of a tiled build).
    struct Tiles {
        TileGrid grid;
        TileCoord first;
        uint32_t columns = 0;
        uint32_t rows = 0;
        bool asked() const { return columns > 0 && rows > 0; }
    } only_tiles;
    // The triangles the world gathered for this build already (Level::triangles_to_build) and their
    // level_hash, borrowed for the build; null: the builder's host gathers them when asked.
    const BuildTriangles* level = nullptr;
    uint64_t level_hash = 0;
};

// What a builder hands back.
struct BuiltNavMesh {
    std::shared_ptr<const NavMesh> navmesh;
    // The settings it used, complete (its defaults filled in), as a JSON object; empty: not said (the
    // world then records the settings JSON it was given).
    std::string settings_used;
    // level_hash() of the triangles it built from, as it was handed them; 0: not said (the world then
    // hashes the level as it is when the build returns).
    uint64_t level_hash = 0;
    // For a navmesh built in tiles: the tiles it was joined from, in row order (what adding and
    // removing tiles joins again). For a request of only_tiles: those tiles that have polygons, and
    // no navmesh.
    TileInputs tiles;
};

class NavMeshBuilder {
public:
    virtual ~NavMeshBuilder() = default;
    // A navmesh for request.agent from the world's level geometry, made with build_navmesh. Throws
    // its own failures (bad settings: InvalidArgument or Parse; no walkable surface: NotFound), and
    // Internal when the polygons it made were refused (a builder bug, not the caller's).
    virtual BuiltNavMesh build(World& world, const NavMeshBuildRequest& request) = 0;
};

class LinkKindProvider {
public:
    virtual ~LinkKindProvider() = default;
    virtual uint32_t kind() const noexcept = 0;  // >= LinkKind::FirstPluginKind, unique in a world
    virtual const std::string& kind_name() const noexcept = 0;
    // Proposes links of this kind for `navmesh`, each through `accept`, which places it on the
    // navmesh (place_link) and throws when it does not fit (a provider over a C plugin tells the
    // plugin so); the World then refuses the whole generation. `settings_json`: the object given under
    // kind_name() in the generation's plugin settings, empty when none was. Throws its own failures.
    virtual void propose(World& world, Handle navmesh, const std::string& settings_json,
                         FunctionRef<void(Link)> accept) = 0;
};

struct PluginDescription {
    std::string name;  // unique in a world
    std::string version;
    std::string description;
    uint32_t abi_version = 0;  // the plugin ABI version it speaks (0 for a C++ plugin)
    bool builtin = false;      // compiled into the library
};

class Plugin {
public:
    virtual ~Plugin() = default;
    virtual const PluginDescription& description() const noexcept = 0;
    virtual NavMeshBuilder* navmesh_builder() noexcept { return nullptr; }
    virtual LinkKindProvider* link_kind() noexcept { return nullptr; }
};

}  // namespace nl
