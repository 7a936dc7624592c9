// A navmesh's links at one moment, as readers (path searches, saves, the C API's lists) see them.
#pragma once

#include <vector>

#include "links/link.h"
#include "util/handle.h"

namespace nl {

struct StoredLink {
    Handle id;
    Link link;
};

// The links of one navmesh at one moment, in the order they were added. Immutable once published:
// an edit makes the next one.
using LinkSnapshot = std::vector<StoredLink>;

}  // namespace nl
