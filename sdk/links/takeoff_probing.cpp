// Take-off probing, the first stage of a link generation pass: which edge samples stand over a rim.
#include "links/generation_stage.h"

#include <optional>
#include <array>

namespace nl::generation {
namespace {

class TakeoffProbing : public GenerationStage {
public:
    using GenerationStage::GenerationStage;

    // Take-off points: samples past whose edge the ground falls away (the rim: the first probe, every
    // RimSearch::kStep out to falloff_distance, with no ground within a step below), with nothing solid
    // between the edge and the rim. Recast leaves its edges 0.6 to 0.9 m inside the rim, depending
    // on how the voxel grid falls, so the rim is searched for, not assumed.
    void run(LinkGeneration::Cache& next) {
        next.takeoffs.resize(samples_.size());
        std::vector<uint32_t> redo;
        for (uint32_t i = 0; i < samples_.size(); ++i) {
            if (old_.takeoffs.size() == samples_.size() && !touches(old_.takeoffs[i].bounds, box_))
                next.takeoffs[i] = old_.takeoffs[i];
            else
                redo.push_back(i);
        }
        std::vector<Ray> ground_rays;
        for (uint32_t i : redo)
            ground_rays.push_back(
                Ray{samples_[i].point + Vec3(0, rim_probing_.lift, 0), Vec3(0, -1, 0), rim_probing_.lift + 1.5f});
        const std::vector<RayHit> ground = cast(ground_rays);
        // Indexed generations first try the last triangle found under the sample (by the ground ray, then
        // by each probe cast): a probe that crosses it well inside is on ground without a ray.
        std::vector<std::optional<std::array<Vec3, 3>>> floor(redo.size());
        if (rim_probing_.floor_shortcut)
            level_.static_triangles(ground.data(), static_cast<uint32_t>(ground.size()), floor.data());
        std::vector<RimQuery> queries(redo.size());
        for (size_t k = 0; k < redo.size(); ++k) {
            const EdgeSample& e = samples_[redo[k]];
            LinkGeneration::TakeoffState& t = next.takeoffs[redo[k]];
            t = LinkGeneration::TakeoffState{};
            // Correction for navmeshes that sit above the floor (Recast's rounds up) or sink into it.
            t.ground_y = ground[k].hit ? ground[k].point.y() : e.point.y();
            queries[k] = RimQuery{e.point, e.outward, t.ground_y, settings_.falloff_distance, floor[k]};
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
                t.rejected = LinkGeneration::TakeoffRejection::NoRim;
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
            t.rejected = wall[k] ? LinkGeneration::TakeoffRejection::Wall : LinkGeneration::TakeoffRejection::None;
        }
    }
};

}  // namespace

void probe_takeoffs(PassInputs& in, LinkGeneration::Cache& next) { TakeoffProbing(in).run(next); }

}  // namespace nl::generation
