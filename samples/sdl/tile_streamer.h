// Tiles streamed around the agents the viewer follows, as an open-world host streams them around its
// player: of a tiled navmesh's tiles, only those within a radius of the followed agents stay loaded.
// A tile going out of range is saved first (nl_navmesh_save_tile: its polygons and the generated links
// it owns) and removed (nl_navmesh_remove_tile); a tile coming into range is added back from those
// bytes (nl_navmesh_add_tile_bytes: its links come back with it, none is generated again), or, when it
// has none, built again from the level over its square (nl_navmesh_build_tiles).
//
// An agent plans over the tiles loaded, so one sent beyond them could not be placed there: the viewer
// plans each followed agent's route over every tile before streaming (streamed_route), and sends it
// along that route to the farthest point the loaded tiles hold (waypoint_on_route), further as tiles
// come in, and to the destination itself once the tiles hold the rest of the way.
#pragma once

#include <navlink/navlink.h>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace nl::picture {

class TileStreamer {
public:
    using Point = std::array<float, 3>;

    // `navmesh` is tiled; the tiles loaded now are every tile it streams. `recast_json` and `body`
    // are what it was built with (for tiles built again). Throws SampleError.
    TileStreamer(nl_world* world, nl_navmesh_id navmesh, std::string recast_json, const nl_agent_type& body);

    struct Change {
        std::vector<nl_tile_coord> added, removed;
        bool empty() const { return added.empty() && removed.empty(); }
    };
    // Loads every tile within `radius` metres (seen from above) of one of `centres` and unloads the
    // others (never the last one). Throws SampleError.
    Change follow(const std::vector<Point>& centres, float radius);
    // Every tile loaded again. Throws SampleError.
    Change load_all();

    // Whether the tiles loaded hold (x, z) and every point within `margin` of it along x and z.
    bool holds(float x, float z, float margin) const;
    bool loaded(nl_tile_coord tile) const;
    size_t loaded_count() const { return loaded_.size(); }
    size_t total() const { return every_.size(); }
    float tile_width() const { return width_; }

    // Along the way: the most tiles loaded at once while streaming, and the tiles removed and added
    // (added from saved bytes or built again).
    struct Counts {
        size_t most_loaded = 0, removed = 0, added_from_bytes = 0, built = 0;
    };
    const Counts& counts() const { return counts_; }

private:
    using Key = std::pair<int32_t, int32_t>;
    bool within(const Key& tile, const std::vector<Point>& centres, float radius) const;
    void add(const Key& tile);
    void remove(const Key& tile);

    nl_world* world_;
    nl_navmesh_id navmesh_;
    std::string recast_json_;
    nl_agent_type body_;
    float width_ = 0.0f, origin_[2] = {0.0f, 0.0f};
    std::vector<Key> every_;                     // row order
    std::map<Key, bool> loaded_;                 // the tiles loaded now (the value is unused)
    std::map<Key, std::vector<uint8_t>> saved_;  // each removed tile's file, saved as it went
    Counts counts_;
};

// "+(3, 1) +(3, 2) -(0, 0)" (added, then removed).
std::string change_text(const TileStreamer::Change& change);

// A followed agent's way to its destination over every tile (nl_path_find's points), and how far
// along it the agent is.
struct StreamedRoute {
    std::vector<nl_path_point> points;
    std::array<float, 3> destination{};            // where the host sent it
    bool partial = false;                          // the route falls short of it: the agent goes as near as it can
    size_t segment = 0;                            // the route's segment the agent was last nearest (only grows)
    float along = 0.0f;                            // where along it (0: its start, 1: its end)
    std::optional<std::array<float, 3>> waypoint;  // where it was last sent along the route
    bool done = false;                             // sent to the destination itself
};

// The agent at `position` moves `route.segment` on to the segment of the route it is nearest now (of
// the few ahead: a route may pass the same place again later), and `route.along` to where on it.
void advance_on_route(StreamedRoute& route, const float position[3]);

// Where an agent on `route` is sent while `tiles` are loaded: the farthest point along the route, from
// where the agent is on it, that the loaded tiles hold (`margin` metres inside them) with every point
// before it (walks checked every quarter metre; past a link only when its landing is held); the
// destination itself (`final`) when they hold the rest of the way. None when they do not hold where
// the agent is.
struct Waypoint {
    std::array<float, 3> point;
    bool final;
};
std::optional<Waypoint> waypoint_on_route(const StreamedRoute& route, const TileStreamer& tiles, float margin);

}  // namespace nl::picture
