// A fingerprint of level geometry: what a baked navmesh records of the level it was built from, so
// that a host can tell whether the level changed since.
#pragma once

#include <cstdint>
#include <string>

#include "level/geometry.h"

namespace nl {

// 64-bit FNV-1a over the triangles' corners (their coordinates' bits, corner by corner, triangle by
// triangle), each followed by its area when that is not 0 (an obstacle's is kObstacleArea): the same
// triangles in the same order with the same areas give the same hash, however their vertices are
// shared, and a level of area-0 triangles hashes as its corners alone. Never 0 (0 means "not built
// from the level").
uint64_t level_hash(const BuildTriangles& level);

// 64-bit FNV-1a, fed a word, a number's bits or a text at a time: the level hash's, and what a tile's
// content hash adds to it. Its value is never 0.
class Fnv1a64 {
public:
    void word(uint32_t w);
    void number(float v);
    void text(const std::string& t);
    uint64_t value() const { return h_ == 0 ? 1 : h_; }

private:
    uint64_t h_ = 14695981039346656037ull;
};

// A hash as files and messages write it: 16 hex digits.
std::string level_hash_text(uint64_t hash);

}  // namespace nl
