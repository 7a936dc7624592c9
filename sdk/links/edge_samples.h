// Step 1 of link generation: the navmesh's boundary edges become take-off samples. Short edges that
// touch are grouped (a ragged ledge is one ledge) and represented by the member facing most like the
// group; long edges get a sample every `sample_spacing`.
#pragma once

#include <cstdint>
#include <vector>

#include "links/link_settings.h"
#include "navmesh/navmesh.h"

namespace nl {

struct EdgeSample {
    Vec3 point;        // on the navmesh edge
    Vec3 outward;      // horizontal unit direction away from the navmesh
    Vec3 normal;       // the surface normal at the edge
    uint32_t polygon;  // the polygon the edge belongs to
    uint32_t edge;     // index of the (representative) boundary edge
};

struct EdgeSampling {
    std::vector<EdgeSample> samples;
    uint32_t edges = 0;          // boundary edges considered
    uint32_t groups = 0;         // groups of short edges kept
    uint32_t dropped_edges = 0;  // short edges in groups too small, or with no horizontal outward
};

// Far above any real level (a 940,000-triangle one has 64,000), low enough to fail before memory does.
constexpr double kMaxEdgeSamples = 4'000'000;

// Throws InvalidArgument when the boundary would need more than kMaxEdgeSamples samples.
EdgeSampling sample_edges(const NavMesh& navmesh, const LinkSettings& settings);

}  // namespace nl
