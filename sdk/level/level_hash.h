// A fingerprint of level geometry: what a baked navmesh records of the level it was built from, so
// that a host can tell whether the level changed since.
#pragma once

#include <cstdint>

#include "level/geometry.h"

namespace nl {

// 64-bit FNV-1a over the triangles' corners (their coordinates' bits, corner by corner, triangle by
// triangle): the same triangles in the same order give the same hash, however their vertices are
// shared. Never 0 (0 means "not built from the level").
uint64_t level_hash(const TriangleMesh& mesh);

}  // namespace nl
