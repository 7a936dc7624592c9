// What a picture shows: a level's triangles, its navmesh (polygons, outline, links), the platforms
// that move, paths of agents and marked points. Plain data read through the C ABI; the renderer only
// draws it.
#pragma once

#include <navlink/navlink.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "level.h"
#include "navmesh_contents.h"

namespace nl::picture {

struct Rgba {
    uint8_t r, g, b, a;
};

// One agent's path: its points as nl_path_find returns them (each point says how the agent goes on
// to the next one, and carries the jump's apex).
struct PathLayer {
    std::string label;  // the legend's text, e.g. "long jumper: 2 jumps, 1 drop, 31.2 m"
    Rgba color;
    std::vector<nl_path_point> points;
};

struct ScenePoint {
    std::string label;
    float position[3];
    Rgba color;
};

// An agent where it stands or flies now, the track it left, and in the air the curve it flies.
struct SceneAgent {
    std::string label;
    Rgba color;
    float position[3];
    float radius;
    bool in_air = false;
    std::vector<std::array<float, 3>> track;
    std::vector<std::array<float, 3>> trajectory;  // empty on the ground
};

// A platform the host moves, where it stands now: its triangles and its navmesh (polygons, outline
// and the gangways off it) in the world.
struct ScenePlatform {
    std::string label;             // "shuttle at (4.0, -3.7, 19.2), moving"
    std::vector<float> positions;  // x y z per vertex
    std::vector<uint32_t> triangles;
    samples::NavmeshContents navmesh;
};

// Where one body can get to on the navmesh (nl_navmesh_get_islands): the island of each polygon,
// NL_NO_ISLAND for one in an area the body keeps out of. Polygons are coloured by island.
struct SceneIslands {
    std::string body;                  // whose islands: "walker"
    std::vector<uint32_t> of_polygon;  // one per navmesh polygon
    uint32_t count = 0;
};

struct Scene {
    // The navmesh the level's drawing goes by (roofs cut away, the grid's height): the whole one.
    const samples::NavmeshContents* level_navmesh() const { return whole_navmesh ? whole_navmesh : navmesh; }

    const samples::Level* level = nullptr;              // required
    const samples::NavmeshContents* navmesh = nullptr;  // optional
    const SceneIslands* islands = nullptr;              // optional: navmesh polygons coloured by island
    // Optional: the navmesh with every tile loaded while tiles of `navmesh` are streamed out, so that
    // the level is drawn as it is without streaming: the roofs cut away above it and the grid's height.
    const samples::NavmeshContents* whole_navmesh = nullptr;
    std::vector<ScenePlatform> platforms;
    std::vector<PathLayer> paths;
    std::vector<ScenePoint> points;  // start, goal, ...
    std::vector<SceneAgent> agents;
    std::string title;
    // The viewer's tile streaming, notes in the legend, one a line ("streaming: 6 of 24 tiles loaded,\n...");
    // empty: none.
    std::string streaming;
};

struct Layers {
    bool level = true;
    bool navmesh = true;
    bool boundary = true;
    bool links = true;
    bool paths = true;
    bool legend = true;
    bool agents = true;
    bool grid = true;           // metre lines with x and z labels at the map's edges
    bool link_numbers = false;  // each link's index in the navmesh's list (LINKS.json, path output)
    bool roofs = false;         // draw level surfaces above the navmesh too (none cut away)
    bool tile_borders = true;   // a tiled navmesh's loaded tiles outlined (a solo navmesh has none)
};

struct ViewSettings {
    int width = 1600;
    int height = 1000;     // PNG files: 0 fits the height to the level
    bool oblique = false;  // false: straight down; true: from the south, 55 degrees down
    Layers layers;
};

}  // namespace nl::picture
