// World's link operations: links placed on their navmesh, and generations with the plugins' links.
#include <string>

#include "links/link_generation.h"
#include "level/mesh_validation.h"
#include "links/link_placement.h"
#include "world/world.h"

namespace nl {

Handle World::add_link(Handle navmesh, Link link) {
    link = link_in_surface(link, pose_of(navmeshes_.frame(navmesh)));
    place_link(*navmeshes_.navmesh(navmesh), link);
    link.generated = false;
    return navmeshes_.add_link(navmesh, link);
}

void World::update_link(Handle link, Link replacement) {
    const Handle navmesh = navmeshes_.link(link).first;
    replacement = link_in_surface(replacement, pose_of(navmeshes_.frame(navmesh)));
    place_link(*navmeshes_.navmesh(navmesh), replacement);
    navmeshes_.update_link(link, replacement);
}

std::pair<Handle, Link> World::link_in_world(Handle link) const {
    auto [navmesh, stored] = navmeshes_.link(link);
    return {navmesh, nl::link_in_world(stored, pose_of(navmeshes_.frame(navmesh)))};
}

void World::refuse_generation_on_surface(Handle navmesh) const {
    if (navmeshes_.frame(navmesh))
        fail(ErrorCode::InvalidArgument, "links are not generated on a navmesh that rides a moving mesh (its links would "
                                         "hold at one placement only): add its links with nl_link_add");
}

void World::load_links(Handle navmesh, std::vector<Link> links) {
    const std::shared_ptr<const NavMesh> mesh = navmeshes_.navmesh(navmesh);
    for (size_t i = 0; i < links.size(); ++i) {
        naming_fields(concat("links[", i, "].").c_str(), [&] { place_saved_link(*mesh, links[i]); });
    }
    navmeshes_.replace_links(navmesh, links);
}

std::vector<Link> World::plugin_links(Handle navmesh, const NavMesh& mesh, const PluginSettings& settings,
                                      LinkGenerationReport& report) {
    std::vector<Link> out;
    for (Plugin* plugin : plugins_.link_kind_plugins()) {
        LinkKindProvider& provider = *plugin->link_kind();
        std::string refusal;  // why the first link the plugin proposed that does not fit was refused
        auto accept = [&](Link link) {
            try {
                if (static_cast<uint32_t>(link.kind) != provider.kind())
                    fail(ErrorCode::InvalidArgument, "its kind is ", static_cast<uint32_t>(link.kind), ", not the plugin's kind ",
                         provider.kind());
                place_link(mesh, link);
            } catch (const Error& e) {
                if (e.code() != ErrorCode::OutOfMemory && refusal.empty()) refusal = e.what();
                throw;
            }
            link.generated = true;
            out.push_back(link);
        };
        const auto own = settings.find(provider.kind_name());
        try {
            provider.propose(*this, navmesh, own == settings.end() ? std::string() : own->second, accept);
        } catch (...) {
            if (refusal.empty()) throw;  // its own failure
        }
        if (!refusal.empty())
            fail(ErrorCode::Internal, "link-kind plugin '", plugin->description().name, "' proposed a link that was refused: ",
                 refusal);
    }
    report.plugin_links = static_cast<uint32_t>(out.size());
    return out;
}

LinkGenerationReport World::generate_links(Handle navmesh, const LinkSettings& settings, PluginSettings plugin_settings,
                                           GenerationProgress progress) {
    const std::shared_ptr<const NavMesh> mesh = navmeshes_.navmesh(navmesh);
    refuse_generation_on_surface(navmesh);
    auto generation = std::make_shared<LinkGeneration>(mesh, settings, GenerationMethod::Indexed);
    const NavMeshRegistry::GenerationTurn one_at_a_time = navmeshes_.take_generation_turn(navmesh);
    LinkGenerationReport report;
    std::vector<Link> links = generation->run(*level_, *tasks_, report, progress);
    const std::vector<Link> extra = plugin_links(navmesh, *mesh, plugin_settings, report);
    links.insert(links.end(), extra.begin(), extra.end());
    navmeshes_.store_generation(navmesh, LastGeneration{std::move(generation), std::move(plugin_settings)}, links);
    return report;
}

LinkGenerationReport World::update_links_in_box(Handle navmesh, const Aabb& box, GenerationProgress progress) {
    const std::shared_ptr<const NavMesh> mesh = navmeshes_.navmesh(navmesh);
    refuse_generation_on_surface(navmesh);
    if (!within_coordinate_limit(box.min) || !within_coordinate_limit(box.max) || box.empty())
        fail(ErrorCode::InvalidArgument, "the box's corners must be finite, within the coordinate limit, and min <= max");
    const NavMeshRegistry::GenerationTurn one_at_a_time = navmeshes_.take_generation_turn(navmesh);
    const LastGeneration last = navmeshes_.last_generation(navmesh);
    if (!last.generation)
        fail(ErrorCode::NotFound, "the navmesh has no generation to update (never generated, or its generated links were "
                                  "removed or replaced by a JSON load since): generate its links first");
    LinkGenerationReport report;
    std::vector<Link> links = last.generation->update(box, *level_, *tasks_, report, progress);
    const std::vector<Link> extra = plugin_links(navmesh, *mesh, last.plugin_settings, report);
    links.insert(links.end(), extra.begin(), extra.end());
    if (!navmeshes_.store_update(navmesh, last.generation.get(), links))
        fail(ErrorCode::NotFound, "the navmesh's generated links were removed or replaced by a JSON load during the update");
    return report;
}

}  // namespace nl
