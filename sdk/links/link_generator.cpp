#include "links/link_generator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_map>

#include "links/clearance.h"
#include "links/edge_samples.h"
#include "util/error.h"

namespace nl {
namespace {

constexpr float kDegrees = 3.14159265358979f / 180.0f;
constexpr float kProbeLift = 0.5f;  // probes start this far above the navmesh: clear of the floor,
                                    // and below any ceiling (the navmesh has agent height above it)

struct Stopwatch {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double ms = std::chrono::duration<double, std::milli>(now - start).count();
        start = now;
        return ms;
    }
};

// A take-off point: a sample whose outside really hangs over a drop or gap.
struct Takeoff {
    EdgeSample sample;
    float ground_y;  // the level's surface under the edge (the navmesh may float above it or sink in)
    float rim;       // how far past the edge the ground falls away
};

constexpr float kRimStep = 0.25f;  // spacing of the probes that look for the rim past an edge

class Generator {
public:
    Generator(const NavMesh& mesh, const Level& level, TaskSystem& tasks, const LinkSettings& s, BakeReport& report,
              BakeProgress progress)
        : mesh_(mesh), level_(level), tasks_(tasks), s_(s), report_(report), progress_(progress),
          body_{mesh.agent().radius, mesh.agent().height} {}

    std::vector<Link> run(CandidateSearch search) {
        Stopwatch total, stage;
        step(0.0f, "edges");
        const EdgeSampling sampling = sample_edges(mesh_, s_);
        report_.edges = sampling.edges;
        report_.groups = sampling.groups;
        report_.samples = static_cast<uint32_t>(sampling.samples.size());
        report_.milliseconds_edges = stage.lap();

        step(0.05f, "take-off points");
        find_takeoffs(sampling.samples);
        report_.milliseconds_takeoff = stage.lap();

        step(0.15f, "jumps");
        std::vector<Link> links = find_jumps(search);
        report_.milliseconds_jumps = stage.lap();

        step(0.55f, "drops");
        std::vector<Link> drops = find_drops();
        links.insert(links.end(), drops.begin(), drops.end());
        report_.milliseconds_drops = stage.lap();

        step(0.95f, "merge");
        links = merge(std::move(links));
        report_.milliseconds_merge = stage.lap();
        for (const Link& l : links) (l.kind == LinkKind::Jump ? report_.jump_links : report_.drop_links)++;
        report_.milliseconds_total = total.lap();
        step(1.0f, "done");
        return links;
    }

private:
    void step(float fraction, const char* stage) {
        if (!progress_(fraction, stage)) fail(ErrorCode::Cancelled, "the bake was cancelled during '", stage, "'");
    }

    std::vector<RayHit> cast(const std::vector<Ray>& rays) {
        std::vector<RayHit> hits(rays.size());
        level_.cast_rays(rays.data(), static_cast<uint32_t>(rays.size()), hits.data());
        report_.rays_cast += rays.size();
        return hits;
    }

    std::vector<uint8_t> blocked(const std::vector<Segment>& segments) {
        std::vector<uint8_t> out(segments.size());
        level_.segments_blocked(segments.data(), static_cast<uint32_t>(segments.size()), out.data());
        report_.rays_cast += segments.size();
        return out;
    }

    // Step 2: keep samples past whose edge the ground falls away (the rim: the first probe, every
    // kRimStep out to falloff_distance, with no ground within a step below), with nothing solid
    // between the edge and the rim. Recast leaves its edges 0.6 to 0.9 m inside the rim, depending
    // on how the voxel grid falls, so the rim is searched for, not assumed.
    void find_takeoffs(const std::vector<EdgeSample>& samples) {
        const float probe = std::min(kProbeLift, 0.5f * body_.height);
        std::vector<Ray> ground_rays;
        for (const EdgeSample& e : samples)
            ground_rays.push_back(Ray{e.point + Vec3(0, probe, 0), Vec3(0, -1, 0), probe + 1.5f});
        const std::vector<RayHit> ground = cast(ground_rays);

        const auto steps = static_cast<uint32_t>(std::ceil(s_.falloff_distance / kRimStep));
        const float climb = mesh_.agent().max_climb;
        std::vector<float> ground_y(samples.size());
        std::vector<Ray> below;
        for (size_t i = 0; i < samples.size(); ++i) {
            const EdgeSample& e = samples[i];
            // Correction for navmeshes that sit above the floor (Recast's rounds up) or sink into it.
            ground_y[i] = ground[i].hit ? ground[i].point.y() : e.point.y();
            for (uint32_t k = 1; k <= steps; ++k) {
                const Vec3 out = e.point + e.outward * std::min(k * kRimStep, s_.falloff_distance);
                below.push_back(Ray{Vec3(out.x(), ground_y[i] + probe, out.z()), Vec3(0, -1, 0), probe + climb + 0.05f});
            }
        }
        const std::vector<RayHit> step_below = cast(below);

        std::vector<float> rim(samples.size(), -1.0f);
        std::vector<Segment> walls;
        std::vector<uint32_t> ledges;
        const Vec3 chest(0, std::min(0.5f * body_.height, 1.0f), 0);
        for (size_t i = 0; i < samples.size(); ++i) {
            for (uint32_t k = 1; k <= steps; ++k) {
                if (!step_below[i * steps + k - 1].hit) {
                    rim[i] = std::min(k * kRimStep, s_.falloff_distance);
                    break;
                }
            }
            if (rim[i] < 0.0f) {
                ++report_.rejected_not_ledge;
                continue;
            }
            const Vec3 foot(samples[i].point.x(), ground_y[i], samples[i].point.z());
            walls.push_back(Segment{foot + chest, foot + samples[i].outward * rim[i] + chest});
            ledges.push_back(static_cast<uint32_t>(i));
        }
        const std::vector<uint8_t> wall = blocked(walls);
        for (size_t k = 0; k < ledges.size(); ++k) {
            const uint32_t i = ledges[k];
            if (wall[k]) ++report_.rejected_wall;
            else takeoffs_.push_back(Takeoff{samples[i], ground_y[i], rim[i]});
        }
        report_.takeoff_points = static_cast<uint32_t>(takeoffs_.size());
    }

    // The pairs of take-off points within max_link_distance, each once (i < j), in order.
    std::vector<std::pair<uint32_t, uint32_t>> nearby_pairs(CandidateSearch search) const {
        std::vector<std::pair<uint32_t, uint32_t>> pairs;
        const auto n = static_cast<uint32_t>(takeoffs_.size());
        const float reach = s_.max_link_distance;
        if (search == CandidateSearch::AllPairs) {
            for (uint32_t i = 0; i < n; ++i)
                for (uint32_t j = i + 1; j < n; ++j)
                    if ((takeoffs_[i].sample.point - takeoffs_[j].sample.point).norm() <= reach) pairs.emplace_back(i, j);
            return pairs;
        }
        // Cells as wide as the reach: a partner is in the 27 cells around a point.
        struct Key {
            int64_t x, y, z;
            bool operator==(const Key& o) const { return x == o.x && y == o.y && z == o.z; }
        };
        struct Hash {
            size_t operator()(const Key& k) const {
                return size_t(k.x * 73856093) ^ size_t(k.y * 19349663) ^ size_t(k.z * 83492791);
            }
        };
        auto key = [&](const Vec3& p) {
            return Key{int64_t(std::floor(p.x() / reach)), int64_t(std::floor(p.y() / reach)), int64_t(std::floor(p.z() / reach))};
        };
        std::unordered_map<Key, std::vector<uint32_t>, Hash> cells;
        for (uint32_t i = 0; i < n; ++i) cells[key(takeoffs_[i].sample.point)].push_back(i);
        for (uint32_t i = 0; i < n; ++i) {
            const Vec3& p = takeoffs_[i].sample.point;
            const Key k = key(p);
            const size_t first = pairs.size();
            for (int64_t dz = -1; dz <= 1; ++dz)
                for (int64_t dy = -1; dy <= 1; ++dy)
                    for (int64_t dx = -1; dx <= 1; ++dx) {
                        const auto it = cells.find(Key{k.x + dx, k.y + dy, k.z + dz});
                        if (it == cells.end()) continue;
                        for (uint32_t j : it->second)
                            if (j > i && (takeoffs_[j].sample.point - p).norm() <= reach) pairs.emplace_back(i, j);
                    }
            std::sort(pairs.begin() + first, pairs.end());
        }
        return pairs;
    }

    // The constraints that need no ray: rise, distance, facing, incline. Both directions at once:
    // every one of them is symmetric in the two ends.
    bool jump_constraints_hold(const Takeoff& a, const Takeoff& b) {
        const Vec3 d = b.sample.point - a.sample.point;
        const Vec3 flat(d.x(), 0.0f, d.z());
        const float distance = d.norm(), gap = flat.norm();
        if (gap < s_.min_link_distance || distance > s_.max_link_distance) {
            ++report_.rejected_distance;
            return false;
        }
        if (std::fabs(d.y()) > s_.max_jump_up) {
            ++report_.rejected_rise;
            return false;
        }
        const bool is_short = distance < s_.short_link_distance;
        const float forward = std::cos((is_short ? s_.permissive_forward_angle : s_.strict_forward_angle) * kDegrees);
        const float incline = std::sin((is_short ? s_.permissive_incline_angle : s_.strict_incline_angle) * kDegrees);
        const Vec3 heading = flat / gap, direction = d / distance;
        if (a.sample.outward.dot(heading) < forward || b.sample.outward.dot(-heading) < forward ||
            std::fabs(direction.dot(a.sample.normal)) > incline || std::fabs(direction.dot(b.sample.normal)) > incline) {
            ++report_.rejected_angle;
            return false;
        }
        return true;
    }

    // Which of `paths` an agent-sized body (of `radius`) passes along, in one occlusion batch.
    std::vector<bool> clear(const std::vector<std::vector<Vec3>>& paths, float radius) {
        std::vector<std::vector<Segment>> per_path(paths.size());
        tasks_.parallel_for(static_cast<uint32_t>(paths.size()), 64, [&](uint32_t begin, uint32_t end) {
            for (uint32_t i = begin; i < end; ++i)
                append_body_sweep(paths[i], Body{radius, body_.height}, s_.clearance_margin, per_path[i]);
        });
        std::vector<Segment> all;
        std::vector<size_t> first(paths.size() + 1, 0);
        for (size_t i = 0; i < paths.size(); ++i) first[i + 1] = first[i] + per_path[i].size();
        all.reserve(first.back());
        for (const auto& segments : per_path) all.insert(all.end(), segments.begin(), segments.end());
        const std::vector<uint8_t> hit = blocked(all);
        std::vector<bool> out(paths.size());
        for (size_t i = 0; i < paths.size(); ++i)
            out[i] = std::none_of(hit.begin() + first[i], hit.begin() + first[i + 1], [](uint8_t h) { return h != 0; });
        return out;
    }

    // The widest body (up to twice the agent's) that passes each already-clear path.
    void measure_clearance(const std::vector<std::vector<Vec3>>& paths, std::vector<Link>& links) {
        for (Link& l : links) l.requirements.clearance_width = 2.0f * body_.radius;
        for (float scale : {1.5f, 2.0f}) {
            std::vector<size_t> still;
            std::vector<std::vector<Vec3>> wider;
            for (size_t i = 0; i < links.size(); ++i) {
                if (links[i].requirements.clearance_width >= 2.0f * body_.radius * (scale - 0.5f) - 1e-6f) {
                    still.push_back(i);
                    wider.push_back(paths[i]);
                }
            }
            const std::vector<bool> ok = clear(wider, body_.radius * scale);
            for (size_t k = 0; k < still.size(); ++k)
                if (ok[k]) links[still[k]].requirements.clearance_width = 2.0f * body_.radius * scale;
        }
    }

    bool on_navmesh(const Vec3& point, uint32_t& polygon) const {
        const NavPoint p = mesh_.find_nearest(point, Vec3(0.1f, 0.5f, 0.1f));
        polygon = p.polygon;
        return p.found && p.distance < 0.3f;
    }

    // Step 3: edge to edge.
    std::vector<Link> find_jumps(CandidateSearch search) {
        const auto pairs = nearby_pairs(search);
        std::vector<Link> candidates;
        std::vector<std::pair<uint32_t, uint32_t>> ends;
        std::vector<std::vector<Vec3>> arcs;
        for (size_t k = 0; k < pairs.size(); ++k) {
            if ((k & 1023) == 0) step(0.15f + 0.2f * float(k) / pairs.size(), "jumps");
            const Takeoff& a = takeoffs_[pairs[k].first];
            const Takeoff& b = takeoffs_[pairs[k].second];
            if (!jump_constraints_hold(a, b)) continue;
            uint32_t landing_polygon = 0;
            if (!on_navmesh(b.sample.point, landing_polygon)) {
                ++report_.rejected_no_landing;
                continue;
            }
            const JumpArc arc = jump_arc(a.sample.point, b.sample.point, s_.jump_arc_height, s_.arc_segments);
            Link l;
            l.kind = LinkKind::Jump;
            l.start = a.sample.point;
            l.end = b.sample.point;
            l.apex = arc.apex;
            l.bidirectional = true;  // every jump constraint holds both ways
            l.generated = true;
            l.start_polygon = a.sample.polygon;
            l.end_polygon = b.sample.polygon;
            set_requirements(l);
            candidates.push_back(l);
            ends.push_back(pairs[k]);
            arcs.push_back(arc.points);
        }
        report_.jump_candidates = static_cast<uint32_t>(candidates.size());
        step(0.35f, "jump clearance");
        const std::vector<bool> ok = clear(arcs, body_.radius);
        std::vector<size_t> passed;
        for (size_t i = 0; i < candidates.size(); ++i) {
            if (ok[i]) passed.push_back(i);
            else ++report_.rejected_clearance;
        }
        const std::vector<size_t> kept = straightest_partners(passed, candidates, ends);
        std::vector<Link> links;
        std::vector<std::vector<Vec3>> kept_arcs;
        for (size_t i : kept) {
            links.push_back(candidates[i]);
            kept_arcs.push_back(arcs[i]);
        }
        measure_clearance(kept_arcs, links);
        return links;
    }

    // A take-off point faces a whole edge across a gap: of its links to that edge, only the most
    // head-on one is a distinct traversal (the others cross it diagonally). Best first: facing both
    // edges most squarely, then shortest, then by position in the take-off list.
    std::vector<size_t> straightest_partners(std::vector<size_t> passed, const std::vector<Link>& links,
                                             const std::vector<std::pair<uint32_t, uint32_t>>& ends) {
        auto squareness = [&](size_t i) {
            const Takeoff& a = takeoffs_[ends[i].first];
            const Takeoff& b = takeoffs_[ends[i].second];
            Vec3 heading = links[i].end - links[i].start;
            heading.y() = 0.0f;
            heading.normalize();
            return std::min(a.sample.outward.dot(heading), b.sample.outward.dot(-heading));
        };
        std::vector<float> score(links.size());
        for (size_t i : passed) score[i] = squareness(i);
        std::stable_sort(passed.begin(), passed.end(), [&](size_t x, size_t y) {
            if (score[x] != score[y]) return score[x] > score[y];
            if (links[x].requirements.gap != links[y].requirements.gap) return links[x].requirements.gap < links[y].requirements.gap;
            return ends[x] < ends[y];
        });
        std::unordered_map<uint64_t, bool> taken;  // (take-off point, edge across) already linked
        auto key = [](uint32_t takeoff, uint32_t edge) { return (uint64_t(takeoff) << 32) | edge; };
        std::vector<size_t> kept;
        for (size_t i : passed) {
            const auto [a, b] = ends[i];
            const uint64_t from_a = key(a, takeoffs_[b].sample.edge), from_b = key(b, takeoffs_[a].sample.edge);
            if (taken[from_a] || taken[from_b]) {
                ++report_.rejected_duplicate;
                continue;
            }
            taken[from_a] = taken[from_b] = true;
            kept.push_back(i);
        }
        std::sort(kept.begin(), kept.end());
        return kept;
    }

    // Step 4: edge to floor, probing below each take-off point along rotated outward directions.
    std::vector<Link> find_drops() {
        const float steep = s_.drop_steepness * kDegrees;
        const float reach = (s_.max_drop_distance + kProbeLift + 1.0f) / std::sin(steep);
        std::vector<Ray> probes;
        std::vector<Vec3> falloffs;
        std::vector<uint32_t> owner;
        for (uint32_t i = 0; i < takeoffs_.size(); ++i) {
            const EdgeSample& e = takeoffs_[i].sample;
            for (float angle : s_.drop_angles) {
                const Eigen::AngleAxisf turn(angle * kDegrees, Vec3::UnitY());
                const Vec3 heading = turn * e.outward;
                // Past the rim (found straight out; a turned probe starts as far out, plus a margin).
                const Vec3 falloff = e.point + heading * (takeoffs_[i].rim + 0.2f);
                const Vec3 direction = heading * std::cos(steep) + Vec3(0, -std::sin(steep), 0);
                probes.push_back(Ray{falloff + Vec3(0, kProbeLift, 0), direction.normalized(), reach});
                falloffs.push_back(falloff);
                owner.push_back(i);
            }
        }
        const std::vector<RayHit> hits = cast(probes);
        step(0.7f, "drops");

        std::vector<Link> candidates;
        std::vector<std::vector<Vec3>> falls;
        const Vec3 landing_box(std::max(body_.radius * 1.5f, 0.3f), 1.0f, std::max(body_.radius * 1.5f, 0.3f));
        for (size_t k = 0; k < probes.size(); ++k) {
            const Takeoff& a = takeoffs_[owner[k]];
            if (!hits[k].hit) {
                ++report_.rejected_no_landing;
                continue;
            }
            const NavPoint landing = mesh_.find_nearest(hits[k].point, landing_box);
            if (!landing.found || landing.polygon == a.sample.polygon) {
                ++report_.rejected_no_landing;
                continue;
            }
            const float drop = a.sample.point.y() - landing.point.y();
            if (drop <= mesh_.agent().max_climb || drop > s_.max_drop_distance) {
                ++report_.rejected_distance;
                continue;
            }
            Link l;
            l.kind = LinkKind::Drop;
            l.start = a.sample.point;
            l.end = landing.point;
            l.apex = l.start;
            l.bidirectional = drop <= s_.max_jump_up;  // low enough to jump back up
            l.generated = true;
            l.start_polygon = a.sample.polygon;
            l.end_polygon = landing.polygon;
            set_requirements(l);
            candidates.push_back(l);
            // Walk out over the edge, fall, land.
            const Vec3 over_landing(landing.point.x(), l.start.y(), landing.point.z());
            falls.push_back({l.start, Vec3(falloffs[k].x(), l.start.y(), falloffs[k].z()), over_landing, landing.point});
        }
        report_.drop_candidates = static_cast<uint32_t>(candidates.size());
        step(0.8f, "drop clearance");
        return keep_clear(std::move(candidates), falls);
    }

    static void set_requirements(Link& l) {
        const Vec3 d = l.end - l.start;
        l.requirements.gap = Vec3(d.x(), 0.0f, d.z()).norm();
        l.requirements.rise = std::max(0.0f, d.y());
        l.requirements.drop = std::max(0.0f, -d.y());
    }

    std::vector<Link> keep_clear(std::vector<Link> candidates, const std::vector<std::vector<Vec3>>& paths) {
        const std::vector<bool> ok = clear(paths, body_.radius);
        std::vector<Link> kept;
        std::vector<std::vector<Vec3>> kept_paths;
        for (size_t i = 0; i < candidates.size(); ++i) {
            if (!ok[i]) {
                ++report_.rejected_clearance;
                continue;
            }
            kept.push_back(candidates[i]);
            kept_paths.push_back(paths[i]);
        }
        measure_clearance(kept_paths, kept);
        return kept;
    }

    // Step 5: one link per traversal. Jumps come first, so a drop that repeats a jump goes; within a
    // kind, a fixed order of positions decides, so the result does not depend on thread count.
    std::vector<Link> merge(std::vector<Link> links) {
        auto order = [](const Link& l) {
            return std::make_tuple(static_cast<uint32_t>(l.kind), l.start.x(), l.start.z(), l.start.y(), l.end.x(),
                                   l.end.z(), l.end.y());
        };
        std::stable_sort(links.begin(), links.end(), [&](const Link& a, const Link& b) { return order(a) < order(b); });
        const float r = s_.merge_distance;
        auto same_traversal = [&](const Link& a, const Link& b) {
            if ((a.start - b.start).norm() <= r && (a.end - b.end).norm() <= r) return true;
            return (a.bidirectional || b.bidirectional) && (a.start - b.end).norm() <= r && (a.end - b.start).norm() <= r;
        };
        // Kept links indexed by the cell of both their ends, so either orientation is found.
        struct Key {
            int64_t x, z;
            bool operator==(const Key& o) const { return x == o.x && z == o.z; }
        };
        struct Hash {
            size_t operator()(const Key& k) const { return size_t(k.x * 73856093) ^ size_t(k.z * 19349663); }
        };
        const float cell = std::max(r, 1e-3f);
        auto key = [&](const Vec3& p) { return Key{int64_t(std::floor(p.x() / cell)), int64_t(std::floor(p.z() / cell))}; };
        std::unordered_map<Key, std::vector<uint32_t>, Hash> by_end;
        std::vector<Link> kept;
        for (const Link& l : links) {
            bool duplicate = false;
            const Key k = key(l.start);
            for (int64_t dz = -1; dz <= 1 && !duplicate; ++dz)
                for (int64_t dx = -1; dx <= 1 && !duplicate; ++dx) {
                    const auto it = by_end.find(Key{k.x + dx, k.z + dz});
                    if (it == by_end.end()) continue;
                    for (uint32_t j : it->second)
                        if (same_traversal(kept[j], l)) {
                            duplicate = true;
                            break;
                        }
                }
            if (duplicate) {
                ++report_.rejected_duplicate;
                continue;
            }
            const auto index = static_cast<uint32_t>(kept.size());
            by_end[key(l.start)].push_back(index);
            if (!(key(l.end) == key(l.start))) by_end[key(l.end)].push_back(index);
            kept.push_back(l);
        }
        return kept;
    }

    const NavMesh& mesh_;
    const Level& level_;
    TaskSystem& tasks_;
    const LinkSettings& s_;
    BakeReport& report_;
    BakeProgress progress_;
    Body body_;
    std::vector<Takeoff> takeoffs_;
};

}  // namespace

std::vector<Link> generate_links(const NavMesh& navmesh, const Level& level, TaskSystem& tasks, const LinkSettings& settings,
                                 CandidateSearch search, BakeReport& report, BakeProgress progress) {
    validate(settings, "settings->");
    report = BakeReport{};
    return Generator(navmesh, level, tasks, settings, report, progress).run(search);
}

}  // namespace nl
