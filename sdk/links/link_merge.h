// One link per traversal: near-duplicate links (both ends within merge_distance, either way round
// when either link is bidirectional) are merged into the first in a fixed order.
#pragma once

#include <cstdint>
#include <vector>

#include "links/link.h"

namespace nl {

struct MergedLinks {
    std::vector<Link> kept;
    uint32_t duplicates = 0;
};

// Links are taken by kind (jumps before drops, so a drop that repeats a jump goes), then by the
// positions of their ends, then by their order in `links`: the result does not depend on how they
// were found. Near-duplicates are looked up in a grid of kept links' ends, or, with `brute_force`,
// among every kept link.
MergedLinks merge_links(std::vector<Link> links, float merge_distance, bool brute_force);

}  // namespace nl
