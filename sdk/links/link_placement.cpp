#include "links/link_placement.h"

#include <cmath>

#include "util/error.h"

namespace nl {
namespace {

uint32_t polygon_near(const NavMesh& navmesh, const Vec3& p, const char* end) {
    const NavPoint near = navmesh.find_nearest(p, Vec3::Constant(kLinkEndReach));
    if (!near.found || near.distance > kLinkEndReach)
        fail_field(ErrorCode::InvalidArgument, end, " is not within ", kLinkEndReach, " m of the navmesh");
    return near.polygon;
}

uint32_t polygon_still_under(const NavMesh& navmesh, const Vec3& p, uint32_t saved, const char* end) {
    if (saved < navmesh.polygon_count()) {
        // Seen from above: detail heights may sit a voxel above the polygon's own corners.
        const Vec3 q = navmesh.closest_point_on_polygon(saved, p);
        if (Vec3(q.x() - p.x(), 0.0f, q.z() - p.z()).norm() < 0.05f && std::fabs(q.y() - p.y()) < kLinkEndReach)
            return saved;
    }
    return polygon_near(navmesh, p, end);
}

}  // namespace

void place_link(const NavMesh& navmesh, Link& link) {
    link.start_polygon = polygon_near(navmesh, link.start, "start");
    link.end_polygon = polygon_near(navmesh, link.end, "end");
}

void place_cross_link(const NavMesh& from, const NavMesh& to, Link& link) {
    link.start_polygon = polygon_near(from, link.start, "start");
    link.end_polygon = polygon_near(to, link.end, "end");
}

bool cross_link_holds(const Link& link, const CarrierPose& from, const CarrierPose& to) {
    return (from.carrier_point(to.world_point(link.end)) - link.placed_end).norm() <= link.tolerance;
}

void place_saved_link(const NavMesh& navmesh, Link& link) {
    link.start_polygon = polygon_still_under(navmesh, link.start, link.start_polygon, "start");
    link.end_polygon = polygon_still_under(navmesh, link.end, link.end_polygon, "end");
}

Link link_in_world(Link link, const CarrierPose& pose) {
    link.start = pose.world_point(link.start);
    link.end = pose.world_point(link.end);
    link.apex = pose.world_point(link.apex);
    return link;
}

Link link_in_carrier_space(Link link, const CarrierPose& pose) {
    link.start = pose.carrier_point(link.start);
    link.end = pose.carrier_point(link.end);
    link.apex = pose.carrier_point(link.apex);
    return link;
}

Link link_in_world(Link link, const CarrierPose& from, const CarrierPose& to) {
    const Vec3 end = to.world_point(link.end);
    link = link_in_world(link, from);
    link.end = end;
    return link;
}

}  // namespace nl
