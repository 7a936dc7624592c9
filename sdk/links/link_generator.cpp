#include "links/link_generator.h"

#include "links/link_bake.h"

namespace nl {

std::vector<Link> generate_links(const NavMesh& navmesh, const Level& level, TaskSystem& tasks, const LinkSettings& settings,
                                 BakeMethod method, BakeReport& report, BakeProgress progress) {
    // A one-off bake: the caller keeps the navmesh alive for the call, so it is borrowed, not owned.
    LinkBake bake(std::shared_ptr<const NavMesh>(&navmesh, [](const NavMesh*) {}), settings, method);
    return bake.run(level, tasks, report, progress);
}

}  // namespace nl
