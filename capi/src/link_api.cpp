#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>

#include "entry_guard.h"
#include "first_sizes.h"
#include "field_copy.h"
#include "host_input.h"
#include "io/link_json.h"
#include "links/link_placement.h"
#include "mapping.h"
#include "world.h"

using nl::ErrorCode;
using nl::fail;
using nl::capi::deref;
using nl::capi::guarded;
using nl::capi::require;
using nl::capi::to_handle;
using nl::capi::copy_point;
using nl::capi::to_id;

namespace {

// The first release ended with the requirements before their length.
constexpr size_t kMaxDropAngles = sizeof(nl_link_settings::drop_angles) / sizeof(float);

nl::LinkSettings to_core(const nl_link_settings& c) {
    nl::LinkSettings s;
    NL_COPY_FIELDS(NL_LINK_SETTINGS_FIELDS, s, c);
    if (c.drop_angle_count > kMaxDropAngles)
        fail(ErrorCode::InvalidArgument, "settings->drop_angle_count is ", c.drop_angle_count, " (at most ",
             kMaxDropAngles, ")");
    s.drop_angles.assign(c.drop_angles, c.drop_angles + c.drop_angle_count);
    return s;
}

nl_link_settings to_c(const nl::LinkSettings& s) {
    nl_link_settings c{};
    c.size = sizeof c;
    NL_COPY_FIELDS(NL_LINK_SETTINGS_FIELDS, c, s);
    c.drop_angle_count = static_cast<uint32_t>(std::min(s.drop_angles.size(), kMaxDropAngles));
    std::copy_n(s.drop_angles.begin(), c.drop_angle_count, c.drop_angles);
    return c;
}

nl_link to_c(const nl::StoredLink& stored, nl::Handle navmesh, bool holds) {
    const nl::Link& l = stored.link;
    nl_link c{};
    c.size = sizeof c;
    c.id = to_id<nl_link_id>(stored.id);
    c.navmesh = to_id<nl_navmesh_id>(navmesh);
    c.kind = static_cast<nl_link_kind>(l.kind);
    copy_point(c.start, l.start);
    copy_point(c.end, l.end);
    copy_point(c.apex, l.apex);
    c.bidirectional = l.bidirectional;
    c.generated = l.generated;
    c.enabled = l.enabled;
    c.cost_modifier = l.cost_modifier;
    c.user_data = l.user_data;
    const nl::LinkRequirements& r = l.requirements;
    c.requirements = nl_link_requirements{r.gap, r.rise, r.drop, r.clearance_width, r.abilities, r.length, 0};
    c.start_polygon = l.start_polygon;
    c.end_polygon = l.end_polygon;
    c.landing_navmesh = to_id<nl_navmesh_id>(l.landing_navmesh);
    c.tolerance = l.tolerance;
    c.holds = holds ? 1 : 0;
    return c;
}

nl_link_generation_report to_c(const nl::LinkGenerationReport& r) {
    nl_link_generation_report c{};
    c.size = sizeof c;
    NL_COPY_FIELDS(NL_LINK_GENERATION_REPORT_FIELDS, c, r);
    return c;
}

// The host's progress callback as the core's (no callback: never cancel).
// The caller's settings (NULL: the defaults), every field read from the copy: a caller's struct holds
// only `size` bytes.
nl_link_settings read_settings(const nl_link_settings* settings) {
    const nl_link_settings given = settings
                                       ? nl::capi::read_growable(*settings, nl_default_link_settings(),
                                                                 nl::capi::kFirstSize<nl_link_settings>, "settings")
                                       : nl_default_link_settings();
    if (!given.plugin_settings_json && given.plugin_settings_json_length != 0)
        fail(ErrorCode::InvalidArgument,
             "settings->plugin_settings_json is null but settings->plugin_settings_json_length is ",
             given.plugin_settings_json_length);
    return given;
}

nl::LinkSettings core_settings_of(const nl_link_settings& given) {
    return nl::naming_fields("settings->", [&] {
        nl::LinkSettings s = to_core(given);
        nl::validate(s);
        return s;
    });
}

nl::PluginSettings plugin_settings_of(const nl_link_settings& given) {
    return nl::naming_fields("settings->", [&] {
        return nl::plugin_settings_from_json(
            given.plugin_settings_json ? std::string_view(given.plugin_settings_json, given.plugin_settings_json_length)
                                       : std::string_view());
    });
}

std::vector<nl::Link> links_of(const nl::LinkSnapshot& snapshot) {
    std::vector<nl::Link> out;
    out.reserve(snapshot.size());
    for (const nl::StoredLink& s : snapshot) out.push_back(s.link);
    return out;
}

}  // namespace

namespace nl::capi {

Link link_from_def(const nl_link_def& given) {
    const nl_link_def def = read_growable(given, nl_default_link_def(), nl::capi::kFirstSize<nl_link_def>, "def");
    const LinkKind kind = static_cast<LinkKind>(def.kind);
    if (kind != LinkKind::Jump && kind != LinkKind::Drop && kind != LinkKind::Manual &&
        def.kind < NL_LINK_FIRST_PLUGIN_KIND)
        fail_field(ErrorCode::InvalidArgument, "kind is ", def.kind, " (NL_LINK_* or a plugin kind >= 256)");
    read_amount(def.cost_modifier, "cost_modifier");
    read_amount(def.tolerance, "tolerance");
    for (const auto& [value, name] :
         {std::pair{def.requirements.gap, "gap"}, std::pair{def.requirements.rise, "rise"},
          std::pair{def.requirements.drop, "drop"}, std::pair{def.requirements.clearance_width, "clearance_width"},
          std::pair{def.requirements.length, "length"}})
        read_amount(value, "requirements.", name);
    Link l;
    l.kind = kind;
    l.start = read_position(def.start, "start");
    l.end = read_position(def.end, "end");
    l.apex = nl::higher_end(l);
    l.bidirectional = def.bidirectional != 0;
    l.enabled = def.enabled != 0;
    l.cost_modifier = def.cost_modifier;
    l.user_data = def.user_data;
    l.landing_navmesh = to_handle(def.landing_navmesh);
    l.tolerance = l.crosses() ? def.tolerance : 0.0f;
    const nl_link_requirements& r = def.requirements;
    l.requirements.gap = r.gap;
    l.requirements.length = r.length;
    l.requirements.rise = r.rise;
    l.requirements.drop = r.drop;
    l.requirements.clearance_width = r.clearance_width;
    l.requirements.abilities = r.abilities;
    settle_host_requirements(l, def.requirements_as_given != 0);
    return l;
}

}  // namespace nl::capi

extern "C" {

NL_API nl_link_def nl_default_link_def(void) {
    nl_link_def def{};
    def.size = sizeof def;
    def.kind = NL_LINK_MANUAL;
    def.enabled = 1;
    def.cost_modifier = 1.0f;
    def.tolerance = nl::kDefaultCrossTolerance;
    return def;
}

NL_API nl_status nl_link_add(nl_world* world, nl_navmesh_id navmesh, const nl_link_def* def, nl_link_id* out_id) {
    return guarded("nl_link_add", world, [&] {
        nl::World& w = deref(world);
        w.navmeshes().navmesh(to_handle(navmesh));  // a stale id first, before the def
        require(def, "def");
        require(out_id, "out_id");
        *out_id = to_id<nl_link_id>(
            nl::naming_fields("def->", [&] { return w.add_link(to_handle(navmesh), nl::capi::link_from_def(*def)); }));
    });
}

NL_API nl_status nl_link_update(nl_world* world, nl_link_id link, const nl_link_def* def) {
    return guarded("nl_link_update", world, [&] {
        nl::World& w = deref(world);
        w.navmeshes().link(to_handle(link));  // a stale id first, before the def
        require(def, "def");
        nl::naming_fields("def->", [&] { w.update_link(to_handle(link), nl::capi::link_from_def(*def)); });
    });
}

NL_API nl_status nl_link_remove(nl_world* world, nl_link_id link) {
    return guarded("nl_link_remove", world, [&] { deref(world).navmeshes().remove_link(to_handle(link)); });
}

NL_API int32_t nl_link_is_valid(const nl_world* world, nl_link_id link) {
    int32_t valid = 0;
    guarded("nl_link_is_valid", world,
            [&] { valid = deref(world).navmeshes().contains_link(to_handle(link)) ? 1 : 0; });
    return valid;
}

NL_API nl_status nl_link_get(const nl_world* world, nl_link_id link, nl_link* out_link) {
    return guarded("nl_link_get", world, [&] {
        const nl::World& w = deref(world);
        const auto [navmesh, stored] = w.navmeshes().link(to_handle(link));
        require(out_link, "out_link");
        nl::capi::write_growable(
            out_link,
            to_c(nl::StoredLink{to_handle(link), w.in_world(navmesh, stored)}, navmesh, w.link_holds(navmesh, stored)),
            nl::capi::kFirstSize<nl_link>, "out_link");
    });
}

NL_API nl_status nl_navmesh_get_links(const nl_world* world, nl_navmesh_id navmesh, nl_link* out_links,
                                      uint32_t capacity, uint32_t* out_count) {
    return guarded("nl_navmesh_get_links", world, [&] {
        const nl::Handle mesh = to_handle(navmesh);
        const nl::World& w = deref(world);
        const auto snapshot = w.navmeshes().links(mesh);
        nl::capi::list_growable_into(
            *snapshot, out_links, capacity, out_count, nl::capi::kFirstSize<nl_link>, "out_links",
            [&](const nl::StoredLink& s) {
                return to_c(nl::StoredLink{s.id, w.in_world(mesh, s.link)}, mesh, w.link_holds(mesh, s.link));
            });
    });
}

NL_API nl_status nl_navmesh_remove_generated_links(nl_world* world, nl_navmesh_id navmesh, uint32_t* out_removed) {
    return guarded("nl_navmesh_remove_generated_links", world, [&] {
        const uint32_t removed = deref(world).navmeshes().remove_generated_links(to_handle(navmesh));
        if (out_removed) *out_removed = removed;
    });
}

NL_API nl_link_settings nl_default_link_settings(void) { return to_c(nl::LinkSettings{}); }

NL_API nl_status nl_link_settings_from_json(const char* json, size_t length, nl_link_settings* settings) {
    return guarded("nl_link_settings_from_json", nullptr, [&] {
        require(settings, "settings");
        if (length > 0) require(json, "json");
        const nl_link_settings given = nl::capi::read_growable(*settings, nl_default_link_settings(),
                                                               nl::capi::kFirstSize<nl_link_settings>, "settings");
        nl::LinkSettings s = to_core(given);
        nl::apply_settings_json(std::string_view(json ? json : "", length), s);
        if (s.drop_angles.size() > kMaxDropAngles)
            fail(ErrorCode::InvalidArgument, "settings.drop_angles has more than ", kMaxDropAngles, " entries");
        nl_link_settings out = to_c(s);
        // The plugins' settings are the host's pointer, not the JSON's business.
        out.plugin_settings_json = given.plugin_settings_json;
        out.plugin_settings_json_length = given.plugin_settings_json_length;
        nl::capi::write_growable(settings, out, nl::capi::kFirstSize<nl_link_settings>, "settings");
    });
}

NL_API nl_status nl_navmesh_generate_links(nl_world* world, nl_navmesh_id navmesh, const nl_link_settings* settings,
                                           nl_progress_fn* progress, void* user,
                                           nl_link_generation_report* out_report) {
    return guarded("nl_navmesh_generate_links", world, [&] {
        nl::World& w = deref(world);
        w.navmeshes().navmesh(to_handle(navmesh));  // a stale id first, before the settings
        const nl_link_settings given = read_settings(settings);
        if (out_report)
            nl::capi::check_growable_output(out_report, nl::capi::kFirstSize<nl_link_generation_report>, "out_report");
        const nl::LinkSettings core_settings = core_settings_of(given);
        nl::PluginSettings plugin_settings = plugin_settings_of(given);
        const nl::LinkGenerationReport report = w.generate_links(
            to_handle(navmesh), core_settings, std::move(plugin_settings), nl::capi::progress_of(progress, user));
        if (out_report)
            nl::capi::write_growable(out_report, to_c(report), nl::capi::kFirstSize<nl_link_generation_report>,
                                     "out_report");
    });
}

NL_API nl_status nl_navmesh_generate_cross_links(nl_world* world, nl_navmesh_id first, nl_navmesh_id second,
                                                 float tolerance, const nl_link_settings* settings,
                                                 nl_progress_fn* progress, void* user,
                                                 nl_link_generation_report* out_report) {
    return guarded("nl_navmesh_generate_cross_links", world, [&] {
        nl::World& w = deref(world);
        // Stale ids first, before the settings, each named.
        for (const auto& [id, name] : {std::pair{first, "first"}, std::pair{second, "second"}}) {
            try {
                w.navmeshes().navmesh(to_handle(id));
            } catch (const nl::Error& e) {
                if (e.code() != ErrorCode::InvalidHandle) throw;
                fail(ErrorCode::InvalidHandle, name, ": ", e.what());
            }
        }
        const nl_link_settings given = read_settings(settings);
        if (out_report)
            nl::capi::check_growable_output(out_report, nl::capi::kFirstSize<nl_link_generation_report>, "out_report");
        const nl::LinkSettings core_settings = core_settings_of(given);
        // Checked as for any generation, though link-kind plugins link within one navmesh.
        w.check_plugin_settings(plugin_settings_of(given));
        const nl::LinkGenerationReport report = w.generate_cross_links(
            to_handle(first), to_handle(second), core_settings, tolerance, nl::capi::progress_of(progress, user));
        if (out_report)
            nl::capi::write_growable(out_report, to_c(report), nl::capi::kFirstSize<nl_link_generation_report>,
                                     "out_report");
    });
}

NL_API nl_status nl_navmesh_update_links_in_box(nl_world* world, nl_navmesh_id navmesh, const float* box_min,
                                                const float* box_max, nl_progress_fn* progress, void* user,
                                                nl_link_generation_report* out_report) {
    return guarded("nl_navmesh_update_links_in_box", world, [&] {
        nl::World& w = deref(world);
        w.navmeshes().navmesh(to_handle(navmesh));  // a stale id first, before the box
        require(box_min, "box_min");
        require(box_max, "box_max");
        nl::Aabb box;
        box.min = nl::Vec3(box_min[0], box_min[1], box_min[2]);
        box.max = nl::Vec3(box_max[0], box_max[1], box_max[2]);
        if (!nl::within_coordinate_limit(box.min) || !nl::within_coordinate_limit(box.max) || box.empty())
            fail(ErrorCode::InvalidArgument, "box_min and box_max must be finite, within the limit, and min <= max");
        if (out_report)
            nl::capi::check_growable_output(out_report, nl::capi::kFirstSize<nl_link_generation_report>, "out_report");
        const nl::LinkGenerationReport report = [&] {
            try {
                return w.update_links_in_box(to_handle(navmesh), box, nl::capi::progress_of(progress, user));
            } catch (const nl::Error& e) {
                if (e.code() != ErrorCode::NotFound) throw;
                throw nl::Error(e.code(), nl::concat(e.what(), " (nl_navmesh_generate_links)"));
            }
        }();
        if (out_report)
            nl::capi::write_growable(out_report, to_c(report), nl::capi::kFirstSize<nl_link_generation_report>,
                                     "out_report");
    });
}

NL_API nl_status nl_navmesh_save_links_json(const nl_world* world, nl_navmesh_id navmesh, char* buffer, size_t capacity,
                                            size_t* out_length) {
    return guarded("nl_navmesh_save_links_json", world, [&] {
        const nl::World& w = deref(world);
        const auto snapshot = w.navmeshes().links(to_handle(navmesh));
        require(out_length, "out_length");
        if (!buffer && capacity > 0) fail(ErrorCode::InvalidArgument, "buffer is null but capacity is ", capacity);
        const std::shared_ptr<const nl::NavMesh> mesh = w.navmeshes().navmesh(to_handle(navmesh));
        const nl::NavMeshProvenance recorded = w.navmeshes().made_for(to_handle(navmesh));
        const nl::LinksFileProvenance made_for{mesh->agent(), recorded.links, recorded.level_hash};
        const std::string json = nl::links_to_json(links_of(*snapshot), &made_for);
        *out_length = json.size();
        if (!buffer) return;
        if (json.size() >= capacity)
            fail(ErrorCode::BufferTooSmall, "capacity is ", capacity, " but ", json.size() + 1, " bytes are needed");
        std::memcpy(buffer, json.c_str(), json.size() + 1);
    });
}

NL_API nl_status nl_navmesh_load_links_json(nl_world* world, nl_navmesh_id navmesh, const char* json, size_t length,
                                            uint32_t flags, uint32_t* out_count) {
    return guarded("nl_navmesh_load_links_json", world, [&] {
        nl::World& w = deref(world);
        w.navmeshes().navmesh(to_handle(navmesh));  // a stale id first, before the text
        if (length > 0) require(json, "json");
        if (flags & ~NL_LINKS_LOAD_ANY_BODY)
            fail(ErrorCode::InvalidArgument, "flags has unknown bits 0x", std::hex, flags & ~NL_LINKS_LOAD_ANY_BODY);
        nl::LinksFile file = nl::read_links_json(std::string_view(json ? json : "", length));
        const size_t count = file.links.size();
        w.load_links_file(to_handle(navmesh), std::move(file), (flags & NL_LINKS_LOAD_ANY_BODY) != 0);
        if (out_count) *out_count = static_cast<uint32_t>(count);
    });
}

}  // extern "C"
