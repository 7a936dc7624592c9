#include "drop_runs.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace nl::picture {
namespace {

constexpr float kSameHeading = 0.42f;  // cos 65 degrees: the generator's fan of drop angles, not a corner
constexpr float kSameLedge = 0.3f;     // metres between take-off heights, plus one per metre apart

// The drop's heading seen from above, unit (0, 0 for a drop straight down).
void heading(const nl_link& link, float out[2]) {
    const float dx = link.end[0] - link.start[0], dz = link.end[2] - link.start[2];
    const float length = std::hypot(dx, dz);
    out[0] = length > 1e-4f ? dx / length : 0.0f;
    out[1] = length > 1e-4f ? dz / length : 0.0f;
}

bool same_run(const nl_link& a, const nl_link& b) {
    if (a.enabled != b.enabled || a.holds != b.holds) return false;
    // Take-offs near each other seen from above, at one height or up a ramp's edge (at most 45 degrees).
    const float across = std::hypot(a.start[0] - b.start[0], a.start[2] - b.start[2]);
    if (across > kDropRunSpacing) return false;
    if (std::fabs(a.start[1] - b.start[1]) > kSameLedge + across) return false;
    float ha[2], hb[2];
    heading(a, ha);
    heading(b, hb);
    return ha[0] * hb[0] + ha[1] * hb[1] >= kSameHeading;
}

uint32_t root(std::vector<uint32_t>& parent, uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

}  // namespace

std::vector<DropRun> drop_runs(const std::vector<nl_link>& links) {
    std::vector<uint32_t> drops;
    for (uint32_t i = 0; i < links.size(); ++i)
        if (links[i].kind == NL_LINK_DROP && !links[i].bidirectional) drops.push_back(i);
    std::vector<uint32_t> parent(drops.size());
    std::iota(parent.begin(), parent.end(), 0u);
    for (size_t a = 0; a < drops.size(); ++a)
        for (size_t b = a + 1; b < drops.size(); ++b)
            if (same_run(links[drops[a]], links[drops[b]]))
                parent[root(parent, static_cast<uint32_t>(b))] = root(parent, static_cast<uint32_t>(a));

    std::map<uint32_t, size_t> run_of_root;  // in order of each run's first drop
    std::vector<DropRun> runs;
    for (size_t a = 0; a < drops.size(); ++a) {
        const auto [it, fresh] = run_of_root.try_emplace(root(parent, static_cast<uint32_t>(a)), runs.size());
        if (fresh) runs.emplace_back();
        runs[it->second].links.push_back(drops[a]);
    }
    for (DropRun& run : runs) {
        // Along the ledge: across the run's mean heading, seen from above.
        float mean[2] = {0.0f, 0.0f};
        for (uint32_t i : run.links) {
            float h[2];
            heading(links[i], h);
            mean[0] += h[0];
            mean[1] += h[1];
        }
        const float along[2] = {-mean[1], mean[0]};
        auto position = [&](uint32_t i) { return links[i].start[0] * along[0] + links[i].start[2] * along[1]; };
        std::stable_sort(run.links.begin(), run.links.end(),
                         [&](uint32_t a, uint32_t b) { return position(a) < position(b); });
        run.arrow = run.links[run.links.size() / 2];
    }
    return runs;
}

std::string drop_summary(const std::vector<nl_link>& links) {
    size_t drops = 0;
    for (const nl_link& link : links) drops += link.kind == NL_LINK_DROP;
    const size_t arrows = drop_runs(links).size();
    return std::to_string(drops) + " (" + std::to_string(arrows) + (arrows == 1 ? " arrow)" : " arrows)");
}

}  // namespace nl::picture
