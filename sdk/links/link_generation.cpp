#include "links/link_generation.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <unordered_set>

#include "links/clearance.h"
#include "links/link_merge.h"
#include "links/rim_search.h"
#include "motion/trajectory.h"
#include "navmesh/walk_graph.h"
#include "util/error.h"

namespace nl {
namespace {

constexpr float kDegrees = 3.14159265358979f / 180.0f;
constexpr float kProbeLift = 0.5f;  // probes start this far above the navmesh: clear of the floor,
                                    // and below any ceiling (the navmesh has agent height above it)
constexpr float kFloorReach = 2.0f; // a link end's floor is looked for this far below kProbeLift
constexpr float kPastRim = 0.2f;    // a drop's fall starts this far past the rim
constexpr float kPad = 1e-3f;       // bounds are padded: a surface exactly on them still counts

struct Stopwatch {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double ms = std::chrono::duration<double, std::milli>(now - start).count();
        start = now;
        return ms;
    }
};

uint64_t pair_key(uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; }

Aabb bounds_of(std::initializer_list<Vec3> points) {
    Aabb box;
    for (const Vec3& p : points) box.grow(p);
    return box;
}

void grow(Aabb& box, const Aabb& other) {
    box.grow(other.min);
    box.grow(other.max);
}

bool touches(const Aabb& a, const Aabb* box) {
    if (!box) return true;  // a full generation recomputes everything
    return (a.min.array() - kPad <= box->max.array()).all() && (a.max.array() + kPad >= box->min.array()).all();
}

// One generation or update: fills `next` from the old cache and new rays.
class GenerationPass {
public:
    GenerationPass(const NavMesh& mesh, const EdgeSampling& sampling, const LinkSettings& s, GenerationMethod method,
          const LinkGeneration::Cache& old, const Aabb* box, const Level& level, TaskSystem& tasks, LinkGenerationReport& report,
          GenerationProgress progress)
        : mesh_(mesh), samples_(sampling.samples), s_(s), method_(method), old_(old), box_(box), level_(level),
          tasks_(tasks), report_(report), progress_(progress), body_{mesh.agent().radius, mesh.agent().height}, walk_(mesh) {
        // Probes start above the floor by at most half the body (a low ceiling over the edge is not
        // ground) and count as ground anything within a walkable step below it.
        rim_probing_.lift = std::min(kProbeLift, 0.5f * body_.height);
        rim_probing_.step_reach = rim_probing_.lift + mesh.agent().max_climb + 0.05f;
        rim_probing_.floor_shortcut = method == GenerationMethod::Indexed;
    }

    std::vector<Link> run(LinkGeneration::Cache& next) {
        Stopwatch stage;
        step(0.05f, "take-off points");
        probe_takeoffs(next);
        report_.milliseconds_takeoff = stage.lap();
        step(0.15f, "jumps");
        find_jumps(next);
        report_.milliseconds_jumps = stage.lap();
        step(0.55f, "drops");
        find_drops(next);
        report_.milliseconds_drops = stage.lap();
        step(0.95f, "merge");
        std::vector<Link> links = select(next);
        report_.milliseconds_merge = stage.lap();
        return links;
    }

private:
    void step(float fraction, const char* stage) {
        if (!progress_(fraction, stage)) fail(ErrorCode::Cancelled, "the generation was cancelled during '", stage, "'");
    }

    std::vector<RayHit> cast(const std::vector<Ray>& rays) {
        std::vector<RayHit> hits(rays.size());
        level_.cast_rays(rays.data(), static_cast<uint32_t>(rays.size()), hits.data());
        report_.rays_cast += rays.size();
        return hits;
    }

    std::vector<RayHit> first_hits(const std::vector<Segment>& segments) {
        std::vector<RayHit> hits(segments.size());
        level_.segments_first_hit(segments.data(), static_cast<uint32_t>(segments.size()), hits.data());
        report_.rays_cast += segments.size();
        return hits;
    }

    std::vector<uint8_t> blocked(const std::vector<Segment>& segments) {
        std::vector<uint8_t> out(segments.size());
        level_.segments_blocked(segments.data(), static_cast<uint32_t>(segments.size()), out.data());
        report_.rays_cast += segments.size();
        return out;
    }

    // Take-off points: samples past whose edge the ground falls away (the rim: the first probe, every
    // RimSearch::kStep out to falloff_distance, with no ground within a step below), with nothing solid
    // between the edge and the rim. Recast leaves its edges 0.6 to 0.9 m inside the rim, depending
    // on how the voxel grid falls, so the rim is searched for, not assumed.
    void probe_takeoffs(LinkGeneration::Cache& next) {
        next.takeoffs.resize(samples_.size());
        std::vector<uint32_t> redo;
        for (uint32_t i = 0; i < samples_.size(); ++i) {
            if (old_.takeoffs.size() == samples_.size() && !touches(old_.takeoffs[i].bounds, box_)) next.takeoffs[i] = old_.takeoffs[i];
            else redo.push_back(i);
        }
        std::vector<Ray> ground_rays;
        for (uint32_t i : redo) ground_rays.push_back(Ray{samples_[i].point + Vec3(0, rim_probing_.lift, 0), Vec3(0, -1, 0), rim_probing_.lift + 1.5f});
        const std::vector<RayHit> ground = cast(ground_rays);
        // Indexed generations first try the last triangle found under the sample (by the ground ray, then
        // by each probe cast): a probe that crosses it well inside is on ground without a ray.
        std::vector<std::optional<std::array<Vec3, 3>>> floor(redo.size());
        if (rim_probing_.floor_shortcut) level_.static_triangles(ground.data(), static_cast<uint32_t>(ground.size()), floor.data());
        std::vector<RimQuery> queries(redo.size());
        for (size_t k = 0; k < redo.size(); ++k) {
            const EdgeSample& e = samples_[redo[k]];
            LinkGeneration::TakeoffState& t = next.takeoffs[redo[k]];
            t = LinkGeneration::TakeoffState{};
            // Correction for navmeshes that sit above the floor (Recast's rounds up) or sink into it.
            t.ground_y = ground[k].hit ? ground[k].point.y() : e.point.y();
            queries[k] = RimQuery{e.point, e.outward, t.ground_y, s_.falloff_distance, floor[k]};
            // Every probe the rim search may cast, so a change anywhere along it redoes the sample.
            t.bounds = bounds_of({e.point + Vec3(0, rim_probing_.lift, 0), e.point - Vec3(0, 1.5f, 0)});
            grow(t.bounds, rim_search_bounds(queries[k], rim_probing_));
        }
        const std::vector<float> rims = find_rims(level_, tasks_, std::move(queries), rim_probing_, report_.rays_cast);
        for (size_t k = 0; k < redo.size(); ++k) next.takeoffs[redo[k]].rim = rims[k];

        std::vector<Segment> walls;
        std::vector<uint32_t> ledges;
        const Vec3 chest(0, std::min(0.5f * body_.height, 1.0f), 0);
        for (size_t k = 0; k < redo.size(); ++k) {
            LinkGeneration::TakeoffState& t = next.takeoffs[redo[k]];
            const EdgeSample& e = samples_[redo[k]];
            if (t.rim < 0.0f) {
                t.rejected = 2;
                continue;
            }
            const Vec3 foot(e.point.x(), t.ground_y, e.point.z());
            walls.push_back(Segment{foot + chest, foot + e.outward * t.rim + chest});
            t.bounds.grow(walls.back().from);
            t.bounds.grow(walls.back().to);
            ledges.push_back(redo[k]);
        }
        const std::vector<uint8_t> wall = blocked(walls);
        for (size_t k = 0; k < ledges.size(); ++k) {
            LinkGeneration::TakeoffState& t = next.takeoffs[ledges[k]];
            t.valid = !wall[k];
            t.rejected = wall[k] ? 1 : 0;
        }
    }

    // The floor under a take-off point: its sample's x and z, the height of the level found under it.
    Vec3 floor_point(const LinkGeneration::Cache& c, uint32_t i) const {
        return Vec3(samples_[i].point.x(), c.takeoffs[i].ground_y, samples_[i].point.z());
    }

    // How far out along `heading` a take-off point's rim is looked for: as far as falloff_distance
    // straight out reaches along it, and never past the other end.
    float rim_reach(const Vec3& outward, const Vec3& heading, float length) const {
        return std::min(s_.falloff_distance / std::max(outward.dot(heading), 1e-3f), length);
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
        return std::max(2.0f * s_.max_jump_gap + 2.0f * s_.falloff_distance + s_.max_jump_up, 0.01f);
    }

    CellKey cell_of(const Vec3& p) const {
        const float reach = pair_reach();
        return CellKey{int64_t(std::floor(p.x() / reach)), int64_t(std::floor(p.y() / reach)), int64_t(std::floor(p.z() / reach))};
    }

    // Appends the take-off points after `valid[x]` (by sample index) within reach of it, in order:
    // from the grid's 27 cells (Indexed) or from every later one (BruteForce).
    void partners_after(const std::vector<uint32_t>& valid, size_t x, const TakeoffGrid& grid, std::vector<uint32_t>& out) const {
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
        const bool is_short = distance < s_.short_link_distance;
        const float forward = std::cos((is_short ? s_.permissive_forward_angle : s_.strict_forward_angle) * kDegrees);
        const bool facing = length > 0.0f && a.outward.dot(heading) >= forward && b.outward.dot(-heading) >= forward;
        const float gap = length - rim_reach(a.outward, heading, length) - rim_reach(b.outward, -heading, length);
        // Only edges that face each other are worth reporting as too far apart.
        if (gap > s_.max_jump_gap) return facing ? PairVerdict::Distance : PairVerdict::Ignored;
        if (length < s_.min_link_distance) return PairVerdict::Distance;
        if (std::fabs(d.y()) > s_.max_jump_up) return PairVerdict::Rise;
        const float incline = std::sin((is_short ? s_.permissive_incline_angle : s_.strict_incline_angle) * kDegrees);
        const Vec3 direction = d / distance;
        if (!facing || std::fabs(direction.dot(a.normal)) > incline || std::fabs(direction.dot(b.normal)) > incline)
            return PairVerdict::Angle;
        const float walk = walk_.walk_within(a.point, a.polygon, b.point, b.polygon, s_.walk_factor * length + s_.walk_distance);
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
        if (cached != old_.jumps.end() && !touches(cached->second.sweep.bounds, box_) && cached->second.link.start == start &&
            cached->second.link.end == end) {
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
        c.link.apex = JumpArc(start, end, s_.jump_arc_height).apex();
        c.link.arc_height = s_.jump_arc_height;
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
            Vec3 flat = c.link.end - c.link.start;
            flat.y() = 0.0f;
            const float length = flat.norm();
            const Vec3 heading = flat / length;  // judge_pair kept only ends apart
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
            Vec3 flat = c.link.end - c.link.start;
            flat.y() = 0.0f;
            const float gap = std::max(0.0f, flat.norm() - rim_a - rim_b);
            c.gap_within = rim_a >= 0.0f && rim_b >= 0.0f && gap <= s_.max_jump_gap;
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
    std::vector<const LinkGeneration::JumpCandidate*> walk_jump_ranking(const LinkGeneration::Cache& c, std::vector<uint64_t>* pending,
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

    // Sweeps the jump arcs between each pair of ends (from the first to the second).
    std::vector<LinkGeneration::Sweep> sweep_arcs(const std::vector<std::pair<Vec3, Vec3>>& ends) {
        const double piece = 1.0 / s_.arc_segments;
        std::vector<std::vector<Vec3>> arcs(ends.size());
        std::vector<PathPoints> paths(ends.size());
        for (size_t n = 0; n < ends.size(); ++n) {
            const JumpArc arc(ends[n].first, ends[n].second, s_.jump_arc_height);
            arcs[n] = arc.points(s_.arc_segments);
            paths[n] = PathPoints{arcs[n].data(), arcs[n].size(), arc.sagitta(0.0, piece)};
        }
        return sweep(paths);
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

    // Sweeps each path with the agent's body and bodies 1.5 and 2 times as wide (Body, kSweepRadii),
    // every piece tested exactly against the triangles near it: a path is clear if the agent's body
    // touches nothing anywhere along it, and as wide as the widest body that touches nothing. Indexed
    // generations ask the level for the triangles around each straight run of pieces once (a run through
    // open air costs that one query) and test the run's pieces against those; brute-force generations ask
    // for each piece on its own.
    std::vector<LinkGeneration::Sweep> sweep(const std::vector<PathPoints>& paths) {
        std::vector<LinkGeneration::Sweep> out(paths.size());
        std::vector<std::vector<SweepPiece>> pieces(paths.size());
        std::vector<std::vector<PieceRun>> runs(paths.size());
        const float widest = kSweepRadii[kSweepRadiusCount - 1] * body_.radius;
        tasks_.parallel_for(static_cast<uint32_t>(paths.size()), 64, [&](uint32_t begin, uint32_t end) {
            for (uint32_t i = begin; i < end; ++i) {
                pieces[i] = sweep_pieces(paths[i], s_.clearance_margin, body_.radius);
                if (method_ == GenerationMethod::Indexed) runs[i] = straight_runs(pieces[i]);
                Aabb& b = out[i].bounds;
                for (size_t n = 0; n < paths[i].count; ++n) b.grow(paths[i].points[n]);
                b.min -= Vec3(widest, paths[i].slack, widest);
                b.max += Vec3(widest, body_.height + paths[i].slack, widest);
            }
        });
        // Stretches in path order; groups: each path's runs, then its pieces in no run, one each.
        std::vector<size_t> first_piece(paths.size() + 1, 0);
        for (size_t i = 0; i < paths.size(); ++i) first_piece[i + 1] = first_piece[i] + pieces[i].size();
        const auto piece_count = static_cast<uint32_t>(first_piece.back());
        std::vector<BodyStretch> stretches(piece_count);
        std::vector<uint32_t> group_first(paths.size() + 1, 0);
        for (size_t i = 0; i < paths.size(); ++i) {
            uint32_t in_runs = 0;
            for (const PieceRun& run : runs[i]) in_runs += run.last - run.first;
            group_first[i + 1] = group_first[i] + static_cast<uint32_t>(runs[i].size() + pieces[i].size() - in_runs);
        }
        std::vector<BodyGroup> groups(group_first.back());
        tasks_.parallel_for(static_cast<uint32_t>(paths.size()), 64, [&](uint32_t begin, uint32_t end) {
            for (uint32_t i = begin; i < end; ++i) {
                const auto base = static_cast<uint32_t>(first_piece[i]);
                for (size_t k = 0; k < pieces[i].size(); ++k) stretches[base + k] = stretch_of(pieces[i][k], body_, widest);
                uint32_t g = group_first[i], next = 0;
                for (const PieceRun& run : runs[i]) {
                    for (; next < run.first; ++next) groups[g++] = BodyGroup{stretches[base + next].bounds, base + next, 1};
                    groups[g++] = BodyGroup{run_box(pieces[i], run, body_, widest), base + run.first, run.last - run.first};
                    next = run.last;
                }
                for (; next < pieces[i].size(); ++next) groups[g++] = BodyGroup{stretches[base + next].bounds, base + next, 1};
            }
        });
        std::array<float, kSweepRadiusCount> radii;
        for (unsigned r = 0; r < kSweepRadiusCount; ++r) radii[r] = kSweepRadii[r] * body_.radius;
        std::vector<uint8_t> cleared(piece_count, 0);
        report_.body_tests += level_.bodies_clear(groups.data(), static_cast<uint32_t>(groups.size()), stretches.data(),
                                                  radii.data(), kSweepRadiusCount, cleared.data());
        report_.box_queries += groups.size();
        for (size_t i = 0; i < paths.size(); ++i) {
            uint8_t fewest = kSweepRadiusCount;
            for (size_t k = first_piece[i]; k < first_piece[i + 1]; ++k) fewest = std::min(fewest, cleared[k]);
            out[i].swept = true;
            out[i].clear = fewest > 0;
            out[i].width = fewest > 0 ? 2.0f * radii[fewest - 1] : 0.0f;
        }
        return out;
    }

    // Point location through the navmesh's polygon grid, or over every polygon (brute force).
    NavPoint locate(const Vec3& point, const Vec3& half_extents) const {
        return method_ == GenerationMethod::Indexed ? mesh_.find_nearest(point, half_extents)
                                              : mesh_.find_nearest_brute_force(point, half_extents);
    }


    // Jump candidates: the geometry-free constraints over every pair (cheap, so always redone, in
    // parallel over take-off points, a block at a time so progress can cancel), then the arc sweep,
    // reused from the old cache unless geometry in the box could have changed it.
    void find_jumps(LinkGeneration::Cache& next) {
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
        for (const auto& [key, j] : next.jumps) (j.gap_within ? report_.jump_candidates : report_.rejected_distance) += 1;
        step(0.35f, "jump clearance");
        decide_jumps(next);
    }

    // Drops: probes down from past the rim along rotated outward directions, then the fall's sweep.
    void find_drops(LinkGeneration::Cache& next) {
        const float steep = s_.drop_steepness * kDegrees;
        const float reach = (s_.max_drop_distance + kProbeLift + 1.0f) / std::sin(steep);
        const auto angles = static_cast<uint32_t>(s_.drop_angles.size());
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
            headings[k] = Eigen::AngleAxisf(s_.drop_angles[angle] * kDegrees, Vec3::UnitY()) * e.outward;
            d.rim = next.takeoffs[i].rim;
            d.bounds = Aabb{};
            if (s_.drop_angles[angle] == 0.0f) continue;
            const float reach = s_.falloff_distance / std::cos(s_.drop_angles[angle] * kDegrees);
            turned.push_back(RimQuery{e.point, headings[k], next.takeoffs[i].ground_y, reach, std::nullopt});
            grow(d.bounds, rim_search_bounds(turned.back(), rim_probing_));
            turned_of.push_back(k);
        }
        const std::vector<float> rims = find_rims(level_, tasks_, std::move(turned), rim_probing_, report_.rays_cast);
        for (size_t n = 0; n < turned_of.size(); ++n) next.drops[probed[turned_of[n]]].rim = rims[n];
        std::vector<uint32_t> off_rim;  // positions in `probed` of the probes cast
        for (uint32_t k = 0; k < probed.size(); ++k) {
            LinkGeneration::DropProbe& d = next.drops[probed[k]];
            if (d.rim >= 0.0f) off_rim.push_back(k);
            else d.outcome = 1;
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
            for (uint32_t k : round) paths.push_back(PathPoints{next.drops[k].fall.data(), next.drops[k].fall.size(), 0.0f});
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
            auto turn = [&](uint32_t k) { return std::fabs(s_.drop_angles[static_cast<uint32_t>(c.drops[k].key)]); };
            std::stable_sort(landed.begin(), landed.end(), [&](uint32_t x, uint32_t y) { return turn(x) < turn(y); });
            ways.clear();
            for (uint32_t k : landed) {
                const Link& b = c.drops[k].link;
                auto same = std::find_if(ways.begin(), ways.end(), [&](const std::vector<uint32_t>& way) {
                    const Link& a = c.drops[way.front()].link;
                    return walk_.surface(a.end_polygon) == walk_.surface(b.end_polygon) &&
                           std::fabs(a.end.y() - b.end.y()) <= mesh_.agent().max_climb;
                });
                if (same != ways.end()) same->push_back(k);
                else ways.push_back({k});
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
    void settle(const LinkGeneration::Cache& c, LinkGeneration::DropProbe& d, const Vec3& heading, const NavPoint& landing,
                const Ray& floor_ray, const RayHit& floor) const {
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
        if (drop > s_.max_drop_distance) {
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
        l.bidirectional = drop <= s_.max_jump_up && l.requirements.gap <= s_.max_jump_gap;
        l.arc_height = s_.jump_arc_height;  // the jump back up's arc, when the drop works both ways
        d.fall = fall_path(start, heading, d.rim + kPastRim, end);
        l.apex = d.fall[1];  // where the body leaves the ground: the top of the fall, and its heading
    }

    // No rays from here on: over everything cached, so an update gives what a full generation would.
    std::vector<Link> select(const LinkGeneration::Cache& c) {
        for (const auto& t : c.takeoffs) {
            if (t.rejected == 1) ++report_.rejected_wall;
            if (t.rejected == 2) ++report_.rejected_not_ledge;
        }
        std::vector<Link> links = straightest_jumps(c);
        const std::vector<Link> drops = one_drop_per_way_down(c);
        links.insert(links.end(), drops.begin(), drops.end());
        report_.drop_candidates = 0;
        for (const LinkGeneration::DropProbe& d : c.drops) report_.drop_candidates += d.outcome == 0;
        MergedLinks merged = merge_links(std::move(links), s_.merge_distance, method_ == GenerationMethod::BruteForce);
        report_.rejected_duplicate += merged.duplicates;
        links = std::move(merged.kept);
        for (const Link& l : links) (l.kind == LinkKind::Jump ? report_.jump_links : report_.drop_links)++;
        return links;
    }

    // The kept drops, in key order: one per way down (for_each_way_down), its most head-on clear
    // probe. The ways' other probes are duplicates, unless blocked.
    std::vector<Link> one_drop_per_way_down(const LinkGeneration::Cache& c) {
        for (const LinkGeneration::DropProbe& d : c.drops) {
            if (d.outcome == 1) ++report_.rejected_no_landing;
            else if (d.outcome == 2) ++report_.rejected_too_shallow;
            else if (d.outcome == 3) ++report_.rejected_too_deep;
        }
        std::vector<uint32_t> kept;
        for_each_way_down(c, [&](const std::vector<uint32_t>& way) {
            const uint32_t* keep = kept_probe(c, way);
            for (const uint32_t& k : way) {
                if (&k == keep) kept.push_back(k);
                else if (c.drops[k].sweep.swept && !c.drops[k].sweep.clear) ++report_.rejected_clearance;
                else ++report_.rejected_duplicate;
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

    // The kept jumps (walk_jump_ranking), in take-off order.
    std::vector<Link> straightest_jumps(const LinkGeneration::Cache& c) {
        std::vector<const LinkGeneration::JumpCandidate*> kept = walk_jump_ranking(c, nullptr, &report_);
        std::sort(kept.begin(), kept.end(), [](const auto* x, const auto* y) { return std::make_pair(x->a, x->b) < std::make_pair(y->a, y->b); });
        std::vector<Link> links;
        for (const auto* j : kept) {
            links.push_back(j->link);
            links.back().requirements.clearance_width = j->sweep.width;
        }
        return links;
    }

    const NavMesh& mesh_;
    const std::vector<EdgeSample>& samples_;
    const LinkSettings& s_;
    GenerationMethod method_;
    const LinkGeneration::Cache& old_;
    const Aabb* box_;
    const Level& level_;
    TaskSystem& tasks_;
    LinkGenerationReport& report_;
    GenerationProgress progress_;
    Body body_;
    WalkGraph walk_;
    RimProbing rim_probing_{};
};

}  // namespace

LinkGeneration::LinkGeneration(std::shared_ptr<const NavMesh> navmesh, const LinkSettings& settings, GenerationMethod method)
    : navmesh_(std::move(navmesh)), settings_(settings), method_(method) {
    validate(settings_);
}

std::vector<Link> LinkGeneration::run(const Level& level, TaskSystem& tasks, LinkGenerationReport& report, GenerationProgress progress) {
    std::lock_guard lock(mutex_);
    return generate(nullptr, level, tasks, report, progress);
}

std::vector<Link> LinkGeneration::update(const Aabb& box, const Level& level, TaskSystem& tasks, LinkGenerationReport& report,
                                   GenerationProgress progress) {
    std::lock_guard lock(mutex_);
    return generate(generated_ ? &box : nullptr, level, tasks, report, progress);
}

std::vector<Link> LinkGeneration::generate(const Aabb* box, const Level& level, TaskSystem& tasks, LinkGenerationReport& report,
                                 GenerationProgress progress) {
    Stopwatch total, stage;
    report = LinkGenerationReport{};
    if (!progress(0.0f, "edges")) fail(ErrorCode::Cancelled, "the generation was cancelled during 'edges'");
    if (!generated_) sampling_ = sample_edges(*navmesh_, settings_);
    report.edges = sampling_.edges;
    report.groups = sampling_.groups;
    report.samples = static_cast<uint32_t>(sampling_.samples.size());
    report.milliseconds_edges = stage.lap();

    const Cache empty;
    Cache next;
    std::vector<Link> links =
        GenerationPass(*navmesh_, sampling_, settings_, method_, generated_ ? cache_ : empty, box, level, tasks, report, progress).run(next);
    if (!progress(1.0f, "done")) fail(ErrorCode::Cancelled, "the generation was cancelled at its end");
    cache_ = std::move(next);  // only a generation that finished replaces the cache
    generated_ = true;
    report.milliseconds_total = total.lap();
    return links;
}

}  // namespace nl
