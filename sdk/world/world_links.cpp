// World's link operations: links placed on their navmesh, and generations with the plugins' links.
#include <algorithm>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "io/json_input.h"
#include "io/link_json.h"
#include "links/link_generation.h"
#include "level/level_hash.h"
#include "level/mesh_validation.h"
#include "links/link_placement.h"
#include "links/tile_links.h"
#include "util/excerpt.h"
#include "world/world.h"

namespace nl {

CarrierPose World::navmesh_pose(Handle navmesh) const {
    try {
        return pose_of(navmeshes_.frame(navmesh));
    } catch (const Error& e) {
        if (e.code() != ErrorCode::InvalidHandle) throw;
        return CarrierPose{};  // a cross link's landing navmesh removed since: the link leads nowhere
    }
}

void World::place_host_link(Handle navmesh, Link& link) const {
    const std::shared_ptr<const NavMesh> from = navmeshes_.navmesh(navmesh);
    const CarrierPose from_pose = pose_of(navmeshes_.frame(navmesh));
    if (!link.crosses()) {
        link = link_in_carrier_space(link, from_pose);
        place_link(*from, link);
        return;
    }
    std::shared_ptr<const NavMesh> to;
    CarrierPose to_pose;
    try {
        to = navmeshes_.navmesh(link.landing_navmesh);
        to_pose = pose_of(navmeshes_.frame(link.landing_navmesh));
    } catch (const Error& e) {
        if (e.code() != ErrorCode::InvalidHandle) throw;
        fail_field(ErrorCode::InvalidHandle, "landing_navmesh", ": ", e.what());
    }
    if (link.landing_navmesh == navmesh)
        fail_field(ErrorCode::InvalidArgument, "landing_navmesh",
                   " is the link's own navmesh (leave it null for a link within it)");
    if (link.bidirectional)
        fail_field(ErrorCode::InvalidArgument, "bidirectional",
                   " is set on a link to another navmesh: such links are one-way "
                   "(add one each way)");
    if (!(link.tolerance >= 0.0f) || !std::isfinite(link.tolerance))
        fail_field(ErrorCode::InvalidArgument, "tolerance", " is ", link.tolerance, " (must be finite and >= 0)");
    // Placed as the two navmeshes stand now: it holds while they stay so (cross_link_holds).
    const Vec3 end = link.end;
    link = link_in_carrier_space(link, from_pose);
    link.end = to_pose.carrier_point(end);
    link.placed_end = from_pose.carrier_point(end);
    place_cross_link(*from, *to, link);
}

Handle World::add_link(Handle navmesh, Link link) {
    place_host_link(navmesh, link);
    link.generated = false;
    return navmeshes_.add_link(navmesh, link);
}

void World::update_link(Handle link, Link replacement) {
    const Handle navmesh = navmeshes_.link(link).first;
    place_host_link(navmesh, replacement);
    navmeshes_.update_link(link, replacement);
}

Link World::in_world(Handle navmesh, const Link& link) const {
    const CarrierPose from = navmesh_pose(navmesh);
    return link.crosses() ? nl::link_in_world(link, from, navmesh_pose(link.landing_navmesh))
                          : nl::link_in_world(link, from);
}

std::pair<Handle, Link> World::link_in_world(Handle link) const {
    const auto [navmesh, stored] = navmeshes_.link(link);
    return {navmesh, in_world(navmesh, stored)};
}

bool World::link_holds(Handle navmesh, const Link& link) const {
    if (link.start_polygon == kNoPolygon || link.end_polygon == kNoPolygon) return false;  // parked: a tile is out
    return !link.crosses() || cross_link_holds(link, navmesh_pose(navmesh), navmesh_pose(link.landing_navmesh));
}

void World::refuse_generation_on_carrier(Handle navmesh) const {
    if (navmeshes_.frame(navmesh))
        fail(ErrorCode::InvalidArgument,
             "links are not generated on a navmesh that rides a moving mesh (its links would "
             "hold at one placement only): add its links with nl_link_add");
}

void World::load_links(Handle navmesh, std::vector<Link> links, LinkProvenance made_with) {
    const std::shared_ptr<const NavMesh> mesh = navmeshes_.navmesh(navmesh);
    for (size_t i = 0; i < links.size(); ++i) {
        naming_fields(concat("links[", i, "].").c_str(), [&] { place_saved_link(*mesh, links[i]); });
    }
    navmeshes_.replace_links(navmesh, links, std::move(made_with));
}

void World::load_links_file(Handle navmesh, LinksFile file, bool any_body) {
    if (file.made_for) {
        const auto mesh = navmeshes_.navmesh(navmesh);
        const AgentType ours = mesh->agent(), theirs = file.made_for->agent_type;
        if (!same_body(ours, theirs)) {
            const std::string why =
                concat("the links were generated for a body of radius ", theirs.radius, " m and height ", theirs.height,
                       " m; this navmesh was built for radius ", ours.radius, " m and height ", ours.height, " m");
            if (!any_body)
                fail(ErrorCode::InvalidArgument, why,
                     ": generate links for this navmesh, or load them anyway with NL_LINKS_LOAD_ANY_BODY");
            logger_.log(LogLevel::Warning, concat(why, ": loaded anyway (NL_LINKS_LOAD_ANY_BODY)"));
        }
    }
    // Made for another level (both hashes known and unequal): a link end off the navmesh is most
    // likely why, and the failure says so; links that do fit load, with a warning.
    const uint64_t ours = navmeshes_.made_for(navmesh).level_hash,
                   theirs = file.made_for ? file.made_for->level_hash : 0;
    const bool other_level = ours != 0 && theirs != 0 && ours != theirs;
    const std::string level_words =
        other_level ? concat("these links were made for another level (level hash ", level_hash_text(theirs),
                             "; this navmesh was built from ", level_hash_text(ours), ")")
                    : std::string();
    try {
        load_links(navmesh, std::move(file.links), file.made_for ? file.made_for->made_with : LinkProvenance{});
    } catch (const Error& e) {
        if (!other_level || e.code() != ErrorCode::InvalidArgument) throw;
        throw Error(e.code(), concat(level_words, ": ", e.what()));
    }
    if (other_level)
        logger_.log(LogLevel::Warning, concat(level_words, ": every end lies on this navmesh, so they were loaded"));
}

World::PluginLinks World::plugin_links(Handle navmesh, const NavMesh& mesh, const PluginSettings& settings,
                                       LinkGenerationReport& report) {
    std::vector<Link> out;
    nlohmann::json ran = nlohmann::json::object();
    for (Plugin* plugin : plugins_.link_kind_plugins()) {
        LinkKindProvider& provider = *plugin->link_kind();
        std::string refusal;  // why the first link the plugin proposed that does not fit was refused
        auto accept = [&](Link link) {
            try {
                if (static_cast<uint32_t>(link.kind) != provider.kind())
                    fail(ErrorCode::InvalidArgument, "its kind is ", static_cast<uint32_t>(link.kind),
                         ", not the plugin's kind ", provider.kind());
                place_link(mesh, link);
            } catch (const Error& e) {
                if (e.code() != ErrorCode::OutOfMemory && refusal.empty()) refusal = e.what();
                throw;
            }
            link.generated = true;
            out.push_back(link);
        };
        const auto own = settings.find(provider.kind_name());
        ran[provider.kind_name()] = {{"plugin", plugin->description().name},
                                     {"version", plugin->description().version},
                                     {"settings", own == settings.end() ? nlohmann::json::object()
                                                                        : parse_json(own->second, "plugin settings")}};
        try {
            provider.propose(*this, navmesh, own == settings.end() ? std::string() : own->second, accept);
        } catch (...) {
            if (refusal.empty()) throw;  // its own failure
        }
        if (!refusal.empty())
            fail(ErrorCode::Internal, "link-kind plugin '", plugin->description().name,
                 "' proposed a link that was refused: ", refusal);
    }
    report.plugin_links = static_cast<uint32_t>(out.size());
    // Names and versions come from plugins: bytes that are not UTF-8 are kept as U+FFFD.
    return {std::move(out),
            ran.empty() ? std::string() : ran.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)};
}

void World::check_plugin_settings(const PluginSettings& settings) const {
    std::vector<std::string> kinds;
    for (Plugin* p : plugins_.link_kind_plugins()) kinds.push_back(p->link_kind()->kind_name());
    for (const auto& entry : settings) {
        if (std::find(kinds.begin(), kinds.end(), entry.first) == kinds.end())
            fail(ErrorCode::InvalidArgument, "plugin_settings_json: no loaded link-kind plugin provides the kind ",
                 quoted_excerpt(entry.first), " (loaded: ", listed_names(kinds), ")");
    }
}

LinkGenerationReport World::generate_links(Handle navmesh, const LinkSettings& settings, PluginSettings plugin_settings,
                                           GenerationProgress progress) {
    check_plugin_settings(plugin_settings);
    refuse_generation_on_carrier(navmesh);
    const NavMeshRegistry::GenerationTurn one_at_a_time = navmeshes_.take_generation_turn(navmesh);
    // Read under the turn: tiles added or removed before it was ours replaced the navmesh.
    const std::shared_ptr<const NavMesh> mesh = navmeshes_.navmesh(navmesh);
    LastGeneration last;
    LinkGenerationReport report;
    std::vector<Link> links;
    if (mesh->tiles().grid.tiled()) {
        // A tile at a time, as the tiles that arrive later get theirs (tile_links.h).
        last.tile_settings = std::make_shared<const LinkSettings>(settings);
        links = generate_tile_links(navmeshes_.tile_inputs(navmesh), mesh->tiles().tiles, *level_, *tasks_, settings,
                                    report, progress);
    } else {
        last.generation = std::make_shared<LinkGeneration>(mesh, settings, GenerationMethod::Indexed);
        links = last.generation->run(*level_, *tasks_, report, progress);
    }
    PluginLinks extra = plugin_links(navmesh, *mesh, plugin_settings, report);
    links.insert(links.end(), extra.links.begin(), extra.links.end());
    last.plugin_settings = std::move(plugin_settings);
    navmeshes_.store_generation(navmesh, std::move(last), links,
                                LinkProvenance{link_settings_to_json(settings), std::move(extra.made_with)});
    return report;
}

LinkGenerationReport World::update_links_in_box(Handle navmesh, const Aabb& box, GenerationProgress progress) {
    const std::shared_ptr<const NavMesh> mesh = navmeshes_.navmesh(navmesh);
    refuse_generation_on_carrier(navmesh);
    if (!within_coordinate_limit(box.min) || !within_coordinate_limit(box.max) || box.empty())
        fail(ErrorCode::InvalidArgument,
             "the box's corners must be finite, within the coordinate limit, and min <= max");
    const NavMeshRegistry::GenerationTurn one_at_a_time = navmeshes_.take_generation_turn(navmesh);
    const LastGeneration last = navmeshes_.last_generation(navmesh);
    if (!last.generation && !last.tile_settings)
        fail(ErrorCode::NotFound,
             "the navmesh has no generation to update (never generated, or its generated links were "
             "removed or replaced by a JSON load since): generate its links first");
    LinkGenerationReport report;
    if (last.tile_settings) {
        // The tiles whose links can see into the box have theirs generated again; plugin links stay.
        const std::shared_ptr<const NavMesh> tiled = navmeshes_.navmesh(navmesh);
        TileLinks regenerated;
        regenerated.owners =
            tiles_within_reach(tiled->tiles().grid, tiled->tiles().tiles, box, tile_link_reach(*last.tile_settings));
        regenerated.links = generate_tile_links(navmeshes_.tile_inputs(navmesh), regenerated.owners, *level_, *tasks_,
                                                *last.tile_settings, report, progress);
        if (!navmeshes_.store_tile_links(navmesh, last.tile_settings.get(), regenerated))
            fail(ErrorCode::NotFound,
                 "the navmesh's generated links were removed or replaced by a JSON load during the update");
        return report;
    }
    std::vector<Link> links = last.generation->update(box, *level_, *tasks_, report, progress);
    const PluginLinks extra = plugin_links(navmesh, *mesh, last.plugin_settings, report);
    links.insert(links.end(), extra.links.begin(), extra.links.end());
    if (!navmeshes_.store_update(navmesh, last.generation.get(), links))
        fail(ErrorCode::NotFound,
             "the navmesh's generated links were removed or replaced by a JSON load during the update");
    return report;
}

}  // namespace nl
