#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>

#include "entry_guard.h"
#include "host_input.h"
#include "io/json_input.h"
#include "io/link_json.h"
#include "links/link_bakes.h"
#include "util/excerpt.h"
#include "world.h"

using nl::ErrorCode;
using nl::fail;
using nl::capi::deref;
using nl::capi::guarded;
using nl::capi::require;
using nl::capi::to_handle;
using nl::capi::to_id;

namespace {

// The first release ended with the requirements before their length.
constexpr size_t kLinkDefFirstSize = offsetof(nl_link_def, requirements) + offsetof(nl_link_requirements, length);
constexpr size_t kSettingsFirstSize = offsetof(nl_link_settings, plugin_settings_json_length) + sizeof(size_t);
constexpr size_t kReportFirstSize = offsetof(nl_link_generation_report, milliseconds_total) + sizeof(double);
constexpr size_t kMaxDropAngles = sizeof(nl_link_settings::drop_angles) / sizeof(float);
constexpr float kEndReach = 1.0f;  // how far a manual link's end may be from its navmesh

void copy_point(float* out, const nl::Vec3& v) { Eigen::Map<nl::Vec3>{out} = v; }

nl::LinkSettings to_core(const nl_link_settings& c) {
    nl::LinkSettings s;
    s.min_edge_length = c.min_edge_length;
    s.min_group_size = c.min_group_size;
    s.max_group_size = c.max_group_size;
    s.sample_spacing = c.sample_spacing;
    s.falloff_distance = c.falloff_distance;
    s.max_jump_gap = c.max_jump_gap;
    s.min_link_distance = c.min_link_distance;
    s.short_link_distance = c.short_link_distance;
    s.max_jump_up = c.max_jump_up;
    s.jump_arc_height = c.jump_arc_height;
    s.strict_forward_angle = c.strict_forward_angle;
    s.permissive_forward_angle = c.permissive_forward_angle;
    s.strict_incline_angle = c.strict_incline_angle;
    s.permissive_incline_angle = c.permissive_incline_angle;
    s.max_drop_distance = c.max_drop_distance;
    if (c.drop_angle_count > kMaxDropAngles)
        fail(ErrorCode::InvalidArgument, "settings->drop_angle_count is ", c.drop_angle_count, " (at most ", kMaxDropAngles, ")");
    s.drop_angles.assign(c.drop_angles, c.drop_angles + c.drop_angle_count);
    s.drop_steepness = c.drop_steepness;
    s.merge_distance = c.merge_distance;
    s.clearance_margin = c.clearance_margin;
    s.arc_segments = c.arc_segments;
    s.walk_factor = c.walk_factor;
    s.walk_distance = c.walk_distance;
    return s;
}

nl_link_settings to_c(const nl::LinkSettings& s) {
    nl_link_settings c{};
    c.size = sizeof c;
    c.min_edge_length = s.min_edge_length;
    c.min_group_size = s.min_group_size;
    c.max_group_size = s.max_group_size;
    c.sample_spacing = s.sample_spacing;
    c.falloff_distance = s.falloff_distance;
    c.max_jump_gap = s.max_jump_gap;
    c.min_link_distance = s.min_link_distance;
    c.short_link_distance = s.short_link_distance;
    c.max_jump_up = s.max_jump_up;
    c.jump_arc_height = s.jump_arc_height;
    c.strict_forward_angle = s.strict_forward_angle;
    c.permissive_forward_angle = s.permissive_forward_angle;
    c.strict_incline_angle = s.strict_incline_angle;
    c.permissive_incline_angle = s.permissive_incline_angle;
    c.max_drop_distance = s.max_drop_distance;
    c.drop_angle_count = static_cast<uint32_t>(std::min(s.drop_angles.size(), kMaxDropAngles));
    std::copy_n(s.drop_angles.begin(), c.drop_angle_count, c.drop_angles);
    c.drop_steepness = s.drop_steepness;
    c.merge_distance = s.merge_distance;
    c.clearance_margin = s.clearance_margin;
    c.arc_segments = s.arc_segments;
    c.walk_factor = s.walk_factor;
    c.walk_distance = s.walk_distance;
    return c;
}

nl_link to_c(const nl::StoredLink& stored, nl::Handle navmesh) {
    const nl::Link& l = stored.link;
    nl_link c{};
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
    return c;
}

nl::Vec3 read_end(const float* p, const char* name) { return nl::capi::read_position(p, "def->", name); }

// A host's link def as a core link on `mesh`: both ends must be near the navmesh.
// Requirements left all zero are the ends' own (a manual link between two points asks for its gap,
// rise and drop), and a length left zero is the ends' distance: the same for nl_link_add and a JSON
// load.
void requirements_from_ends_if_unset(nl::Link& l) {
    nl::LinkRequirements& r = l.requirements;
    if (r.gap == 0.0f && r.rise == 0.0f && r.drop == 0.0f) nl::set_requirements_from_ends(l);
    if (r.length == 0.0f) r.length = nl::Vec3(l.end.x() - l.start.x(), 0.0f, l.end.z() - l.start.z()).norm();
}

// The polygon nearest a link end within kEndReach; INVALID_ARGUMENT naming the end otherwise.
uint32_t polygon_near(const nl::NavMesh& mesh, const nl::Vec3& p, const std::string& name) {
    const nl::NavPoint near = mesh.find_nearest(p, nl::Vec3::Constant(kEndReach));
    if (!near.found || near.distance > kEndReach)
        fail(ErrorCode::InvalidArgument, name, " is not within ", kEndReach, " m of the navmesh");
    return near.polygon;
}

nl::Link link_from_def(const nl_link_def& in, const nl::NavMesh& mesh) {
    const nl_link_def def = nl::capi::read_growable(in, nl_default_link_def(), kLinkDefFirstSize, "def");
    const nl::LinkKind kind = static_cast<nl::LinkKind>(def.kind);
    if (kind != nl::LinkKind::Jump && kind != nl::LinkKind::Drop && kind != nl::LinkKind::Manual &&
        def.kind < NL_LINK_FIRST_PLUGIN_KIND)
        fail(ErrorCode::InvalidArgument, "def->kind is ", def.kind, " (NL_LINK_* or a plugin kind >= 256)");
    nl::capi::read_amount(def.cost_modifier, "def->cost_modifier");
    const nl_link_requirements& r = def.requirements;
    for (const auto& [value, name] : {std::pair{r.gap, "gap"}, std::pair{r.rise, "rise"}, std::pair{r.drop, "drop"},
                                      std::pair{r.clearance_width, "clearance_width"}, std::pair{r.length, "length"}})
        nl::capi::read_amount(value, "def->requirements.", name);

    nl::Link l;
    l.kind = kind;
    l.start = read_end(def.start, "start");
    l.end = read_end(def.end, "end");
    l.apex = l.start.y() > l.end.y() ? l.start : l.end;
    l.bidirectional = def.bidirectional != 0;
    l.enabled = def.enabled != 0;
    l.cost_modifier = def.cost_modifier;
    l.user_data = def.user_data;
    l.requirements.gap = r.gap;
    l.requirements.length = r.length;
    l.requirements.rise = r.rise;
    l.requirements.drop = r.drop;
    l.requirements.clearance_width = r.clearance_width;
    l.requirements.abilities = r.abilities;
    requirements_from_ends_if_unset(l);
    l.start_polygon = polygon_near(mesh, l.start, "def->start");
    l.end_polygon = polygon_near(mesh, l.end, "def->end");
    return l;
}

nl_link_generation_report to_c(const nl::LinkGenerationReport& r) {
    nl_link_generation_report c{};
    c.size = sizeof c;
    c.edges = r.edges;
    c.groups = r.groups;
    c.samples = r.samples;
    c.takeoff_points = r.takeoff_points;
    c.jump_candidates = r.jump_candidates;
    c.drop_candidates = r.drop_candidates;
    c.jump_links = r.jump_links;
    c.drop_links = r.drop_links;
    c.plugin_links = r.plugin_links;
    c.rejected_wall = r.rejected_wall;
    c.rejected_not_ledge = r.rejected_not_ledge;
    c.rejected_distance = r.rejected_distance;
    c.rejected_rise = r.rejected_rise;
    c.rejected_angle = r.rejected_angle;
    c.rejected_no_landing = r.rejected_no_landing;
    c.rejected_clearance = r.rejected_clearance;
    c.rejected_duplicate = r.rejected_duplicate;
    c.rays_cast = r.rays_cast;
    c.milliseconds_edges = r.milliseconds_edges;
    c.milliseconds_takeoff = r.milliseconds_takeoff;
    c.milliseconds_jumps = r.milliseconds_jumps;
    c.milliseconds_drops = r.milliseconds_drops;
    c.milliseconds_merge = r.milliseconds_merge;
    c.milliseconds_total = r.milliseconds_total;
    c.box_queries = r.box_queries;
    c.body_tests = r.body_tests;
    c.rejected_walkable = r.rejected_walkable;
    c.rejected_too_shallow = r.rejected_too_shallow;
    c.rejected_too_deep = r.rejected_too_deep;
    return c;
}

// What a link-kind plugin hands back through the sink: its links, validated as manual links are.
struct PluginLinkSink {
    const nl::NavMesh* mesh = nullptr;
    nl_link_kind kind = 0;
    std::vector<nl::Link> links;
    std::string error;
    bool out_of_memory = false;

    static nl_status receive(void* context, const nl_link_def* def) {
        auto& self = *static_cast<PluginLinkSink*>(context);
        try {
            require(def, "link");
            if (def->kind != self.kind)
                fail(ErrorCode::InvalidArgument, "def->kind is ", def->kind, ", not the plugin's kind ", self.kind);
            nl::Link link = link_from_def(*def, *self.mesh);
            link.generated = true;
            self.links.push_back(link);
            return NL_STATUS_SUCCESS;
        } catch (const std::bad_alloc&) {
            self.out_of_memory = true;
            return NL_STATUS_FAILURE | NL_STATUS_OUT_OF_MEMORY;
        } catch (const std::exception& e) {
            if (self.error.empty()) self.error = e.what();
            return NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT;
        }
    }
};

// The plugins' settings, checked before any ray is cast: a JSON object (or none) whose members are
// the objects handed to the plugins, each under its kind name.
nlohmann::json plugin_settings_of(const std::string& text) {
    if (text.empty()) return nlohmann::json::object();
    const nlohmann::json all = nl::parse_json(text, "settings->plugin_settings_json");
    if (!all.is_object()) fail(ErrorCode::InvalidArgument, "settings->plugin_settings_json must be a JSON object");
    for (const auto& [kind_name, own] : all.items()) {
        if (!own.is_object())
            fail(ErrorCode::InvalidArgument, "settings->plugin_settings_json: ", nl::quoted_excerpt(kind_name),
                 " must be a JSON object (a plugin's settings), not ", nl::json_excerpt(own));
    }
    return all;
}

// The links of every loaded link-kind plugin for a navmesh, each plugin given the object under its
// kind name in `all`. Throws Internal naming a plugin that failed.
std::vector<nl::Link> plugin_links(nl_world& w, nl_navmesh_id navmesh, const nl::NavMesh& mesh,
                                   const nlohmann::json& all, uint32_t& count) {
    std::vector<nl::Link> out;
    for (const nl::capi::Plugin* plugin : w.plugins->link_kinds()) {
        const nl_link_kind_provider& provider = plugin->info.link_kind;
        std::string own;
        if (const auto it = all.find(provider.kind_name); it != all.end()) own = it->dump();
        PluginLinkSink sink;
        sink.mesh = &mesh;
        sink.kind = provider.kind;
        nl::capi::take_plugin_error();
        const nl_status status = provider.generate(plugin->info.state, &w.plugins->host(), navmesh,
                                                   own.empty() ? nullptr : own.c_str(), own.size(),
                                                   &PluginLinkSink::receive, &sink);
        const std::string reason = nl::capi::take_plugin_error();
        if (sink.out_of_memory) throw std::bad_alloc();
        if (!sink.error.empty())
            fail(ErrorCode::Internal, "link-kind plugin '", plugin->name, "' proposed a link that was refused: ", sink.error);
        if (NL_FAILED(status))
            throw nl::Error(nl::capi::to_error_code(status),
                            nl::concat("link-kind plugin '", plugin->name, "': ", reason.empty() ? nl_status_string(status) : reason));
        out.insert(out.end(), sink.links.begin(), sink.links.end());
    }
    count = static_cast<uint32_t>(out.size());
    return out;
}

// The host's progress callback as the core's (no callback: never cancel).
auto progress_of(nl_progress_fn* progress, void* user) {
    return [progress, user](float fraction, const char* stage) { return !progress || progress(user, fraction, stage) != 0; };
}

std::vector<nl::Link> links_of(const nl::LinkSnapshot& snapshot) {
    std::vector<nl::Link> out;
    out.reserve(snapshot.size());
    for (const nl::StoredLink& s : snapshot) out.push_back(s.link);
    return out;
}

}  // namespace

extern "C" {

NL_API nl_link_def nl_default_link_def(void) {
    nl_link_def def{};
    def.size = sizeof def;
    def.kind = NL_LINK_MANUAL;
    def.enabled = 1;
    def.cost_modifier = 1.0f;
    return def;
}

NL_API nl_status nl_link_add(nl_world* world, nl_navmesh_id navmesh, const nl_link_def* def, nl_link_id* out_id) {
    return guarded("nl_link_add", world, [&] {
        nl_world& w = deref(world);
        const auto mesh = w.navmeshes->get(to_handle(navmesh));
        require(def, "def");
        require(out_id, "out_id");
        nl::Link link = link_from_def(*def, *mesh);
        link.generated = false;
        *out_id = to_id<nl_link_id>(w.links->add(to_handle(navmesh), link));
    });
}

NL_API nl_status nl_link_update(nl_world* world, nl_link_id link, const nl_link_def* def) {
    return guarded("nl_link_update", world, [&] {
        nl_world& w = deref(world);
        const nl::Handle navmesh = w.links->get(to_handle(link)).first;
        require(def, "def");
        w.links->update(to_handle(link), link_from_def(*def, *w.navmeshes->get(navmesh)));
    });
}

NL_API nl_status nl_link_remove(nl_world* world, nl_link_id link) {
    return guarded("nl_link_remove", world, [&] { deref(world).links->remove(to_handle(link)); });
}

NL_API int32_t nl_link_is_valid(const nl_world* world, nl_link_id link) {
    int32_t valid = 0;
    guarded("nl_link_is_valid", world, [&] { valid = deref(world).links->contains(to_handle(link)) ? 1 : 0; });
    return valid;
}

NL_API nl_status nl_link_get(const nl_world* world, nl_link_id link, nl_link* out_link) {
    return guarded("nl_link_get", world, [&] {
        const auto [navmesh, stored] = deref(world).links->get(to_handle(link));
        require(out_link, "out_link");
        *out_link = to_c(nl::StoredLink{to_handle(link), stored}, navmesh);
    });
}

NL_API nl_status nl_navmesh_get_links(const nl_world* world, nl_navmesh_id navmesh, nl_link* out_links,
                                      uint32_t capacity, uint32_t* out_count) {
    return guarded("nl_navmesh_get_links", world, [&] {
        const nl_world& w = deref(world);
        const nl::Handle mesh = to_handle(navmesh);
        w.navmeshes->get(mesh);  // refuses stale ids
        const auto snapshot = w.links->snapshot(mesh);
        nl::capi::list_into(*snapshot, out_links, capacity, out_count, "out_links",
                            [&](const nl::StoredLink& s) { return to_c(s, mesh); });
    });
}

NL_API nl_status nl_navmesh_remove_generated_links(nl_world* world, nl_navmesh_id navmesh, uint32_t* out_removed) {
    return guarded("nl_navmesh_remove_generated_links", world, [&] {
        nl_world& w = deref(world);
        const nl::Handle handle = to_handle(navmesh);
        w.navmeshes->get(handle);
        uint32_t removed = 0;
        w.generations->forget(handle, [&] { removed = w.links->remove_generated(handle); });
        if (out_removed) *out_removed = removed;
    });
}

NL_API nl_link_settings nl_default_link_settings(void) { return to_c(nl::LinkSettings{}); }

NL_API nl_status nl_link_settings_from_json(const char* json, size_t length, nl_link_settings* settings) {
    return guarded("nl_link_settings_from_json", nullptr, [&] {
        require(settings, "settings");
        if (length > 0) require(json, "json");
        const nl_link_settings given = nl::capi::read_growable(*settings, nl_default_link_settings(), kSettingsFirstSize, "settings");
        nl::LinkSettings s = to_core(given);
        nl::apply_settings_json(std::string_view(json ? json : "", length), s);
        if (s.drop_angles.size() > kMaxDropAngles)
            fail(ErrorCode::InvalidArgument, "settings.drop_angles has more than ", kMaxDropAngles, " entries");
        nl_link_settings out = to_c(s);
        // The plugins' settings are the host's pointer, not the JSON's business.
        out.plugin_settings_json = given.plugin_settings_json;
        out.plugin_settings_json_length = given.plugin_settings_json_length;
        nl::capi::write_growable(settings, out, kSettingsFirstSize, "settings");
    });
}

NL_API nl_status nl_navmesh_generate_links(nl_world* world, nl_navmesh_id navmesh, const nl_link_settings* settings,
                                           nl_progress_fn* progress, void* user, nl_link_generation_report* out_report) {
    return guarded("nl_navmesh_generate_links", world, [&] {
        nl_world& w = deref(world);
        const nl::Handle handle = to_handle(navmesh);
        const auto mesh = w.navmeshes->get(handle);
        // Every field is read from the copy: a caller's struct holds only `size` bytes.
        const nl_link_settings given =
            settings ? nl::capi::read_growable(*settings, nl_default_link_settings(), kSettingsFirstSize, "settings")
                     : nl_default_link_settings();
        const nl::LinkSettings s = to_core(given);
        if (!given.plugin_settings_json && given.plugin_settings_json_length != 0)
            fail(ErrorCode::InvalidArgument, "settings->plugin_settings_json is null but settings->plugin_settings_json_length is ",
                 given.plugin_settings_json_length);
        if (out_report && out_report->size < kReportFirstSize)
            fail(ErrorCode::InvalidArgument, "out_report->size is ", out_report->size, " (set it to sizeof)");
        const std::string plugin_json = given.plugin_settings_json
                                            ? std::string(given.plugin_settings_json, given.plugin_settings_json_length)
                                            : std::string();
        const nlohmann::json plugin_settings = plugin_settings_of(plugin_json);
        auto generation = std::make_shared<nl::LinkGeneration>(mesh, s, nl::GenerationMethod::Indexed);
        const nl::LinkBakes::Turn one_at_a_time = w.generations->take_turn(handle);
        nl::LinkGenerationReport report;
        std::vector<nl::Link> links = generation->run(*w.level, *w.tasks, report, progress_of(progress, user));
        const std::vector<nl::Link> extra = plugin_links(w, navmesh, *mesh, plugin_settings, report.plugin_links);
        links.insert(links.end(), extra.begin(), extra.end());
        w.generations->store(handle, nl::LinkBakes::Entry{std::move(generation), plugin_json}, [&] { w.links->replace_generated(handle, links); });
        if (out_report) nl::capi::write_growable(out_report, to_c(report), kReportFirstSize, "out_report");
    });
}

NL_API nl_status nl_navmesh_update_links_in_box(nl_world* world, nl_navmesh_id navmesh, const float* box_min,
                                                const float* box_max, nl_progress_fn* progress, void* user,
                                                nl_link_generation_report* out_report) {
    return guarded("nl_navmesh_update_links_in_box", world, [&] {
        nl_world& w = deref(world);
        const nl::Handle handle = to_handle(navmesh);
        const auto mesh = w.navmeshes->get(handle);
        require(box_min, "box_min");
        require(box_max, "box_max");
        nl::Aabb box;
        box.min = nl::Vec3(box_min[0], box_min[1], box_min[2]);
        box.max = nl::Vec3(box_max[0], box_max[1], box_max[2]);
        if (!nl::within_coordinate_limit(box.min) || !nl::within_coordinate_limit(box.max) || box.empty())
            fail(ErrorCode::InvalidArgument, "box_min and box_max must be finite, within the limit, and min <= max");
        if (out_report && out_report->size < kReportFirstSize)
            fail(ErrorCode::InvalidArgument, "out_report->size is ", out_report->size, " (set it to sizeof)");
        const nl::LinkBakes::Turn one_at_a_time = w.generations->take_turn(handle);
        // The generation and the plugin settings of the generation being updated, read together.
        const nl::LinkBakes::Entry last = w.generations->get(handle);
        if (!last.generation) fail(ErrorCode::NotFound, "the navmesh has no generation to update (never generated, or its generated links were "
                                      "removed or replaced by a JSON load since): call nl_navmesh_generate_links");
        nl::LinkGenerationReport report;
        std::vector<nl::Link> links = last.generation->update(box, *w.level, *w.tasks, report, progress_of(progress, user));
        const std::vector<nl::Link> extra =
            plugin_links(w, navmesh, *mesh, plugin_settings_of(last.plugin_settings_json), report.plugin_links);
        links.insert(links.end(), extra.begin(), extra.end());
        if (!w.generations->store_if_current(handle, last.generation.get(), [&] { w.links->replace_generated(handle, links); }))
            fail(ErrorCode::NotFound, "the navmesh's generated links were removed or replaced by a JSON load during the update");
        if (out_report) nl::capi::write_growable(out_report, to_c(report), kReportFirstSize, "out_report");
    });
}

NL_API nl_status nl_navmesh_save_links_json(const nl_world* world, nl_navmesh_id navmesh, char* buffer, size_t capacity,
                                            size_t* out_length) {
    return guarded("nl_navmesh_save_links_json", world, [&] {
        const nl_world& w = deref(world);
        w.navmeshes->get(to_handle(navmesh));
        require(out_length, "out_length");
        if (!buffer && capacity > 0) fail(ErrorCode::InvalidArgument, "buffer is null but capacity is ", capacity);
        const std::string json = nl::links_to_json(links_of(*w.links->snapshot(to_handle(navmesh))));
        *out_length = json.size();
        if (!buffer) return;
        if (json.size() >= capacity)
            fail(ErrorCode::BufferTooSmall, "capacity is ", capacity, " but ", json.size() + 1, " bytes are needed");
        std::memcpy(buffer, json.c_str(), json.size() + 1);
    });
}

NL_API nl_status nl_navmesh_load_links_json(nl_world* world, nl_navmesh_id navmesh, const char* json, size_t length,
                                            uint32_t* out_count) {
    return guarded("nl_navmesh_load_links_json", world, [&] {
        nl_world& w = deref(world);
        const nl::Handle handle = to_handle(navmesh);
        const auto mesh = w.navmeshes->get(handle);
        if (length > 0) require(json, "json");
        std::vector<nl::Link> links = nl::links_from_json(std::string_view(json ? json : "", length));
        // The polygons under the ends: the saved ones while they still hold the ends (the file may
        // come from another build of the navmesh), else located again.
        // An end must be as near the navmesh as nl_link_add asks, else the file is refused.
        auto polygon_under = [&](const nl::Vec3& p, uint32_t saved, const std::string& name) {
            if (saved < mesh->polygon_count()) {
                // Seen from above: detail heights may sit a voxel above the polygon's own corners.
                const nl::Vec3 q = mesh->closest_point_on_polygon(saved, p);
                if (nl::Vec3(q.x() - p.x(), 0.0f, q.z() - p.z()).norm() < 0.05f && std::fabs(q.y() - p.y()) < kEndReach)
                    return saved;
            }
            return polygon_near(*mesh, p, name);
        };
        for (size_t i = 0; i < links.size(); ++i) {
            nl::Link& l = links[i];
            const std::string at = "links[" + std::to_string(i) + "]";
            l.start_polygon = polygon_under(l.start, l.start_polygon, at + ".start");
            l.end_polygon = polygon_under(l.end, l.end_polygon, at + ".end");
            requirements_from_ends_if_unset(l);
        }
        // The loaded links are not a generation an update could continue.
        w.generations->forget(handle, [&] { w.links->replace_all(handle, links); });
        if (out_count) *out_count = static_cast<uint32_t>(links.size());
    });
}

}  // extern "C"
