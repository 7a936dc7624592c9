#include "links/link_generation.h"

#include <chrono>

#include "links/generation_stage.h"
#include "links/link_merge.h"
#include "util/error.h"

namespace nl {
namespace {

struct Stopwatch {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double ms = std::chrono::duration<double, std::milli>(now - start).count();
        start = now;
        return ms;
    }
};

// One generation or update: the stages in order, then the selection, which casts no ray and runs over
// the whole cache, so an update gives what a full generation would.
std::vector<Link> run_pass(generation::PassInputs& in, LinkGeneration::Cache& next) {
    LinkGenerationReport& report = in.report;
    auto step = [&](float fraction, const char* stage) { generation::check_progress(in.progress, fraction, stage); };
    Stopwatch stage;
    step(0.05f, "take-off points");
    generation::probe_takeoffs(in, next);
    report.milliseconds_takeoff = stage.lap();
    step(0.15f, "jumps");
    generation::find_jumps(in, next);
    report.milliseconds_jumps = stage.lap();
    step(0.55f, "drops");
    generation::find_drops(in, next);
    report.milliseconds_drops = stage.lap();
    step(0.95f, "merge");

    for (const auto& t : next.takeoffs) {
        if (t.rejected == LinkGeneration::TakeoffRejection::Wall) ++report.rejected_wall;
        if (t.rejected == LinkGeneration::TakeoffRejection::NoRim) ++report.rejected_not_ledge;
    }
    std::vector<Link> links = generation::straightest_jumps(in, next);
    const std::vector<Link> drops = generation::one_drop_per_way_down(in, next);
    links.insert(links.end(), drops.begin(), drops.end());
    report.drop_candidates = 0;
    for (const LinkGeneration::DropProbe& d : next.drops) report.drop_candidates += d.outcome == 0;
    MergedLinks merged =
        merge_links(std::move(links), in.settings.merge_distance, in.method == GenerationMethod::BruteForce);
    report.rejected_duplicate += merged.duplicates;
    links = std::move(merged.kept);
    for (const Link& l : links) (l.kind == LinkKind::Jump ? report.jump_links : report.drop_links)++;
    report.milliseconds_merge = stage.lap();
    return links;
}

}  // namespace

LinkGeneration::LinkGeneration(std::shared_ptr<const NavMesh> navmesh, const LinkSettings& settings,
                               GenerationMethod method)
    : navmesh_(std::move(navmesh)), settings_(settings), method_(method) {
    validate(settings_);
}

std::vector<Link> LinkGeneration::run(const Level& level, TaskSystem& tasks, LinkGenerationReport& report,
                                      GenerationProgress progress) {
    std::lock_guard lock(mutex_);
    return generate(nullptr, level, tasks, report, progress);
}

std::vector<Link> LinkGeneration::update(const Aabb& box, const Level& level, TaskSystem& tasks,
                                         LinkGenerationReport& report, GenerationProgress progress) {
    std::lock_guard lock(mutex_);
    return generate(generated_ ? &box : nullptr, level, tasks, report, progress);
}

std::vector<Link> LinkGeneration::generate(const Aabb* box, const Level& level, TaskSystem& tasks,
                                           LinkGenerationReport& report, GenerationProgress progress) {
    Stopwatch total, stage;
    report = LinkGenerationReport{};
    generation::check_progress(progress, 0.0f, "edges");
    if (!generated_) sampling_ = sample_edges(*navmesh_, settings_);
    report.edges = sampling_.edges;
    report.groups = sampling_.groups;
    report.samples = static_cast<uint32_t>(sampling_.samples.size());
    report.milliseconds_edges = stage.lap();

    const Cache empty;
    Cache next;
    generation::PassInputs in(*navmesh_, sampling_, settings_, method_, generated_ ? cache_ : empty, box, level, tasks,
                              report, progress);
    std::vector<Link> links = run_pass(in, next);
    if (!progress(1.0f, "done")) fail(ErrorCode::Cancelled, "the generation was cancelled at its end");
    cache_ = std::move(next);  // only a generation that finished replaces the cache
    generated_ = true;
    report.milliseconds_total = total.lap();
    return links;
}

}  // namespace nl
