// What every navmesh the builder hands over must satisfy, checked on a captured copy.
#pragma once

#include "fake_host.h"

namespace nl::test {

// Checks the def's header fields, polygon sizes and indices, areas, detail offsets and indices, and
// that every vertex lies within the level's bounds (give or take Recast's grid snapping).
void check_navmesh(const CapturedMesh& mesh, const FakeHost& host, const nl_agent_type& agent, float cell_size = 0.3f,
                   float cell_height = 0.2f);

// Polygons whose corners run counter-clockwise seen from above (+y), i.e. whose normal points up.
uint32_t count_upward_polygons(const CapturedMesh& mesh);

}  // namespace nl::test
