#include "links/link_bake.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "links/clearance.h"
#include "links/link_merge.h"
#include "util/error.h"

namespace nl {
namespace {

constexpr float kDegrees = 3.14159265358979f / 180.0f;
constexpr float kProbeLift = 0.5f;  // probes start this far above the navmesh: clear of the floor,
                                    // and below any ceiling (the navmesh has agent height above it)
constexpr float kRimStep = 0.25f;   // spacing of the probes that look for the rim past an edge
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

bool touches(const Aabb& a, const Aabb* box) {
    if (!box) return true;  // a full bake recomputes everything
    return (a.min.array() - kPad <= box->max.array()).all() && (a.max.array() + kPad >= box->min.array()).all();
}

// Whether the vertical segment from `top` down `reach` crosses the (static, world-space) triangle a
// millimetre inside its edges and ends (more far from the origin, where floats are coarser), so that
// casting it could only report a hit.
bool crosses_well_inside(const std::array<Vec3, 3>& t, const Vec3& top, float reach) {
    const float kInside = 1e-3f + 16.0f * std::numeric_limits<float>::epsilon() * top.cwiseAbs().maxCoeff();
    const Eigen::Vector2f a(t[0].x(), t[0].z()), b(t[1].x(), t[1].z()), c(t[2].x(), t[2].z()), p(top.x(), top.z());
    auto cross = [](const Eigen::Vector2f& u, const Eigen::Vector2f& v) { return u.x() * v.y() - u.y() * v.x(); };
    const float area = cross(b - a, c - a);
    if (std::fabs(area) < 1e-6f) return false;  // (nearly) vertical as seen from above
    const float side = area > 0.0f ? 1.0f : -1.0f;
    const Eigen::Vector2f corners[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) {
        const Eigen::Vector2f& from = corners[i];
        const Eigen::Vector2f& to = corners[(i + 1) % 3];
        const float length = (to - from).norm();
        if (side * cross(to - from, p - from) < kInside * length) return false;
    }
    const float u = cross(p - a, c - a) / area, v = cross(b - a, p - a) / area;
    const float y = t[0].y() + u * (t[1].y() - t[0].y()) + v * (t[2].y() - t[0].y());
    return y <= top.y() - kInside && y >= top.y() - reach + kInside;
}

// One bake or update: fills `next` from the old cache and new rays.
class Baker {
public:
    Baker(const NavMesh& mesh, const EdgeSampling& sampling, const LinkSettings& s, BakeMethod method,
          const LinkBake::Cache& old, const Aabb* box, const Level& level, TaskSystem& tasks, BakeReport& report,
          BakeProgress progress)
        : mesh_(mesh), samples_(sampling.samples), s_(s), method_(method), old_(old), box_(box), level_(level),
          tasks_(tasks), report_(report), progress_(progress), body_{mesh.agent().radius, mesh.agent().height} {}

    std::vector<Link> run(LinkBake::Cache& next) {
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
        if (!progress_(fraction, stage)) fail(ErrorCode::Cancelled, "the bake was cancelled during '", stage, "'");
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
    // kRimStep out to falloff_distance, with no ground within a step below), with nothing solid
    // between the edge and the rim. Recast leaves its edges 0.6 to 0.9 m inside the rim, depending
    // on how the voxel grid falls, so the rim is searched for, not assumed.
    void probe_takeoffs(LinkBake::Cache& next) {
        next.takeoffs.resize(samples_.size());
        std::vector<uint32_t> redo;
        for (uint32_t i = 0; i < samples_.size(); ++i) {
            if (old_.takeoffs.size() == samples_.size() && !touches(old_.takeoffs[i].bounds, box_)) next.takeoffs[i] = old_.takeoffs[i];
            else redo.push_back(i);
        }
        const float probe = std::min(kProbeLift, 0.5f * body_.height);
        std::vector<Ray> ground_rays;
        for (uint32_t i : redo) ground_rays.push_back(Ray{samples_[i].point + Vec3(0, probe, 0), Vec3(0, -1, 0), probe + 1.5f});
        const std::vector<RayHit> ground = cast(ground_rays);

        const auto steps = static_cast<uint32_t>(std::ceil(s_.falloff_distance / kRimStep));
        const float climb = mesh_.agent().max_climb;
        const float step_reach = probe + climb + 0.05f;
        auto probe_top = [&](size_t k, uint32_t step) {
            const EdgeSample& e = samples_[redo[k]];
            const Vec3 out = e.point + e.outward * std::min(step * kRimStep, s_.falloff_distance);
            return Vec3(out.x(), next.takeoffs[redo[k]].ground_y + probe, out.z());
        };
        // Indexed bakes first try the last triangle found under the sample (by the ground ray, then
        // by each probe cast): a probe that crosses it well inside is on ground without a ray.
        const bool floor_shortcut = method_ == BakeMethod::Indexed;
        std::vector<std::optional<std::array<Vec3, 3>>> floor(floor_shortcut ? redo.size() : 0);
        if (floor_shortcut) level_.static_triangles(ground.data(), static_cast<uint32_t>(ground.size()), floor.data());
        tasks_.parallel_for(static_cast<uint32_t>(redo.size()), 256, [&](uint32_t begin, uint32_t end) {
            for (uint32_t k = begin; k < end; ++k) {
                const EdgeSample& e = samples_[redo[k]];
                LinkBake::TakeoffState& t = next.takeoffs[redo[k]];
                t = LinkBake::TakeoffState{};
                // Correction for navmeshes that sit above the floor (Recast's rounds up) or sink into it.
                t.ground_y = ground[k].hit ? ground[k].point.y() : e.point.y();
                t.rim = -1.0f;
                // Every probe the rim search may cast, so a change anywhere along it redoes the sample.
                t.bounds = bounds_of({e.point + Vec3(0, probe, 0), e.point - Vec3(0, 1.5f, 0)});
                for (uint32_t j = 1; j <= steps; ++j) {
                    t.bounds.grow(probe_top(k, j));
                    t.bounds.grow(probe_top(k, j) - Vec3(0, step_reach, 0));
                }
            }
        });
        // One step out at a time, for the samples still on ground: only a hit or a miss is needed,
        // and a sample stops at its rim.
        std::vector<size_t> looking(redo.size());
        for (size_t k = 0; k < redo.size(); ++k) looking[k] = k;
        for (uint32_t j = 1; j <= steps && !looking.empty(); ++j) {
            std::vector<uint8_t> on_ground(looking.size(), 1), proven(looking.size(), 0);
            if (floor_shortcut)
                tasks_.parallel_for(static_cast<uint32_t>(looking.size()), 512, [&](uint32_t begin, uint32_t end) {
                    for (uint32_t n = begin; n < end; ++n) {
                        const size_t k = looking[n];
                        proven[n] = floor[k] && crosses_well_inside(*floor[k], probe_top(k, j), step_reach);
                    }
                });
            std::vector<Segment> below;
            std::vector<size_t> cast_for;  // positions in `looking` of the probes cast
            for (size_t n = 0; n < looking.size(); ++n) {
                if (proven[n]) continue;
                const Vec3 top = probe_top(looking[n], j);
                below.push_back(Segment{top, top - Vec3(0, step_reach, 0)});
                cast_for.push_back(n);
            }
            if (floor_shortcut) {
                // Cast for the triangle too: the next step out may cross it.
                const std::vector<RayHit> hits = first_hits(below);
                std::vector<std::optional<std::array<Vec3, 3>>> found(hits.size());
                level_.static_triangles(hits.data(), static_cast<uint32_t>(hits.size()), found.data());
                for (size_t c = 0; c < cast_for.size(); ++c) {
                    on_ground[cast_for[c]] = hits[c].hit;
                    if (hits[c].hit) floor[looking[cast_for[c]]] = found[c];
                }
            } else {
                const std::vector<uint8_t> ground_below = blocked(below);
                for (size_t c = 0; c < cast_for.size(); ++c) on_ground[cast_for[c]] = ground_below[c];
            }
            size_t still = 0;
            for (size_t n = 0; n < looking.size(); ++n) {
                if (on_ground[n]) looking[still++] = looking[n];
                else next.takeoffs[redo[looking[n]]].rim = std::min(j * kRimStep, s_.falloff_distance);
            }
            looking.resize(still);
        }

        std::vector<Segment> walls;
        std::vector<uint32_t> ledges;
        const Vec3 chest(0, std::min(0.5f * body_.height, 1.0f), 0);
        for (size_t k = 0; k < redo.size(); ++k) {
            LinkBake::TakeoffState& t = next.takeoffs[redo[k]];
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
            LinkBake::TakeoffState& t = next.takeoffs[ledges[k]];
            t.valid = !wall[k];
            t.rejected = wall[k] ? 1 : 0;
        }
    }

    // What the geometry-free tests say of a pair of take-off points, for the report.
    enum class PairVerdict : uint8_t { Candidate, Ignored, Distance, Rise, Angle, NoLanding };

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

    // Pairs beyond max_link_distance are still looked at, up to twice as far, so the report can say
    // that two facing edges were too far apart. Never finer than a centimetre: cell keys stay far
    // inside int64 within the coordinate limit.
    float pair_reach() const { return std::max(2.0f * s_.max_link_distance, 0.01f); }

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
        if (method_ == BakeMethod::BruteForce) {
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

    // The constraints that need no ray: distance, rise, facing, incline. Both directions at once:
    // every one of them is symmetric in the two ends.
    PairVerdict judge_pair(const EdgeSample& a, const EdgeSample& b) const {
        const Vec3 d = b.point - a.point;
        const Vec3 flat(d.x(), 0.0f, d.z());
        const float distance = d.norm(), gap = flat.norm();
        const bool is_short = distance < s_.short_link_distance;
        const float forward = std::cos((is_short ? s_.permissive_forward_angle : s_.strict_forward_angle) * kDegrees);
        const bool facing = gap > 0.0f && a.outward.dot(flat / gap) >= forward && b.outward.dot(-flat / gap) >= forward;
        // Only edges that face each other are worth reporting as too far apart.
        if (distance > s_.max_link_distance) return facing ? PairVerdict::Distance : PairVerdict::Ignored;
        if (gap < s_.min_link_distance) return PairVerdict::Distance;
        if (std::fabs(d.y()) > s_.max_jump_up) return PairVerdict::Rise;
        const float incline = std::sin((is_short ? s_.permissive_incline_angle : s_.strict_incline_angle) * kDegrees);
        const Vec3 direction = d / distance;
        if (!facing || std::fabs(direction.dot(a.normal)) > incline || std::fabs(direction.dot(b.normal)) > incline)
            return PairVerdict::Angle;
        return on_navmesh(b.point) ? PairVerdict::Candidate : PairVerdict::NoLanding;
    }

    void count(PairVerdict verdict, uint32_t pairs) {
        switch (verdict) {
            case PairVerdict::Distance: report_.rejected_distance += pairs; break;
            case PairVerdict::Rise: report_.rejected_rise += pairs; break;
            case PairVerdict::Angle: report_.rejected_angle += pairs; break;
            case PairVerdict::NoLanding: report_.rejected_no_landing += pairs; break;
            case PairVerdict::Candidate:
            case PairVerdict::Ignored: break;
        }
    }

    // A pair that met every geometry-free constraint: its arc's sweep is reused from the old cache
    // when the box cannot have changed it, else queued in `redo` / `arcs`.
    void add_jump_candidate(uint32_t a, uint32_t b, LinkBake::Cache& next, std::vector<uint64_t>& redo,
                            std::vector<std::vector<Vec3>>& arcs) {
        const uint64_t key = pair_key(a, b);
        const auto cached = old_.jumps.find(key);
        if (cached != old_.jumps.end() && !touches(cached->second.sweep.bounds, box_)) {
            next.jumps.emplace(key, cached->second);
            return;
        }
        const JumpArc arc = jump_arc(samples_[a].point, samples_[b].point, s_.jump_arc_height, s_.arc_segments);
        LinkBake::JumpCandidate c;
        c.a = a;
        c.b = b;
        c.link.kind = LinkKind::Jump;
        c.link.start = samples_[a].point;
        c.link.end = samples_[b].point;
        c.link.apex = arc.apex;
        c.link.bidirectional = true;  // every jump constraint holds both ways
        c.link.generated = true;
        c.link.start_polygon = samples_[a].polygon;
        c.link.end_polygon = samples_[b].polygon;
        set_requirements_from_ends(c.link);
        next.jumps.emplace(key, c);
        redo.push_back(key);
        arcs.push_back(arc.points);
    }

    // Which pieces a box query proves clear (1) without casting their segments: straight runs of
    // pieces first, one query clearing a run through open air, then each piece not cleared with
    // its run.
    std::vector<uint8_t> proven_clear(const std::vector<std::vector<SweepPiece>>& pieces, const std::vector<size_t>& first_piece,
                                      const std::vector<uint32_t>& path_of) {
        const auto piece_count = static_cast<uint32_t>(first_piece.back());
        std::vector<uint8_t> piece_clear(piece_count, 0);
        std::vector<std::vector<PieceRun>> runs(pieces.size());
        tasks_.parallel_for(static_cast<uint32_t>(pieces.size()), 256, [&](uint32_t begin, uint32_t end) {
            for (uint32_t i = begin; i < end; ++i) runs[i] = straight_runs(pieces[i]);
        });
        std::vector<std::pair<uint32_t, PieceRun>> all_runs;  // (path, run)
        for (uint32_t i = 0; i < pieces.size(); ++i)
            for (const PieceRun& run : runs[i]) all_runs.emplace_back(i, run);
        std::vector<OrientedBox> run_boxes(all_runs.size());
        tasks_.parallel_for(static_cast<uint32_t>(all_runs.size()), 64, [&](uint32_t begin, uint32_t end) {
            for (uint32_t n = begin; n < end; ++n) run_boxes[n] = run_box(pieces[all_runs[n].first], all_runs[n].second, body_.radius);
        });
        std::vector<uint8_t> run_clear(all_runs.size(), 0);
        level_.boxes_empty(run_boxes.data(), static_cast<uint32_t>(run_boxes.size()), run_clear.data());
        for (size_t n = 0; n < all_runs.size(); ++n) {
            if (!run_clear[n]) continue;
            const size_t base = first_piece[all_runs[n].first];
            std::fill(piece_clear.begin() + base + all_runs[n].second.first, piece_clear.begin() + base + all_runs[n].second.last, 1);
        }
        std::vector<uint32_t> asked;
        for (uint32_t k = 0; k < piece_count; ++k)
            if (!piece_clear[k]) asked.push_back(k);
        std::vector<OrientedBox> boxes(asked.size());
        tasks_.parallel_for(static_cast<uint32_t>(asked.size()), 256, [&](uint32_t begin, uint32_t end) {
            for (uint32_t n = begin; n < end; ++n) {
                const uint32_t k = asked[n], i = path_of[k];
                boxes[n] = piece_box(pieces[i][k - first_piece[i]], body_.radius);
            }
        });
        std::vector<uint8_t> clear(asked.size(), 0);
        level_.boxes_empty(boxes.data(), static_cast<uint32_t>(boxes.size()), clear.data());
        for (size_t n = 0; n < asked.size(); ++n) piece_clear[asked[n]] = clear[n];
        report_.box_queries += all_runs.size() + asked.size();
        return piece_clear;
    }

    // Sweeps each path with the agent's body and bodies 1.5 and 2 times as wide, in one occlusion
    // batch: a path is clear if the agent's lines are, and as wide as the widest body whose lines
    // (and every narrower body's) are. Indexed bakes cast only the pieces proven_clear leaves.
    std::vector<LinkBake::Sweep> sweep(const std::vector<PathPoints>& paths) {
        std::vector<LinkBake::Sweep> out(paths.size());
        std::vector<std::vector<SweepPiece>> pieces(paths.size());
        tasks_.parallel_for(static_cast<uint32_t>(paths.size()), 64, [&](uint32_t begin, uint32_t end) {
            for (uint32_t i = begin; i < end; ++i) {
                pieces[i] = sweep_pieces(paths[i], body_, s_.clearance_margin);
                Aabb& b = out[i].bounds;
                for (size_t n = 0; n < paths[i].count; ++n) b.grow(paths[i].points[n]);
                const float widest = 2.0f * body_.radius;
                b.min -= Vec3(widest, 0.0f, widest);
                b.max += Vec3(widest, body_.height, widest);
            }
        });
        std::vector<size_t> first_piece(paths.size() + 1, 0);
        for (size_t i = 0; i < paths.size(); ++i) first_piece[i + 1] = first_piece[i] + pieces[i].size();
        const auto piece_count = static_cast<uint32_t>(first_piece.back());
        std::vector<uint8_t> piece_clear(piece_count, 0);
        std::vector<uint32_t> path_of(piece_count);
        for (uint32_t i = 0; i < paths.size(); ++i)
            for (size_t k = first_piece[i]; k < first_piece[i + 1]; ++k) path_of[k] = i;
        if (method_ == BakeMethod::Indexed) piece_clear = proven_clear(pieces, first_piece, path_of);
        // The pieces left to cast, kSegmentsPerPiece segments each.
        std::vector<uint32_t> cast_pieces;
        for (uint32_t k = 0; k < piece_count; ++k)
            if (!piece_clear[k]) cast_pieces.push_back(k);
        std::vector<Segment> segments(cast_pieces.size() * kSegmentsPerPiece);
        tasks_.parallel_for(static_cast<uint32_t>(cast_pieces.size()), 256, [&](uint32_t begin, uint32_t end) {
            std::vector<Segment> piece_segments;
            for (uint32_t c = begin; c < end; ++c) {
                const uint32_t k = cast_pieces[c], i = path_of[k];
                piece_segments.clear();
                append_piece_segments(pieces[i][k - first_piece[i]], body_.radius, piece_segments);
                std::copy(piece_segments.begin(), piece_segments.end(), segments.begin() + size_t(c) * kSegmentsPerPiece);
            }
        });
        const std::vector<uint8_t> hit = blocked(segments);
        std::vector<std::array<bool, kSweepOffsetCount>> offset_blocked(paths.size());
        for (size_t c = 0; c < cast_pieces.size(); ++c)
            for (unsigned j = 0; j < kSegmentsPerPiece; ++j)
                if (hit[c * kSegmentsPerPiece + j]) offset_blocked[path_of[cast_pieces[c]]][(j / 2) % kSweepOffsetCount] = true;
        for (size_t i = 0; i < paths.size(); ++i) {
            const auto& b = offset_blocked[i];
            // Offsets pair up by width: {0}, {-1, 1}, {-1.5, 1.5}, {-2, 2} radii.
            if (b[0] || b[1] || b[2]) continue;
            out[i].clear = true;
            out[i].width = 2.0f * body_.radius;
            if (b[3] || b[4]) continue;
            out[i].width = 3.0f * body_.radius;
            if (b[5] || b[6]) continue;
            out[i].width = 4.0f * body_.radius;
        }
        return out;
    }

    // Point location through the navmesh's polygon grid, or over every polygon (brute force).
    NavPoint locate(const Vec3& point, const Vec3& half_extents) const {
        return method_ == BakeMethod::Indexed ? mesh_.find_nearest(point, half_extents)
                                              : mesh_.find_nearest_brute_force(point, half_extents);
    }

    bool on_navmesh(const Vec3& point) const {
        const NavPoint p = locate(point, Vec3(0.1f, 0.5f, 0.1f));
        return p.found && p.distance < 0.3f;
    }

    // Jump candidates: the geometry-free constraints over every pair (cheap, so always redone, in
    // parallel over take-off points, a block at a time so progress can cancel), then the arc sweep,
    // reused from the old cache unless geometry in the box could have changed it.
    void find_jumps(LinkBake::Cache& next) {
        std::vector<uint32_t> valid;
        for (uint32_t i = 0; i < samples_.size(); ++i)
            if (next.takeoffs[i].valid) valid.push_back(i);
        report_.takeoff_points = static_cast<uint32_t>(valid.size());
        TakeoffGrid grid;
        if (method_ == BakeMethod::Indexed)
            for (uint32_t i : valid) grid[cell_of(samples_[i].point)].push_back(i);

        std::vector<uint64_t> redo;
        std::vector<std::vector<Vec3>> arcs;
        constexpr size_t kBlock = 2048;
        std::vector<std::vector<uint32_t>> candidates(kBlock);
        std::vector<std::array<uint32_t, 6>> verdicts(kBlock);
        for (size_t block = 0; block < valid.size(); block += kBlock) {
            step(0.15f + 0.2f * float(block) / float(valid.size()), "jumps");
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
                        const PairVerdict verdict = judge_pair(samples_[a], samples_[b]);
                        ++verdicts[n][static_cast<size_t>(verdict)];
                        if (verdict == PairVerdict::Candidate) candidates[n].push_back(b);
                    }
                }
            });
            for (uint32_t n = 0; n < size; ++n) {
                for (size_t v = 0; v < verdicts[n].size(); ++v) count(static_cast<PairVerdict>(v), verdicts[n][v]);
                for (uint32_t b : candidates[n]) add_jump_candidate(valid[block + n], b, next, redo, arcs);
            }
        }
        report_.jump_candidates = static_cast<uint32_t>(next.jumps.size());
        step(0.35f, "jump clearance");
        std::vector<PathPoints> paths;
        for (const auto& arc : arcs) paths.push_back(PathPoints{arc.data(), arc.size()});
        const std::vector<LinkBake::Sweep> swept = sweep(paths);
        for (size_t k = 0; k < redo.size(); ++k) next.jumps[redo[k]].sweep = swept[k];
    }

    // Drops: probes down from past the rim along rotated outward directions, then the fall's sweep.
    void find_drops(LinkBake::Cache& next) {
        const float steep = s_.drop_steepness * kDegrees;
        const float reach = (s_.max_drop_distance + kProbeLift + 1.0f) / std::sin(steep);
        const auto angles = static_cast<uint32_t>(s_.drop_angles.size());
        // Every take-off point's probes, in key order: reused from the old cache (also in key order)
        // when neither the take-off point nor the probe's reach changed, else probed again.
        std::vector<uint32_t> probed;  // indices into next.drops
        next.drops.reserve(size_t(report_.takeoff_points) * angles);
        auto old = old_.drops.begin();
        for (uint32_t i = 0; i < samples_.size(); ++i) {
            const LinkBake::TakeoffState& t = next.takeoffs[i];
            if (!t.valid) continue;
            const bool takeoff_same = old_.takeoffs.size() == samples_.size() && old_.takeoffs[i].valid &&
                                      old_.takeoffs[i].rim == t.rim;
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
        std::vector<Ray> probes(probed.size());
        tasks_.parallel_for(static_cast<uint32_t>(probed.size()), 256, [&](uint32_t begin, uint32_t end) {
            for (uint32_t k = begin; k < end; ++k) {
                LinkBake::DropProbe& d = next.drops[probed[k]];
                const auto i = static_cast<uint32_t>(d.key >> 32), angle = static_cast<uint32_t>(d.key);
                const EdgeSample& e = samples_[i];
                const Eigen::AngleAxisf turn(s_.drop_angles[angle] * kDegrees, Vec3::UnitY());
                const Vec3 heading = turn * e.outward;
                // Past the rim (found straight out; a turned probe starts as far out, plus a margin).
                const Vec3 falloff = e.point + heading * (next.takeoffs[i].rim + 0.2f);
                const Vec3 direction = (heading * std::cos(steep) + Vec3(0, -std::sin(steep), 0)).normalized();
                probes[k] = Ray{falloff + Vec3(0, kProbeLift, 0), direction, reach};
                d.fall[0] = e.point;
                d.fall[1] = Vec3(falloff.x(), e.point.y(), falloff.z());
                d.fall_points = 2;
            }
        });
        const std::vector<RayHit> hits = cast(probes);
        step(0.7f, "drops");

        const Vec3 landing_box(std::max(body_.radius * 1.5f, 0.3f), 1.0f, std::max(body_.radius * 1.5f, 0.3f));
        tasks_.parallel_for(static_cast<uint32_t>(probed.size()), 256, [&](uint32_t begin, uint32_t end) {
            for (uint32_t k = begin; k < end; ++k) land(next.drops[probed[k]], probes[k], hits[k], reach, landing_box);
        });
        // Landed probes: the fresh ones, and the reused ones whose sweep the box touches.
        std::vector<uint8_t> fresh(next.drops.size(), 0);
        for (uint32_t k : probed) fresh[k] = 1;
        std::vector<uint32_t> to_sweep;
        for (uint32_t k = 0; k < next.drops.size(); ++k) {
            const LinkBake::DropProbe& d = next.drops[k];
            if (d.outcome == 0 && (fresh[k] || touches(d.sweep.bounds, box_))) to_sweep.push_back(k);
        }
        step(0.8f, "drop clearance");
        std::vector<PathPoints> paths;
        for (uint32_t k : to_sweep) paths.push_back(PathPoints{next.drops[k].fall.data(), next.drops[k].fall_points});
        const std::vector<LinkBake::Sweep> swept = sweep(paths);
        for (size_t n = 0; n < to_sweep.size(); ++n) next.drops[to_sweep[n]].sweep = swept[n];
    }

    // Where a drop probe came down: no landing, a landing too shallow or too deep, or a drop link
    // with its fall (walk out over the edge, across, down).
    void land(LinkBake::DropProbe& d, const Ray& probe, const RayHit& hit, float reach, const Vec3& landing_box) const {
        const auto i = static_cast<uint32_t>(d.key >> 32);
        d.bounds = bounds_of({probe.origin, probe.origin + probe.direction * (hit.hit ? hit.distance : reach)});
        d.outcome = 1;
        if (!hit.hit) return;
        const NavPoint landing = locate(hit.point, landing_box);
        if (!landing.found || landing.polygon == samples_[i].polygon) return;
        const float drop = samples_[i].point.y() - landing.point.y();
        if (drop <= mesh_.agent().max_climb || drop > s_.max_drop_distance) {
            d.outcome = 2;
            return;
        }
        d.outcome = 0;
        Link& l = d.link;
        l.kind = LinkKind::Drop;
        l.start = samples_[i].point;
        l.end = landing.point;
        l.apex = l.start;
        l.bidirectional = drop <= s_.max_jump_up;  // low enough to jump back up
        l.generated = true;
        l.start_polygon = samples_[i].polygon;
        l.end_polygon = landing.polygon;
        set_requirements_from_ends(l);
        d.fall[2] = Vec3(landing.point.x(), l.start.y(), landing.point.z());
        d.fall[3] = landing.point;
        d.fall_points = 4;
    }

    // No rays from here on: over everything cached, so an update gives what a full bake would.
    std::vector<Link> select(const LinkBake::Cache& c) {
        for (const auto& t : c.takeoffs) {
            if (t.rejected == 1) ++report_.rejected_wall;
            if (t.rejected == 2) ++report_.rejected_not_ledge;
        }
        std::vector<Link> links = straightest_jumps(c);
        for (const LinkBake::DropProbe& d : c.drops) {  // in key order
            if (d.outcome == 1) ++report_.rejected_no_landing;
            else if (d.outcome == 2) ++report_.rejected_distance;
            else if (!d.sweep.clear) ++report_.rejected_clearance;
            else {
                links.push_back(d.link);
                links.back().requirements.clearance_width = d.sweep.width;
            }
        }
        report_.drop_candidates = 0;
        for (const LinkBake::DropProbe& d : c.drops) report_.drop_candidates += d.outcome == 0;
        MergedLinks merged = merge_links(std::move(links), s_.merge_distance, method_ == BakeMethod::BruteForce);
        report_.rejected_duplicate += merged.duplicates;
        links = std::move(merged.kept);
        for (const Link& l : links) (l.kind == LinkKind::Jump ? report_.jump_links : report_.drop_links)++;
        return links;
    }

    // A take-off point faces a whole edge across a gap: of its clear jumps to that edge, only the
    // most head-on one is a distinct traversal (the others cross it diagonally). Best first: facing
    // both edges most squarely, then shortest, then by take-off order.
    std::vector<Link> straightest_jumps(const LinkBake::Cache& c) {
        std::vector<const LinkBake::JumpCandidate*> clear;
        for (const auto& [key, j] : c.jumps) {
            if (j.sweep.clear) clear.push_back(&j);
            else ++report_.rejected_clearance;
        }
        auto squareness = [&](const LinkBake::JumpCandidate& j) {
            Vec3 heading = j.link.end - j.link.start;
            heading.y() = 0.0f;
            heading.normalize();
            return std::min(samples_[j.a].outward.dot(heading), samples_[j.b].outward.dot(-heading));
        };
        std::vector<std::pair<float, const LinkBake::JumpCandidate*>> ranked;
        for (const auto* j : clear) ranked.emplace_back(squareness(*j), j);
        std::sort(ranked.begin(), ranked.end(), [](const auto& x, const auto& y) {
            if (x.first != y.first) return x.first > y.first;
            if (x.second->link.requirements.gap != y.second->link.requirements.gap)
                return x.second->link.requirements.gap < y.second->link.requirements.gap;
            return std::make_pair(x.second->a, x.second->b) < std::make_pair(y.second->a, y.second->b);
        });
        std::unordered_map<uint64_t, bool> taken;  // (take-off point, edge across) already linked
        std::vector<const LinkBake::JumpCandidate*> kept;
        for (const auto& [score, j] : ranked) {
            const uint64_t from_a = pair_key(j->a, samples_[j->b].edge), from_b = pair_key(j->b, samples_[j->a].edge);
            if (taken[from_a] || taken[from_b]) {
                ++report_.rejected_duplicate;
                continue;
            }
            taken[from_a] = taken[from_b] = true;
            kept.push_back(j);
        }
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
    BakeMethod method_;
    const LinkBake::Cache& old_;
    const Aabb* box_;
    const Level& level_;
    TaskSystem& tasks_;
    BakeReport& report_;
    BakeProgress progress_;
    Body body_;
};

}  // namespace

LinkBake::LinkBake(std::shared_ptr<const NavMesh> navmesh, const LinkSettings& settings, BakeMethod method)
    : navmesh_(std::move(navmesh)), settings_(settings), method_(method) {
    validate(settings_, "settings->");
}

std::vector<Link> LinkBake::run(const Level& level, TaskSystem& tasks, BakeReport& report, BakeProgress progress) {
    std::lock_guard lock(mutex_);
    return bake(nullptr, level, tasks, report, progress);
}

std::vector<Link> LinkBake::update(const Aabb& box, const Level& level, TaskSystem& tasks, BakeReport& report,
                                   BakeProgress progress) {
    std::lock_guard lock(mutex_);
    return bake(baked_ ? &box : nullptr, level, tasks, report, progress);
}

std::vector<Link> LinkBake::bake(const Aabb* box, const Level& level, TaskSystem& tasks, BakeReport& report,
                                 BakeProgress progress) {
    Stopwatch total, stage;
    report = BakeReport{};
    if (!progress(0.0f, "edges")) fail(ErrorCode::Cancelled, "the bake was cancelled during 'edges'");
    if (!baked_) sampling_ = sample_edges(*navmesh_, settings_);
    report.edges = sampling_.edges;
    report.groups = sampling_.groups;
    report.samples = static_cast<uint32_t>(sampling_.samples.size());
    report.milliseconds_edges = stage.lap();

    const Cache empty;
    Cache next;
    std::vector<Link> links =
        Baker(*navmesh_, sampling_, settings_, method_, baked_ ? cache_ : empty, box, level, tasks, report, progress).run(next);
    if (!progress(1.0f, "done")) fail(ErrorCode::Cancelled, "the bake was cancelled at its end");
    cache_ = std::move(next);  // only a bake that finished replaces the cache
    baked_ = true;
    report.milliseconds_total = total.lap();
    return links;
}

}  // namespace nl
