// World::generate_cross_links: jumps and drops between two navmeshes (a ledge and a platform), for
// where they stand now. The generator runs unchanged on one navmesh made of the two navmeshes'
// polygons near each other, placed in the world; the links it finds from one to the other become
// cross links, each end in its own navmesh's space.
#include <algorithm>
#include <cmath>

#include "links/link_generation.h"
#include "links/link_placement.h"
#include "world/world.h"

namespace nl {
namespace {

// The area that marks which navmesh a polygon of the joined navmesh came from.
constexpr uint8_t kFromFirst = 0, kFromSecond = 1;

bool overlaps(const Aabb& a, const Aabb& b) {
    return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

Aabb grown(Aabb box, const LinkSettings& s) {
    // As far as a link can reach: across a gap with its run-up, and down a drop or up a jump.
    const float across = s.max_jump_gap + s.falloff_distance + s.walk_distance;
    const float up_down = s.max_drop_distance + s.max_jump_up;
    box.min -= Vec3(across, up_down, across);
    box.max += Vec3(across, up_down, across);
    return box;
}

// Appends the polygons of `mesh` (placed at `pose`) whose world bounds meet `near`, marked `area`.
void append_near(const NavMesh& navmesh, const CarrierPose& pose, const Aabb& near, uint8_t area, NavMeshInput& out) {
    for (uint32_t p = 0; p < navmesh.polygon_count(); ++p) {
        if (!overlaps(pose.world_box(navmesh.polygon_bounds(p)), near)) continue;
        for (uint32_t k = 0; k < navmesh.corner_count(p); ++k) {
            out.indices.push_back(static_cast<uint32_t>(out.vertices.size()));
            out.vertices.push_back(pose.world_point(navmesh.vertex(navmesh.corner(p, k))));
        }
        out.polygon_sizes.push_back(static_cast<uint8_t>(navmesh.corner_count(p)));
        out.areas.push_back(area);
    }
}

// The same link taken the other way, as a one-way link of its own (a drop climbed back is a jump).
Link reversed(const Link& l) {
    Link r = l;
    std::swap(r.start, r.end);
    std::swap(r.start_polygon, r.end_polygon);
    std::swap(r.requirements.rise, r.requirements.drop);
    if (r.kind == LinkKind::Drop) r.kind = LinkKind::Jump;
    r.bidirectional = false;
    return r;
}

}  // namespace

LinkGenerationReport World::generate_cross_links(Handle first, Handle second, const LinkSettings& settings,
                                                 float tolerance, GenerationProgress progress) {
    const NavMeshRegistry::GenerationOnThisThread not_from_inside_another;
    if (first == second)
        fail(ErrorCode::InvalidArgument, "the two navmeshes are one: its own links come from generate_links");
    if (!(tolerance >= 0.0f) || !std::isfinite(tolerance))
        fail_field(ErrorCode::InvalidArgument, "tolerance", " is ", tolerance, " (must be finite and >= 0)");
    const std::shared_ptr<const NavMesh> a = navmeshes_.navmesh(first), b = navmeshes_.navmesh(second);
    const CarrierPose pa = pose_of(navmeshes_.frame(first)), pb = pose_of(navmeshes_.frame(second));
    if (!same_body(a->agent(), b->agent()))
        fail(ErrorCode::InvalidArgument, "the two navmeshes were made for different bodies (radius ", a->agent().radius,
             " and ", b->agent().radius, ", height ", a->agent().height, " and ", b->agent().height,
             "): a link between them fits neither");

    // Told at once, even when the two are out of each other's reach and nothing is generated.
    if (!progress(0.0f, "cross links")) fail(ErrorCode::Cancelled, "cross link generation cancelled");
    NavMeshInput joined;
    joined.agent_type = a->agent();
    joined.weld_tolerance = 0.0f;
    const Aabb near_b = grown(pb.world_box(b->bounds()), settings), near_a = grown(pa.world_box(a->bounds()), settings);
    append_near(*a, pa, near_b, kFromFirst, joined);
    append_near(*b, pb, near_a, kFromSecond, joined);
    LinkGenerationReport report;
    std::vector<Link> first_to_second, second_to_first;
    if (!joined.polygon_sizes.empty() && std::count(joined.areas.begin(), joined.areas.end(), kFromSecond) > 0 &&
        std::count(joined.areas.begin(), joined.areas.end(), kFromFirst) > 0) {
        const std::shared_ptr<const NavMesh> mesh = nl::build_navmesh(joined);
        LinkGeneration generation(mesh, settings, GenerationMethod::Indexed);
        const std::vector<Link> links = generation.run(*level_, *tasks_, report, progress);
        report.jump_links = report.drop_links = 0;  // counted again below: only the links between the two
        for (const Link& found : links) {
            if (mesh->area(found.start_polygon) == mesh->area(found.end_polygon)) continue;  // its navmesh's own
            std::vector<Link> ways{found};
            if (found.bidirectional) ways.push_back(reversed(found));
            for (Link l : ways) {
                const bool forward = mesh->area(l.start_polygon) == kFromFirst;
                const CarrierPose& ps = forward ? pa : pb;
                const CarrierPose& pe = forward ? pb : pa;
                const Vec3 end = l.end;
                l = link_in_carrier_space(l, ps);
                l.end = pe.carrier_point(end);
                l.placed_end = ps.carrier_point(end);
                l.landing_navmesh = forward ? second : first;
                l.tolerance = tolerance;
                l.bidirectional = false;
                l.generated = true;
                place_cross_link(forward ? *a : *b, forward ? *b : *a, l);
                (l.kind == LinkKind::Drop ? report.drop_links : report.jump_links) += 1;
                (forward ? first_to_second : second_to_first).push_back(l);
            }
        }
    }
    // The links generated for this placement (those that hold now) are replaced; links placed for
    // another (a platform's other stop) stay for when it is back there.
    navmeshes_.store_cross_links(
        first, second, [&](const Link& l) { return cross_link_holds(l, pa, pb); }, first_to_second);
    navmeshes_.store_cross_links(
        second, first, [&](const Link& l) { return cross_link_holds(l, pb, pa); }, second_to_first);
    return report;
}

}  // namespace nl
