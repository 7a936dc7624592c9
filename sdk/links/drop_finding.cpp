// Drops, the third stage of a link generation pass: probes turned from each take-off point's edge, down
// to a landing, the falls swept (and the jumps back up); and one drop kept per way down.
#include "links/generation_stage.h"

#include <algorithm>
#include <cmath>
#include "links/trajectory.h"

namespace nl::generation {
namespace {

class DropFinding : public GenerationStage {
public:
    using GenerationStage::GenerationStage;

    // Drops: probes down from past the rim along rotated outward directions, then the fall's sweep.
    void run(LinkGeneration::Cache& next) {
        const float steep = settings_.drop_steepness * kDegrees;
        const float reach = (settings_.max_drop_distance + kProbeLift + 1.0f) / std::sin(steep);
        const auto angles = static_cast<uint32_t>(settings_.drop_angles.size());
        // Every take-off point's probes, in key order: reused from the old cache (also in key order)
        // when neither the take-off point nor the probe's reach changed, else probed again.
        std::vector<uint32_t> probed;  // indices into next.drops
        next.drops.reserve(size_t(report_.takeoff_points) * angles);
        auto old = old_.drops.begin();
        for (uint32_t i = 0; i < samples_.size(); ++i) {
            const LinkGeneration::TakeoffState& t = next.takeoffs[i];
            if (!t.valid) continue;
            const bool takeoff_same = old_.takeoffs.size() == samples_.size() && old_.takeoffs[i].valid &&
                                      old_.takeoffs[i].rim == t.rim && old_.takeoffs[i].ground_y == t.ground_y;
            for (uint32_t angle = 0; angle < angles; ++angle) {
                const uint64_t key = pair_key(i, angle);
                while (old != old_.drops.end() && old->key < key) ++old;
                if (takeoff_same && old != old_.drops.end() && old->key == key && !touches(old->bounds, box_)) {
                    next.drops.push_back(*old);
                    continue;
                }
                probed.push_back(static_cast<uint32_t>(next.drops.size()));
                next.drops.emplace_back().key = key;
            }
        }
        // Each turned probe's own rim: where the ground falls away along its heading (straight out, the
        // take-off point's). A turned heading along which the ground does not fall away within reach
        // has no drop.
        std::vector<Vec3> headings(probed.size());
        std::vector<RimQuery> turned;
        std::vector<uint32_t> turned_of;  // positions in `probed`
        for (uint32_t k = 0; k < probed.size(); ++k) {
            LinkGeneration::DropProbe& d = next.drops[probed[k]];
            const auto i = static_cast<uint32_t>(d.key >> 32), angle = static_cast<uint32_t>(d.key);
            const EdgeSample& e = samples_[i];
            headings[k] = Eigen::AngleAxisf(settings_.drop_angles[angle] * kDegrees, Vec3::UnitY()) * e.outward;
            d.rim = next.takeoffs[i].rim;
            d.bounds = Aabb{};
            if (settings_.drop_angles[angle] == 0.0f) continue;
            const float reach = settings_.falloff_distance / std::cos(settings_.drop_angles[angle] * kDegrees);
            turned.push_back(RimQuery{e.point, headings[k], next.takeoffs[i].ground_y, reach, std::nullopt});
            grow(d.bounds, rim_search_bounds(turned.back(), rim_probing_));
            turned_of.push_back(k);
        }
        const std::vector<float> rims = find_rims(level_, tasks_, std::move(turned), rim_probing_, report_.rays_cast);
        for (size_t n = 0; n < turned_of.size(); ++n) next.drops[probed[turned_of[n]]].rim = rims[n];
        std::vector<uint32_t> off_rim;  // positions in `probed` of the probes cast
        for (uint32_t k = 0; k < probed.size(); ++k) {
            LinkGeneration::DropProbe& d = next.drops[probed[k]];
            if (d.rim >= 0.0f)
                off_rim.push_back(k);
            else
                d.outcome = 1;
        }
        std::vector<Ray> probes(off_rim.size());
        tasks_.parallel_for(static_cast<uint32_t>(off_rim.size()), 256, [&](uint32_t begin, uint32_t end) {
            for (uint32_t n = begin; n < end; ++n) {
                const uint32_t k = off_rim[n];
                const LinkGeneration::DropProbe& d = next.drops[probed[k]];
                const Vec3 falloff = samples_[d.key >> 32].point + headings[k] * (d.rim + kPastRim);
                const Vec3 direction = (headings[k] * std::cos(steep) + Vec3(0, -std::sin(steep), 0)).normalized();
                probes[n] = Ray{falloff + Vec3(0, kProbeLift, 0), direction, reach};
            }
        });
        const std::vector<RayHit> hits = cast(probes);
        step(0.7f, "drops");

        // Where each probe came down on the navmesh, then the floor under that point.
        const Vec3 landing_box(std::max(body_.radius * 1.5f, 0.3f), 1.0f, std::max(body_.radius * 1.5f, 0.3f));
        std::vector<NavPoint> landings(off_rim.size());
        tasks_.parallel_for(static_cast<uint32_t>(off_rim.size()), 256, [&](uint32_t begin, uint32_t end) {
            for (uint32_t n = begin; n < end; ++n) {
                LinkGeneration::DropProbe& d = next.drops[probed[off_rim[n]]];
                d.bounds.grow(probes[n].origin);
                d.bounds.grow(probes[n].origin + probes[n].direction * (hits[n].hit ? hits[n].distance : reach));
                d.outcome = 1;
                if (!hits[n].hit) continue;
                landings[n] = locate(hits[n].point, landing_box);
                if (landings[n].polygon == samples_[d.key >> 32].polygon) landings[n].found = false;
            }
        });
        std::vector<uint32_t> landed;  // positions in `off_rim`
        std::vector<Ray> floor_rays;
        for (uint32_t n = 0; n < off_rim.size(); ++n) {
            if (!landings[n].found) continue;
            landed.push_back(n);
            floor_rays.push_back(floor_ray(landings[n].point));
        }
        const std::vector<RayHit> floors = cast(floor_rays);
        for (size_t m = 0; m < landed.size(); ++m) {
            const uint32_t n = landed[m];
            settle(next, next.drops[probed[off_rim[n]]], headings[off_rim[n]], landings[n], floor_rays[m], floors[m]);
        }
        // Sweeps known: the reused probes' whose bounds the box does not touch. Of each take-off point's
        // probes landing on one surface only the most head-on clear one is kept, so they are swept in
        // that order, a round at a time, until one is clear: the others need no sweep.
        std::vector<uint8_t> fresh(next.drops.size(), 0);
        for (uint32_t k : probed) fresh[k] = 1;
        for (uint32_t k = 0; k < next.drops.size(); ++k) {
            LinkGeneration::DropProbe& d = next.drops[k];
            if (fresh[k] || touches(d.sweep.bounds, box_)) d.sweep = LinkGeneration::Sweep{};
            if (fresh[k] || touches(d.back.bounds, box_)) d.back = LinkGeneration::Sweep{};
        }
        step(0.8f, "drop clearance");
        for (;;) {
            std::vector<uint32_t> round;
            for_each_way_down(next, [&](const std::vector<uint32_t>& way) {
                for (uint32_t k : way) {
                    const LinkGeneration::Sweep& sw = next.drops[k].sweep;
                    if (!sw.swept) round.push_back(k);
                    if (!sw.swept || sw.clear) return;
                }
            });
            if (round.empty()) break;
            std::vector<PathPoints> paths;
            for (uint32_t k : round)
                paths.push_back(PathPoints{next.drops[k].fall.data(), next.drops[k].fall.size(), 0.0f});
            const std::vector<LinkGeneration::Sweep> swept = sweep(paths);
            for (size_t n = 0; n < round.size(); ++n) next.drops[round[n]].sweep = swept[n];
        }
        // The jump back up of each kept drop low enough for one.
        std::vector<uint32_t> back_of;
        for_each_way_down(next, [&](const std::vector<uint32_t>& way) {
            const uint32_t* kept = kept_probe(next, way);
            if (kept && next.drops[*kept].link.bidirectional && !next.drops[*kept].back.swept) back_of.push_back(*kept);
        });
        std::vector<std::pair<Vec3, Vec3>> ends;
        for (uint32_t k : back_of) ends.emplace_back(next.drops[k].link.end, next.drops[k].link.start);
        const std::vector<LinkGeneration::Sweep> back = sweep_arcs(ends);
        for (size_t n = 0; n < back_of.size(); ++n) next.drops[back_of[n]].back = back[n];
    }

    // Calls each(way) for every way down: the landed probes of one take-off point whose landings
    // share a surface, most head-on first (the least turned from the edge's outward direction, the
    // first in drop_angles on a tie). A probe joins the first way whose first probe lands on its
    // surface: a walkable surface joined to that landing on foot, within max_climb of its height.
    template <typename Each>
    void for_each_way_down(const LinkGeneration::Cache& c, Each&& each) const {
        std::vector<uint32_t> landed;
        std::vector<std::vector<uint32_t>> ways;
        for (size_t first = 0; first < c.drops.size();) {
            const uint64_t sample = c.drops[first].key >> 32;
            size_t last = first;
            while (last < c.drops.size() && (c.drops[last].key >> 32) == sample) ++last;
            landed.clear();
            for (size_t k = first; k < last; ++k)
                if (c.drops[k].outcome == 0) landed.push_back(static_cast<uint32_t>(k));
            auto turn = [&](uint32_t k) {
                return std::fabs(settings_.drop_angles[static_cast<uint32_t>(c.drops[k].key)]);
            };
            std::stable_sort(landed.begin(), landed.end(), [&](uint32_t x, uint32_t y) { return turn(x) < turn(y); });
            ways.clear();
            for (uint32_t k : landed) {
                const Link& b = c.drops[k].link;
                auto same = std::find_if(ways.begin(), ways.end(), [&](const std::vector<uint32_t>& way) {
                    const Link& a = c.drops[way.front()].link;
                    return walk_.surface(a.end_polygon) == walk_.surface(b.end_polygon) &&
                           std::fabs(a.end.y() - b.end.y()) <= mesh_.agent().max_climb;
                });
                if (same != ways.end())
                    same->push_back(k);
                else
                    ways.push_back({k});
            }
            for (const auto& way : ways) each(way);
            first = last;
        }
    }

    // A way down's kept probe: its first swept and clear one, or none.
    static const uint32_t* kept_probe(const LinkGeneration::Cache& c, const std::vector<uint32_t>& way) {
        for (const uint32_t& k : way) {
            const LinkGeneration::Sweep& sw = c.drops[k].sweep;
            if (!sw.swept) return nullptr;
            if (sw.clear) return &k;
        }
        return nullptr;
    }

    // A ray down to the floor under a navmesh point: navmeshes float above the floor (Recast's by up
    // to a few decimetres, more over stairs) or sink into it.
    static Ray floor_ray(const Vec3& on_navmesh) {
        return Ray{on_navmesh + Vec3(0, kProbeLift, 0), Vec3(0, -1, 0), kProbeLift + kFloorReach};
    }

    // What a probe that came down on the navmesh found, floor to floor: a landing too shallow (a
    // step, walked) or too deep, or a drop link with its fall (out over the rim, across, down).
    void settle(const LinkGeneration::Cache& c, LinkGeneration::DropProbe& d, const Vec3& heading,
                const NavPoint& landing, const Ray& floor_ray, const RayHit& floor) const {
        const auto i = static_cast<uint32_t>(d.key >> 32);
        d.bounds.grow(floor_ray.origin);
        d.bounds.grow(floor_ray.origin + floor_ray.direction * floor_ray.max_distance);
        const Vec3 start = floor_point(c, i);
        const Vec3 end(landing.point.x(), floor.hit ? floor.point.y() : landing.point.y(), landing.point.z());
        const float drop = start.y() - end.y();
        if (drop <= mesh_.agent().max_climb) {
            d.outcome = 2;
            return;
        }
        if (drop > settings_.max_drop_distance) {
            d.outcome = 3;
            return;
        }
        d.outcome = 0;
        Link& l = d.link;
        l.kind = LinkKind::Drop;
        l.start = start;
        l.end = end;
        l.generated = true;
        l.start_polygon = samples_[i].polygon;
        l.end_polygon = landing.polygon;
        set_requirements_from_ends(l);
        const Vec3 crossing = start + heading * d.rim;
        l.requirements.gap = Vec3(end.x() - crossing.x(), 0.0f, end.z() - crossing.z()).norm();
        // Low and near enough to jump back up (whether the body fits that arc is swept later).
        l.bidirectional = drop <= settings_.max_jump_up && l.requirements.gap <= settings_.max_jump_gap;
        l.arc_height = settings_.jump_arc_height;  // the jump back up's arc, when the drop works both ways
        d.fall = fall_path(start, heading, d.rim + kPastRim, end);
        l.apex = d.fall[1];  // where the body leaves the ground: the top of the fall, and its heading
    }

    // The kept drops, in key order: one per way down (for_each_way_down), its most head-on clear
    // probe. The ways' other probes are duplicates, unless blocked.
    std::vector<Link> one_drop_per_way_down(const LinkGeneration::Cache& c) {
        for (const LinkGeneration::DropProbe& d : c.drops) {
            if (d.outcome == 1)
                ++report_.rejected_no_landing;
            else if (d.outcome == 2)
                ++report_.rejected_too_shallow;
            else if (d.outcome == 3)
                ++report_.rejected_too_deep;
        }
        std::vector<uint32_t> kept;
        for_each_way_down(c, [&](const std::vector<uint32_t>& way) {
            const uint32_t* keep = kept_probe(c, way);
            for (const uint32_t& k : way) {
                if (&k == keep)
                    kept.push_back(k);
                else if (c.drops[k].sweep.swept && !c.drops[k].sweep.clear)
                    ++report_.rejected_clearance;
                else
                    ++report_.rejected_duplicate;
            }
        });
        std::sort(kept.begin(), kept.end());
        std::vector<Link> out;
        for (uint32_t k : kept) {
            const LinkGeneration::DropProbe& d = c.drops[k];
            out.push_back(d.link);
            Link& l = out.back();
            l.requirements.clearance_width = d.sweep.width;
            // Both ways only if the body fits the jump back up as well.
            if (l.bidirectional && !d.back.clear) l.bidirectional = false;
            if (l.bidirectional) l.requirements.clearance_width = std::min(d.sweep.width, d.back.width);
        }
        return out;
    }
};

}  // namespace

void find_drops(PassInputs& in, LinkGeneration::Cache& next) { DropFinding(in).run(next); }

std::vector<Link> one_drop_per_way_down(PassInputs& in, const LinkGeneration::Cache& c) {
    return DropFinding(in).one_drop_per_way_down(c);
}

}  // namespace nl::generation
