// Jumps, the second stage of a link generation pass: pairs of take-off points across a gap, their gaps
// measured along their lines, the arcs swept as the ranking reaches them; and the jumps kept.
#include "links/generation_stage.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>
#include "links/trajectory.h"

namespace nl::generation {
namespace {

class JumpFinding : public GenerationStage {
public:
    using GenerationStage::GenerationStage;

    // How far out along `heading` a take-off point's rim is looked for: as far as falloff_distance
    // straight out reaches along it, and never past the other end.
    float rim_reach(const Vec3& outward, const Vec3& heading, float length) const {
        return std::min(settings_.falloff_distance / std::max(outward.dot(heading), 1e-3f), length);
    }

    // What the geometry-free tests say of a pair of take-off points, for the report.
    enum class PairVerdict : uint8_t { Candidate, Ignored, Distance, Rise, Angle, Walkable };

    // The grid the Indexed search finds partners in: cells as wide as the reach, so that a partner
    // is in the 27 cells around a point.
    struct CellKey {
        int64_t x, y, z;
        bool operator==(const CellKey& o) const { return x == o.x && y == o.y && z == o.z; }
    };
    struct CellHash {
        size_t operator()(const CellKey& k) const {
            return size_t(uint64_t(k.x) * 73856093u ^ uint64_t(k.y) * 19349663u ^ uint64_t(k.z) * 83492791u);
        }
    };
    using TakeoffGrid = std::unordered_map<CellKey, std::vector<uint32_t>, CellHash>;

    // How far apart two take-off points can be and still be worth a look: ends up to twice the
    // widest gap apart, each end up to falloff_distance inside its rim, one up to max_jump_up above
    // the other (so the report can say that two facing edges were too far apart). Never finer than
    // a centimetre: cell keys stay far inside int64 within the coordinate limit.
    float pair_reach() const {
        return std::max(2.0f * settings_.max_jump_gap + 2.0f * settings_.falloff_distance + settings_.max_jump_up,
                        0.01f);
    }

    CellKey cell_of(const Vec3& p) const {
        const float reach = pair_reach();
        return CellKey{int64_t(std::floor(p.x() / reach)), int64_t(std::floor(p.y() / reach)),
                       int64_t(std::floor(p.z() / reach))};
    }

    // Appends the take-off points after `valid[x]` (by sample index) within reach of it, in order:
    // from the grid's 27 cells (Indexed) or from every later one (BruteForce).
    void partners_after(const std::vector<uint32_t>& valid, size_t x, const TakeoffGrid& grid,
                        std::vector<uint32_t>& out) const {
        const uint32_t i = valid[x];
        const Vec3& p = samples_[i].point;
        const float reach = pair_reach();
        if (method_ == GenerationMethod::BruteForce) {
            for (size_t y = x + 1; y < valid.size(); ++y)
                if ((samples_[valid[y]].point - p).norm() <= reach) out.push_back(valid[y]);
            return;
        }
        const CellKey k = cell_of(p);
        for (int64_t dz = -1; dz <= 1; ++dz)
            for (int64_t dy = -1; dy <= 1; ++dy)
                for (int64_t dx = -1; dx <= 1; ++dx) {
                    const auto it = grid.find(CellKey{k.x + dx, k.y + dy, k.z + dz});
                    if (it == grid.end()) continue;
                    for (uint32_t j : it->second)
                        if (j > i && (samples_[j].point - p).norm() <= reach) out.push_back(j);
                }
        std::sort(out.begin(), out.end());
    }

    // The constraints that need no ray, between the floor points of two take-off points: gap,
    // rise, facing, incline, and whether walking is about as short. Both directions at
    // once: every one of them is symmetric in the two ends. The gap is measured later, per candidate
    // (measure_jump_gaps); here only its lower bound counts: the length less both rims' reach.
    PairVerdict judge_pair(const LinkGeneration::Cache& c, uint32_t i, uint32_t j) const {
        const EdgeSample &a = samples_[i], &b = samples_[j];
        const Vec3 d = floor_point(c, j) - floor_point(c, i);
        const Vec3 flat(d.x(), 0.0f, d.z());
        const float distance = d.norm(), length = flat.norm();
        const Vec3 heading = length > 0.0f ? Vec3(flat / length) : Vec3::Zero();
        const bool is_short = distance < settings_.short_link_distance;
        const float forward =
            std::cos((is_short ? settings_.permissive_forward_angle : settings_.strict_forward_angle) * kDegrees);
        const bool facing = length > 0.0f && a.outward.dot(heading) >= forward && b.outward.dot(-heading) >= forward;
        const float gap = length - rim_reach(a.outward, heading, length) - rim_reach(b.outward, -heading, length);
        // Only edges that face each other are worth reporting as too far apart.
        if (gap > settings_.max_jump_gap) return facing ? PairVerdict::Distance : PairVerdict::Ignored;
        if (length < settings_.min_link_distance) return PairVerdict::Distance;
        if (std::fabs(d.y()) > settings_.max_jump_up) return PairVerdict::Rise;
        const float incline =
            std::sin((is_short ? settings_.permissive_incline_angle : settings_.strict_incline_angle) * kDegrees);
        const Vec3 direction = d / distance;
        if (!facing || std::fabs(direction.dot(a.normal)) > incline || std::fabs(direction.dot(b.normal)) > incline)
            return PairVerdict::Angle;
        const float walk = walk_.walk_within(a.point, a.polygon, b.point, b.polygon,
                                             settings_.walk_factor * length + settings_.walk_distance);
        return std::isfinite(walk) ? PairVerdict::Walkable : PairVerdict::Candidate;
    }

    void count(PairVerdict verdict, uint32_t pairs) {
        switch (verdict) {
            case PairVerdict::Distance: report_.rejected_distance += pairs; break;
            case PairVerdict::Rise: report_.rejected_rise += pairs; break;
            case PairVerdict::Angle: report_.rejected_angle += pairs; break;
            case PairVerdict::Walkable: report_.rejected_walkable += pairs; break;
            case PairVerdict::Candidate:
            case PairVerdict::Ignored: break;
        }
    }

    // A pair that met every geometry-free constraint: reused from the old cache (with its sweep, if it
    // had one) when the box cannot have changed it and its ends are where they were; else a new
    // candidate, to be swept if the ranking reaches it (decide_jumps). `unmeasured` receives the keys
    // of the candidates whose gap is to be measured (new ones, and those whose rims the box may move).
    void add_jump_candidate(uint32_t a, uint32_t b, LinkGeneration::Cache& next, std::vector<uint64_t>& unmeasured) {
        const uint64_t key = pair_key(a, b);
        const Vec3 start = floor_point(next, a), end = floor_point(next, b);
        const auto cached = old_.jumps.find(key);
        if (cached != old_.jumps.end() && !touches(cached->second.sweep.bounds, box_) &&
            cached->second.link.start == start && cached->second.link.end == end) {
            next.jumps.emplace(key, cached->second);
            if (touches(cached->second.rim_bounds, box_)) unmeasured.push_back(key);
            return;
        }
        LinkGeneration::JumpCandidate c;
        c.a = a;
        c.b = b;
        c.link.kind = LinkKind::Jump;
        c.link.start = start;
        c.link.end = end;
        c.link.apex = JumpArc(start, end, settings_.jump_arc_height).apex();
        c.link.arc_height = settings_.jump_arc_height;
        c.link.bidirectional = true;  // every jump constraint holds both ways
        c.link.generated = true;
        c.link.start_polygon = samples_[a].polygon;
        c.link.end_polygon = samples_[b].polygon;
        set_requirements_from_ends(c.link);
        next.jumps.emplace(key, c);
        unmeasured.push_back(key);
    }

    // The gap of each candidate in `keys`, measured where the body flies: the line between its ends less
    // how far the ground reaches out along that line from each end. A candidate whose gap is then
    // wider than max_jump_gap is out, as is one along whose line the ground does not fall away within
    // an end's reach (the ends' take-off points each have a rim straight out, not along every line).
    void measure_jump_gaps(LinkGeneration::Cache& next, std::vector<uint64_t> keys) {
        std::sort(keys.begin(), keys.end());  // the rays' order, whatever the map's
        std::vector<RimQuery> queries;
        for (uint64_t key : keys) {
            const LinkGeneration::JumpCandidate& c = next.jumps.at(key);
            const float length = c.link.requirements.length;  // horizontal, > 0: judge_pair kept only ends apart
            const Vec3 heading =
                Vec3(c.link.end.x() - c.link.start.x(), 0.0f, c.link.end.z() - c.link.start.z()) / length;
            const uint32_t ends[2] = {c.a, c.b};
            for (int side = 0; side < 2; ++side) {
                const Vec3 out = side == 0 ? heading : Vec3(-heading);
                const float reach = rim_reach(samples_[ends[side]].outward, out, length);
                const LinkGeneration::TakeoffState& t = next.takeoffs[ends[side]];
                queries.push_back(RimQuery{samples_[ends[side]].point, out, t.ground_y, reach, std::nullopt});
            }
        }
        std::vector<Aabb> bounds(queries.size());
        for (size_t q = 0; q < queries.size(); ++q) bounds[q] = rim_search_bounds(queries[q], rim_probing_);
        const std::vector<float> rims = find_rims(level_, tasks_, std::move(queries), rim_probing_, report_.rays_cast);
        for (size_t n = 0; n < keys.size(); ++n) {
            LinkGeneration::JumpCandidate& c = next.jumps.at(keys[n]);
            const float rim_a = rims[2 * n], rim_b = rims[2 * n + 1];
            c.rim_bounds = bounds[2 * n];
            grow(c.rim_bounds, bounds[2 * n + 1]);
            const float gap = std::max(0.0f, c.link.requirements.length - rim_a - rim_b);
            c.gap_within = rim_a >= 0.0f && rim_b >= 0.0f && gap <= settings_.max_jump_gap;
            c.link.requirements.gap = gap;
        }
    }

    // A take-off point faces a whole edge across a gap: of its clear jumps to that edge, only the
    // most head-on one is a distinct traversal (the others cross it diagonally). The candidates are
    // ranked, best first: facing both edges most squarely, then the narrowest gap, then by take-off
    // order; going down the ranking, one is kept if it is clear and neither end's take-off point is
    // linked to the other end's edge yet. So a candidate needs a sweep only when the ranking reaches
    // it: this walks the ranking and either returns the kept candidates (every one it reached was
    // swept) or fills `pending` with the candidates to sweep next (those the walk reached unswept,
    // and no later one that the outcome of theirs could exclude). `report` counts the rejections of
    // a finished walk.
    std::vector<const LinkGeneration::JumpCandidate*> walk_jump_ranking(const LinkGeneration::Cache& c,
                                                                        std::vector<uint64_t>* pending,
                                                                        LinkGenerationReport* report) const {
        auto squareness = [&](const LinkGeneration::JumpCandidate& j) {
            Vec3 heading = j.link.end - j.link.start;
            heading.y() = 0.0f;
            heading.normalize();
            return std::min(samples_[j.a].outward.dot(heading), samples_[j.b].outward.dot(-heading));
        };
        std::vector<std::pair<float, const LinkGeneration::JumpCandidate*>> ranked;
        ranked.reserve(c.jumps.size());
        for (const auto& [key, j] : c.jumps)
            if (j.gap_within) ranked.emplace_back(squareness(j), &j);
        std::sort(ranked.begin(), ranked.end(), [](const auto& x, const auto& y) {
            if (x.first != y.first) return x.first > y.first;
            if (x.second->link.requirements.gap != y.second->link.requirements.gap)
                return x.second->link.requirements.gap < y.second->link.requirements.gap;
            return std::make_pair(x.second->a, x.second->b) < std::make_pair(y.second->a, y.second->b);
        });
        std::unordered_set<uint64_t> taken, waiting;  // (take-off point, edge across): linked, or awaiting a sweep
        std::vector<const LinkGeneration::JumpCandidate*> kept;
        for (const auto& [score, j] : ranked) {
            const uint64_t from_a = pair_key(j->a, samples_[j->b].edge), from_b = pair_key(j->b, samples_[j->a].edge);
            if (taken.count(from_a) || taken.count(from_b)) {
                if (report) ++report->rejected_duplicate;
                continue;
            }
            if (waiting.count(from_a) || waiting.count(from_b)) continue;  // decided by an earlier one's sweep
            if (!j->sweep.swept) {
                if (pending) pending->push_back(pair_key(j->a, j->b));
                waiting.insert(from_a);
                waiting.insert(from_b);
                continue;
            }
            if (!j->sweep.clear) {
                if (report) ++report->rejected_clearance;
                continue;
            }
            taken.insert(from_a);
            taken.insert(from_b);
            kept.push_back(j);
        }
        return kept;
    }

    // Sweeps the candidates the ranking reaches, a round at a time, until it is decided.
    void decide_jumps(LinkGeneration::Cache& next) {
        for (;;) {
            std::vector<uint64_t> pending;
            walk_jump_ranking(next, &pending, nullptr);
            if (pending.empty()) return;
            std::sort(pending.begin(), pending.end());  // a batch in a fixed order, whatever the map's
            std::vector<std::pair<Vec3, Vec3>> ends;
            for (uint64_t key : pending) ends.emplace_back(next.jumps[key].link.start, next.jumps[key].link.end);
            const std::vector<LinkGeneration::Sweep> swept = sweep_arcs(ends);
            for (size_t n = 0; n < pending.size(); ++n) next.jumps[pending[n]].sweep = swept[n];
        }
    }

    // Jump candidates: the geometry-free constraints over every pair (cheap, so always redone, in
    // parallel over take-off points, a block at a time so progress can cancel), then the arc sweep,
    // reused from the old cache unless geometry in the box could have changed it.
    void run(LinkGeneration::Cache& next) {
        std::vector<uint32_t> valid;
        for (uint32_t i = 0; i < samples_.size(); ++i)
            if (next.takeoffs[i].valid) valid.push_back(i);
        report_.takeoff_points = static_cast<uint32_t>(valid.size());
        TakeoffGrid grid;
        if (method_ == GenerationMethod::Indexed)
            for (uint32_t i : valid) grid[cell_of(samples_[i].point)].push_back(i);

        constexpr size_t kBlock = 2048;
        std::vector<std::vector<uint32_t>> candidates(kBlock);  // partners
        std::vector<uint64_t> unmeasured;
        std::vector<std::array<uint32_t, 6>> verdicts(kBlock);
        for (size_t block = 0; block < valid.size(); block += kBlock) {
            if (block > 0) step(0.15f + 0.2f * float(block) / float(valid.size()), "jumps");
            const auto size = static_cast<uint32_t>(std::min(kBlock, valid.size() - block));
            tasks_.parallel_for(size, 16, [&](uint32_t begin, uint32_t end) {
                std::vector<uint32_t> partners;
                for (uint32_t n = begin; n < end; ++n) {
                    const uint32_t a = valid[block + n];
                    partners.clear();
                    partners_after(valid, block + n, grid, partners);
                    candidates[n].clear();
                    verdicts[n] = {};
                    for (uint32_t b : partners) {
                        const PairVerdict verdict = judge_pair(next, a, b);
                        ++verdicts[n][static_cast<size_t>(verdict)];
                        if (verdict == PairVerdict::Candidate) candidates[n].push_back(b);
                    }
                }
            });
            for (uint32_t n = 0; n < size; ++n) {
                for (size_t v = 0; v < verdicts[n].size(); ++v) count(static_cast<PairVerdict>(v), verdicts[n][v]);
                for (uint32_t b : candidates[n]) add_jump_candidate(valid[block + n], b, next, unmeasured);
            }
        }
        measure_jump_gaps(next, std::move(unmeasured));
        report_.jump_candidates = 0;
        for (const auto& [key, j] : next.jumps)
            (j.gap_within ? report_.jump_candidates : report_.rejected_distance) += 1;
        step(0.35f, "jump clearance");
        decide_jumps(next);
    }

    // The kept jumps (walk_jump_ranking), in take-off order.
    std::vector<Link> straightest_jumps(const LinkGeneration::Cache& c) {
        std::vector<const LinkGeneration::JumpCandidate*> kept = walk_jump_ranking(c, nullptr, &report_);
        std::sort(kept.begin(), kept.end(),
                  [](const auto* x, const auto* y) { return std::make_pair(x->a, x->b) < std::make_pair(y->a, y->b); });
        std::vector<Link> links;
        for (const auto* j : kept) {
            links.push_back(j->link);
            links.back().requirements.clearance_width = j->sweep.width;
        }
        return links;
    }
};

}  // namespace

void find_jumps(PassInputs& in, LinkGeneration::Cache& next) { JumpFinding(in).run(next); }

std::vector<Link> straightest_jumps(PassInputs& in, const LinkGeneration::Cache& c) {
    return JumpFinding(in).straightest_jumps(c);
}

}  // namespace nl::generation
