// Owning pointers for Recast's heap objects: each frees itself with the matching rcFree* call, so every
// path out of a build (success, failure, exception) releases everything.
#pragma once

#include <memory>

#include <Recast.h>

namespace nl::recast {

struct RecastDeleter {
    void operator()(rcHeightfield* p) const noexcept { rcFreeHeightField(p); }
    void operator()(rcCompactHeightfield* p) const noexcept { rcFreeCompactHeightfield(p); }
    void operator()(rcContourSet* p) const noexcept { rcFreeContourSet(p); }
    void operator()(rcPolyMesh* p) const noexcept { rcFreePolyMesh(p); }
    void operator()(rcPolyMeshDetail* p) const noexcept { rcFreePolyMeshDetail(p); }
};

using HeightfieldPtr = std::unique_ptr<rcHeightfield, RecastDeleter>;
using CompactHeightfieldPtr = std::unique_ptr<rcCompactHeightfield, RecastDeleter>;
using ContourSetPtr = std::unique_ptr<rcContourSet, RecastDeleter>;
using PolyMeshPtr = std::unique_ptr<rcPolyMesh, RecastDeleter>;
using PolyMeshDetailPtr = std::unique_ptr<rcPolyMeshDetail, RecastDeleter>;

}  // namespace nl::recast
