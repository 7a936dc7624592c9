#include "links/generation_stage.h"

#include <algorithm>
#include <array>

#include "links/trajectory.h"
#include "util/error.h"

namespace nl::generation {

PassInputs::PassInputs(const NavMesh& navmesh, const EdgeSampling& sampling, const LinkSettings& settings,
                       GenerationMethod method, const LinkGeneration::Cache& old, const Aabb* box, const Level& level,
                       TaskSystem& tasks, LinkGenerationReport& report, GenerationProgress progress)
    : navmesh(navmesh),
      samples(sampling.samples),
      settings(settings),
      method(method),
      old(old),
      box(box),
      level(level),
      tasks(tasks),
      report(report),
      progress(progress),
      body{navmesh.agent().radius, navmesh.agent().height},
      walk(navmesh) {
    // Probes start above the floor by at most half the body (a low ceiling over the edge is not
    // ground) and count as ground anything within a walkable step below it.
    rim_probing.lift = std::min(kProbeLift, 0.5f * body.height);
    rim_probing.step_reach = rim_probing.lift + navmesh.agent().max_climb + 0.05f;
    rim_probing.floor_shortcut = method == GenerationMethod::Indexed;
}

GenerationStage::GenerationStage(PassInputs& in)
    : mesh_(in.navmesh),
      samples_(in.samples),
      settings_(in.settings),
      method_(in.method),
      old_(in.old),
      box_(in.box),
      level_(in.level),
      tasks_(in.tasks),
      report_(in.report),
      progress_(in.progress),
      body_(in.body),
      walk_(in.walk),
      rim_probing_(in.rim_probing) {}

void check_progress(const GenerationProgress& progress, float fraction, const char* stage) {
    if (!progress(fraction, stage)) fail(ErrorCode::Cancelled, "the generation was cancelled during '", stage, "'");
}

void GenerationStage::step(float fraction, const char* stage) { check_progress(progress_, fraction, stage); }

std::vector<RayHit> GenerationStage::cast(const std::vector<Ray>& rays) {
    std::vector<RayHit> hits(rays.size());
    level_.cast_rays(rays.data(), static_cast<uint32_t>(rays.size()), hits.data());
    report_.rays_cast += rays.size();
    return hits;
}

std::vector<uint8_t> GenerationStage::blocked(const std::vector<Segment>& segments) {
    std::vector<uint8_t> out(segments.size());
    level_.segments_blocked(segments.data(), static_cast<uint32_t>(segments.size()), out.data());
    report_.rays_cast += segments.size();
    return out;
}

Vec3 GenerationStage::floor_point(const LinkGeneration::Cache& c, uint32_t i) const {
    return Vec3(samples_[i].point.x(), c.takeoffs[i].ground_y, samples_[i].point.z());
}

// Sweeps each path with the agent's body and bodies 1.5 and 2 times as wide (Body, kSweepRadii),
// every piece tested exactly against the triangles near it: a path is clear if the agent's body
// touches nothing anywhere along it, and as wide as the widest body that touches nothing. Indexed
// generations ask the level for the triangles around each straight run of pieces once (a run through
// open air costs that one query) and test the run's pieces against those; brute-force generations ask
// for each piece on its own.
std::vector<LinkGeneration::Sweep> GenerationStage::sweep(const std::vector<PathPoints>& paths) {
    std::vector<LinkGeneration::Sweep> out(paths.size());
    std::vector<std::vector<SweepPiece>> pieces(paths.size());
    std::vector<std::vector<PieceRun>> runs(paths.size());
    const float widest = kSweepRadii[kSweepRadiusCount - 1] * body_.radius;
    tasks_.parallel_for(static_cast<uint32_t>(paths.size()), 64, [&](uint32_t begin, uint32_t end) {
        for (uint32_t i = begin; i < end; ++i) {
            pieces[i] = sweep_pieces(paths[i], settings_.clearance_margin, body_.radius);
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
            for (; next < pieces[i].size(); ++next)
                groups[g++] = BodyGroup{stretches[base + next].bounds, base + next, 1};
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

std::vector<LinkGeneration::Sweep> GenerationStage::sweep_arcs(const std::vector<std::pair<Vec3, Vec3>>& ends) {
    const double piece = 1.0 / settings_.arc_segments;
    std::vector<std::vector<Vec3>> arcs(ends.size());
    std::vector<PathPoints> paths(ends.size());
    for (size_t n = 0; n < ends.size(); ++n) {
        const JumpArc arc(ends[n].first, ends[n].second, settings_.jump_arc_height);
        arcs[n] = arc.points(settings_.arc_segments);
        paths[n] = PathPoints{arcs[n].data(), arcs[n].size(), arc.sagitta(0.0, piece)};
    }
    return sweep(paths);
}

NavPoint GenerationStage::locate(const Vec3& point, const Vec3& half_extents) const {
    return method_ == GenerationMethod::Indexed ? mesh_.find_nearest(point, half_extents)
                                                : mesh_.find_nearest_brute_force(point, half_extents);
}

}  // namespace nl::generation
