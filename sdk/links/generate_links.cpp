#include "links/generate_links.h"

#include "links/link_generation.h"

namespace nl {

std::vector<Link> generate_links(const NavMesh& navmesh, const Level& level, TaskSystem& tasks,
                                 const LinkSettings& settings, GenerationMethod method, LinkGenerationReport& report,
                                 GenerationProgress progress) {
    // A one-off generation: the caller keeps the navmesh alive for the call, so it is borrowed, not owned.
    LinkGeneration generation(std::shared_ptr<const NavMesh>(&navmesh, [](const NavMesh*) {}), settings, method);
    return generation.run(level, tasks, report, progress);
}

}  // namespace nl
