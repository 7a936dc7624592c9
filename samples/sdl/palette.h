// The colours of every picture, in one place so the legend and the drawing agree.
#pragma once

#include <navlink/navlink.h>

#include "scene.h"

namespace nl::picture::palette {

constexpr Rgba kBackground{28, 32, 38, 255};
constexpr Rgba kLowGround{62, 74, 96, 255};      // the lowest level surface...
constexpr Rgba kHighGround{226, 214, 186, 255};  // ...to the highest
constexpr Rgba kPlatform{70, 150, 200, 255};     // a platform the host moves, at any height
constexpr Rgba kNavmeshFill{70, 190, 100, 105};
constexpr Rgba kNavmeshEdge{40, 120, 60, 120};
constexpr Rgba kBoundary{16, 70, 32, 255};
constexpr Rgba kJump{255, 140, 20, 255};
constexpr Rgba kDrop{20, 190, 235, 255};
constexpr Rgba kManual{220, 60, 210, 255};
constexpr Rgba kPlugin{240, 220, 40, 255};
constexpr Rgba kShadow{0, 0, 0, 170};  // under links and paths, so they read on any ground
constexpr Rgba kText{235, 235, 235, 255};
constexpr Rgba kDimText{165, 170, 178, 255};
constexpr Rgba kPanel{18, 20, 24, 235};

// Agents' paths, in order: white, red, violet, then yellow-green and pink.
constexpr Rgba kAgents[] = {
    {250, 250, 250, 255}, {235, 45, 45, 255}, {160, 80, 255, 255}, {170, 230, 60, 255}, {255, 120, 170, 255}};

constexpr Rgba kGrid{255, 255, 255, 46};
constexpr Rgba kGridLabel{200, 205, 212, 255};
constexpr Rgba kOffMap{255, 70, 200, 255};    // a start or goal off the map: its marker at the edge
constexpr Rgba kNoIsland{150, 150, 150, 90};  // a navmesh polygon in an area the body keeps out of
// A tiled navmesh's tiles: their squares (thin, faint) and the navmesh's edges along the lines
// between them (the same colour, solid).
constexpr Rgba kTileBorder{130, 160, 255, 230};
constexpr Rgba kTileSquare{130, 160, 255, 110};

// Reachability islands: the first is the navmesh's usual green, the others hues apart from it and
// from the links' colours, with the navmesh fill's transparency.
constexpr Rgba kIslands[] = {kNavmeshFill,        {235, 120, 60, 125}, {90, 140, 255, 125}, {225, 80, 200, 125},
                             {230, 215, 60, 125}, {60, 215, 215, 125}, {180, 110, 60, 125}, {160, 120, 255, 125}};

inline Rgba island(uint32_t index) { return kIslands[index % (sizeof kIslands / sizeof kIslands[0])]; }

inline Rgba agent(size_t index) { return kAgents[index % (sizeof kAgents / sizeof kAgents[0])]; }

inline Rgba link_kind(nl_link_kind kind) {
    if (kind == NL_LINK_JUMP) return kJump;
    if (kind == NL_LINK_DROP) return kDrop;
    if (kind == NL_LINK_MANUAL) return kManual;
    return kPlugin;
}

}  // namespace nl::picture::palette
