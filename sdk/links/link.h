// A link: a traversal the navmesh cannot express by walking (a jump across a gap, a drop off a
// ledge, a manual or plugin-defined move), with what it physically asks of an agent.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>

#include "level/geometry.h"
#include "navmesh/navmesh_grid.h"
#include "navmesh/tiles.h"
#include "util/handle.h"

namespace nl {

enum class LinkKind : uint32_t {
    Jump = 1,
    Drop = 2,
    Manual = 3,
    // Kinds from plugins start here.
    FirstPluginKind = 256,
};

// What taking the link asks of an agent, in its forward direction (start to end). Going the other
// way over a bidirectional link swaps rise and drop.
struct LinkRequirements {
    float gap = 0.0f;              // horizontal distance covered in the air: rim to rim for a jump, rim
                                   // to landing for a drop; end to end for links whose rims are not known
    float length = 0.0f;           // horizontal distance between the ends
    float rise = 0.0f;             // how far the end is above the start (0 if below)
    float drop = 0.0f;             // how far the end is below the start (0 if above)
    float clearance_width = 0.0f;  // widest body found clear along the link
    uint64_t abilities = 0;        // ability bits the agent must have (plugin kinds)
};

struct Link {
    LinkKind kind = LinkKind::Manual;
    Vec3 start = Vec3::Zero();
    Vec3 end = Vec3::Zero();
    Vec3 apex = Vec3::Zero();  // top of a jump's arc; where a generated drop's fall leaves the ground;
                               // for other kinds the higher end
    bool bidirectional = false;
    bool generated = false;
    bool enabled = true;
    float cost_modifier = 1.0f;
    // For a generated jump, and a drop's jump back up: how far the arc the generator checked tops
    // out above the higher end (agents fly that arc); 0 when not generated.
    float arc_height = 0.0f;
    uint64_t user_data = 0;
    LinkRequirements requirements;
    uint32_t start_polygon = 0xffffffffu;
    uint32_t end_polygon = 0xffffffffu;
    // On a tiled navmesh: the tiles of the polygons the ends were first placed on (an end near a line
    // between tiles may lie in one tile's square and on the other's polygon). Kept while a tile is out
    // and the end parked, so that the link is out exactly while one of these tiles is; unset until the
    // end is placed on a tiled navmesh.
    std::optional<TileCoord> start_tile, end_tile;

    // A link from one surface to another: the navmesh its end is on (the end in that navmesh's
    // space, end_polygon one of its polygons; the start on the link's own navmesh). Null: both ends
    // on the link's own navmesh. Such a link is one-way and is taken only while it holds: while its
    // end, seen from the start's navmesh, stays within `tolerance` of `placed_end`, where it was
    // when the link was placed (link_placement.h, cross_link_holds).
    Handle landing_navmesh;
    Vec3 placed_end = Vec3::Zero();
    float tolerance = 0.0f;
    bool crosses() const { return landing_navmesh != Handle{}; }
};

// The link with its ends and apex on the navmesh grid (navmesh.h), as navmeshes keep links.
inline Link on_navmesh_grid(Link link) {
    link.start = on_navmesh_grid(link.start);
    link.end = on_navmesh_grid(link.end);
    link.apex = on_navmesh_grid(link.apex);
    return link;
}

// The apex of a link made outside the generator (the host's, a file's without one): its higher end.
inline Vec3 higher_end(const Link& l) { return l.start.y() > l.end.y() ? l.start : l.end; }

// How far a cross link's end may move, seen from its start, before it stops holding (default).
constexpr float kDefaultCrossTolerance = 0.25f;

// Sets the length, rise and drop the link's ends ask for, start to end, and the gap to the length
// (the rims are not known).
inline void set_requirements_from_ends(Link& l) {
    const Vec3 d = l.end - l.start;
    l.requirements.length = Vec3(d.x(), 0.0f, d.z()).norm();
    l.requirements.gap = l.requirements.length;
    l.requirements.rise = std::max(0.0f, d.y());
    l.requirements.drop = std::max(0.0f, -d.y());
}

// A host's link: its requirements measured from its ends, or, `as_given`, kept as the host gave them
// (a link that asks only for an ability) with a length of 0 measured from the ends.
inline void settle_host_requirements(Link& l, bool as_given) {
    if (!as_given) {
        set_requirements_from_ends(l);
    } else if (l.requirements.length == 0.0f) {
        const Vec3 d = l.end - l.start;
        l.requirements.length = Vec3(d.x(), 0.0f, d.z()).norm();
    }
}

}  // namespace nl
