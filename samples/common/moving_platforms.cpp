#include "moving_platforms.h"

#include "navmesh_setup.h"
#include "sample_error.h"

namespace nl::samples {
namespace {

// Half Recast's usual cell size: a platform is small, and at 0.3 m cells a 4 m deck loses a cell to
// the ledge filter and two to the radius at each rim, which leaves a region under Recast's smallest.
constexpr const char* kPlatformRecastSettings = R"({"cell_size": 0.15})";

nl_mesh_id add_movable_mesh(nl_world* world, const levelgen::GeneratedLevel& body, const PlatformPose& pose) {
    const std::array<float, 16> transform = pose.transform();
    nl_mesh_def def = nl_default_mesh_def();
    def.vertices = body.positions.data();
    def.vertex_count = body.vertex_count();
    def.indices = body.indices.data();
    def.triangle_count = body.triangle_count();
    def.flags = NL_MESH_MOVABLE;
    def.transform = transform.data();
    nl_mesh_id mesh{};
    check(nl_mesh_add(world, &def, &mesh), "registering its body");
    return mesh;
}

void set_pose(nl_world* world, nl_mesh_id mesh, const PlatformPose& pose) {
    const std::array<float, 16> transform = pose.transform();
    check(nl_mesh_set_transform(world, mesh, transform.data()), "moving it");
}

nl_link_id add_gangway(nl_world* world, nl_navmesh_id ground, nl_navmesh_id platform, const Gangway& gangway) {
    nl_link_def def = nl_default_link_def();
    def.kind = gangway.kind;
    for (int k = 0; k < 3; ++k) {
        def.start[k] = gangway.start[k];
        def.end[k] = gangway.end[k];
    }
    def.landing_navmesh = gangway.onto ? platform : ground;
    // Walked across, as a gangway is: measured from its ends it would be a jump of its length. A
    // jump keeps what its ends measure (its gap and rise choose who can take it).
    def.requirements_as_given = gangway.kind == NL_LINK_MANUAL;
    nl_link_id id{};
    check(nl_link_add(world, gangway.onto ? ground : platform, &def, &id), "adding its " + gangway.name);
    return id;
}

}  // namespace

MovingPlatform add_moving_platform(nl_world* world, nl_navmesh_id ground, const PlatformLayout& layout,
                                   const nl_agent_type& body, double time) {
    MovingPlatform platform;
    platform.layout = &layout;
    try {
        platform.mesh = add_movable_mesh(world, layout.body, layout.timetable.at(time));
        platform.navmesh = build_navmesh(world, body, kPlatformRecastSettings, platform.mesh);
        // A cross link holds while its ends stand as they did when it was added: each gangway is
        // added with the platform where it docks for it.
        for (const Gangway& gangway : layout.gangways) {
            set_pose(world, platform.mesh, layout.timetable.at(gangway.placed_at));
            platform.gangways.push_back(add_gangway(world, ground, platform.navmesh, gangway));
        }
        set_pose(world, platform.mesh, layout.timetable.at(time));
    } catch (const SampleError& e) {
        remove_moving_platform(world, platform);
        throw SampleError("the " + layout.name + ": " + e.what());
    }
    return platform;
}

std::vector<MovingPlatform> add_moving_platforms(nl_world* world, nl_navmesh_id ground,
                                                 const std::vector<PlatformLayout>& layouts, const nl_agent_type& body,
                                                 double time) {
    std::vector<MovingPlatform> platforms;
    for (const PlatformLayout& layout : layouts)
        platforms.push_back(add_moving_platform(world, ground, layout, body, time));
    return platforms;
}

void move_platform(nl_world* world, const MovingPlatform& platform, double time) {
    try {
        set_pose(world, platform.mesh, platform.layout->timetable.at(time));
    } catch (const SampleError& e) {
        throw SampleError("the " + platform.layout->name + ": " + e.what());
    }
}

void move_platforms(nl_world* world, const std::vector<MovingPlatform>& platforms, double time) {
    for (const MovingPlatform& platform : platforms) move_platform(world, platform, time);
}

void remove_moving_platform(nl_world* world, const MovingPlatform& platform) {
    for (nl_link_id link : platform.gangways) nl_link_remove(world, link);
    if (platform.navmesh.index1) nl_navmesh_remove(world, platform.navmesh);
    if (platform.mesh.index1) nl_mesh_remove(world, platform.mesh);
}

bool same_link(nl_link_id a, nl_link_id b) { return a.index1 == b.index1 && a.revision == b.revision; }

std::optional<GangwayLink> find_gangway(const std::vector<MovingPlatform>& platforms, nl_link_id link) {
    for (const MovingPlatform& platform : platforms)
        for (size_t i = 0; i < platform.gangways.size(); ++i)
            if (same_link(platform.gangways[i], link)) return GangwayLink{&platform, &platform.layout->gangways[i]};
    return std::nullopt;
}

}  // namespace nl::samples
