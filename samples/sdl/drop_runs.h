// Drops along one ledge drawn as one arrow. A level's drops come in rows, one every sample spacing
// along each ledge and fanned out at a few angles, whose arrows overlap into a smear: drops whose
// take-offs are neighbours (at most kDropRunSpacing apart seen from above, at one height or up a
// ramp's edge) and that head about the same way (within 65 degrees seen from above: a fan, not the
// two sides of a corner) make one run, drawn as a line along the ledge with one arrow, its middle
// drop's.
#pragma once

#include <navlink/navlink.h>

#include <cstdint>
#include <string>
#include <vector>

namespace nl::picture {

struct DropRun {
    std::vector<uint32_t> links;  // indices into the link list, in order along the ledge
    uint32_t arrow = 0;           // the one drawn with its arrow: the middle one
};

constexpr float kDropRunSpacing = 1.6f;  // metres between neighbouring take-offs of one run at most

// Every one-way drop in `links` in exactly one run, runs in order of their first link.
std::vector<DropRun> drop_runs(const std::vector<nl_link>& links);

// "141 (38 arrows)": the drops of `links` (one-way or not) and the arrows drawn for them.
std::string drop_summary(const std::vector<nl_link>& links);

}  // namespace nl::picture
