#include "links/link_merge.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>

namespace nl {

MergedLinks merge_links(std::vector<Link> links, float merge_distance, bool brute_force) {
    // Sorted through an index: Links are large, their order keys small.
    using OrderKey = std::tuple<uint32_t, float, float, float, float, float, float>;
    std::vector<std::pair<OrderKey, uint32_t>> order(links.size());
    for (uint32_t k = 0; k < links.size(); ++k) {
        const Link& l = links[k];
        order[k] = {OrderKey{static_cast<uint32_t>(l.kind), l.start.x(), l.start.z(), l.start.y(), l.end.x(), l.end.z(),
                             l.end.y()},
                    k};
    }
    std::sort(order.begin(), order.end());  // ties keep input order: the index is the last key
    const float r = merge_distance;
    auto same_traversal = [&](const Link& a, const Link& b) {
        if ((a.start - b.start).norm() <= r && (a.end - b.end).norm() <= r) return true;
        return (a.bidirectional || b.bidirectional) && (a.start - b.end).norm() <= r && (a.end - b.start).norm() <= r;
    };
    struct Key {
        int64_t x, z;
        bool operator==(const Key& o) const { return x == o.x && z == o.z; }
    };
    struct Hash {
        size_t operator()(const Key& k) const { return size_t(uint64_t(k.x) * 73856093u ^ uint64_t(k.z) * 19349663u); }
    };
    const float cell = std::max(r, 0.01f);
    auto key = [&](const Vec3& p) { return Key{int64_t(std::floor(p.x() / cell)), int64_t(std::floor(p.z() / cell))}; };
    // Kept links indexed by the cells of both their ends, so either orientation is found (brute
    // force: compared with every kept link). Each cell heads a list threaded through `next_in_cell`.
    constexpr uint32_t kNone = ~0u;
    std::unordered_map<Key, uint32_t, Hash> cell_head;
    cell_head.reserve(2 * links.size());
    std::vector<uint32_t> next_in_cell;  // two entries per kept link: its start's cell, its end's
    std::vector<Link> kept;
    kept.reserve(links.size());
    uint32_t duplicates = 0;
    auto file = [&](const Key& k, uint32_t entry) {
        const auto [it, fresh] = cell_head.try_emplace(k, entry);
        next_in_cell[entry] = fresh ? kNone : it->second;
        it->second = entry;
    };
    for (const auto& [order_key, index] : order) {
        const Link& l = links[index];
        bool duplicate = false;
        if (brute_force) {
            duplicate = std::any_of(kept.begin(), kept.end(), [&](const Link& k) { return same_traversal(k, l); });
        } else {
            const Key k = key(l.start);
            for (int64_t dz = -1; dz <= 1 && !duplicate; ++dz)
                for (int64_t dx = -1; dx <= 1 && !duplicate; ++dx) {
                    const auto it = cell_head.find(Key{k.x + dx, k.z + dz});
                    for (uint32_t e = it == cell_head.end() ? kNone : it->second; e != kNone && !duplicate;
                         e = next_in_cell[e])
                        duplicate = same_traversal(kept[e / 2], l);
                }
        }
        if (duplicate) {
            ++duplicates;
            continue;
        }
        const auto index_kept = static_cast<uint32_t>(kept.size());
        kept.push_back(l);
        if (brute_force) continue;
        next_in_cell.resize(2 * kept.size(), kNone);
        file(key(l.start), 2 * index_kept);
        if (!(key(l.end) == key(l.start))) file(key(l.end), 2 * index_kept + 1);
    }
    return MergedLinks{std::move(kept), duplicates};
}

}  // namespace nl
