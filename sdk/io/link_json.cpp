#include "io/link_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "io/json_input.h"
#include "level/level_hash.h"
#include "level/mesh_validation.h"
#include "util/error.h"
#include "util/excerpt.h"
#include "util/shortest_decimal.h"

namespace nl {
namespace {

using Json = nlohmann::json;

uint64_t parse_hex_hash(const Json& value) {
    const std::string text = value.is_string() ? value.get<std::string>() : std::string();
    if (text.size() != 16 || text.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
        fail(ErrorCode::InvalidArgument, "links JSON.made_for.level_hash must be a string of 16 hex digits");
    return std::stoull(text, nullptr, 16);
}

Json point(const Vec3& v) { return Json::array({v.x(), v.y(), v.z()}); }

// A double beyond float's range does not convert to a float (undefined behaviour), so every number
// read as a float is checked first.
bool within_float_range(const Json& value) {
    return value.is_number() && std::fabs(value.get<double>()) <= std::numeric_limits<float>::max();
}

// Reads fields with their path in every message.
class Reader {
public:
    Reader(const Json& object, std::string path) : object_(object), path_(std::move(path)) {
        if (!object_.is_object()) fail(ErrorCode::InvalidArgument, path_, " is not a JSON object");
    }

    const Json* find(const char* key) const {
        const auto it = object_.find(key);
        return it == object_.end() ? nullptr : &*it;
    }
    const Json& at(const char* key) const {
        const Json* value = find(key);
        if (!value) fail(ErrorCode::InvalidArgument, path_, ".", key, " is missing");
        return *value;
    }
    float number(const char* key, float fallback, bool required = false) const {
        const Json* value = required ? &at(key) : find(key);
        if (!value) return fallback;
        if (!within_float_range(*value))
            fail(ErrorCode::InvalidArgument, path_, ".", key, " must be a finite number within float range");
        return value->get<float>();
    }
    bool flag(const char* key, bool fallback) const {
        const Json* value = find(key);
        if (!value) return fallback;
        if (!value->is_boolean()) fail(ErrorCode::InvalidArgument, path_, ".", key, " must be true or false");
        return value->get<bool>();
    }
    uint64_t whole(const char* key, uint64_t fallback) const {
        const Json* value = find(key);
        if (!value) return fallback;
        if (!value->is_number_unsigned())
            fail(ErrorCode::InvalidArgument, path_, ".", key, " must be a whole number >= 0");
        return value->get<uint64_t>();
    }
    Vec3 point(const char* key, bool required) const {
        const Json* value = required ? &at(key) : find(key);
        if (!value) return Vec3::Zero();
        if (!value->is_array() || value->size() != 3)
            fail(ErrorCode::InvalidArgument, path_, ".", key, " must be an array of 3 numbers");
        Vec3 v;
        for (int k = 0; k < 3; ++k) {
            if (!(*value)[k].is_number() || !(std::fabs((*value)[k].get<double>()) <= kCoordinateLimit))
                fail(ErrorCode::InvalidArgument, path_, ".", key, "[", k,
                     "] must be a number within the coordinate limit");
            v[k] = (*value)[k].get<float>();
        }
        if (!within_coordinate_limit(v))
            fail(ErrorCode::InvalidArgument, path_, ".", key, " is not finite or beyond the coordinate limit");
        return v;
    }
    const std::string& path() const { return path_; }

private:
    const Json& object_;
    std::string path_;
};

LinkKind kind_from(const Json& value, const std::string& path) {
    if (value.is_string()) {
        const std::string name = value.get<std::string>();
        if (name == "jump") return LinkKind::Jump;
        if (name == "drop") return LinkKind::Drop;
        if (name == "manual") return LinkKind::Manual;
    } else if (value.is_number_unsigned() && value.get<uint64_t>() >= uint64_t(LinkKind::FirstPluginKind) &&
               value.get<uint64_t>() <= UINT32_MAX) {
        return static_cast<LinkKind>(value.get<uint32_t>());
    }
    fail(ErrorCode::InvalidArgument, path,
         ".kind must be \"jump\", \"drop\", \"manual\" or a plugin kind number >= 256");
}

}  // namespace

const char* link_kind_name(LinkKind kind) {
    switch (kind) {
        case LinkKind::Jump: return "jump";
        case LinkKind::Drop: return "drop";
        case LinkKind::Manual: return "manual";
        default: return "plugin";
    }
}

std::string links_to_json(const std::vector<Link>& links, const LinksFileProvenance* made_for) {
    Json list = Json::array();
    for (size_t i = 0; i < links.size(); ++i) {
        const Link& l = links[i];
        // Its landing navmesh's id means nothing in another run: saving it would lose where it leads.
        if (l.crosses())
            fail(ErrorCode::InvalidArgument, "link ", i,
                 " leads to another navmesh (a cross link): links files hold the "
                 "links within one navmesh; add cross links again after loading");
        Json kind = l.kind < LinkKind::FirstPluginKind ? Json(link_kind_name(l.kind)) : Json(uint32_t(l.kind));
        list.push_back({{"kind", kind},
                        {"start", point(l.start)},
                        {"end", point(l.end)},
                        {"apex", point(l.apex)},
                        {"bidirectional", l.bidirectional},
                        {"cost_modifier", l.cost_modifier},
                        {"generated", l.generated},
                        {"enabled", l.enabled},
                        {"user_data", l.user_data},
                        {"start_polygon", l.start_polygon},
                        {"end_polygon", l.end_polygon},
                        {"requires",
                         {{"gap", l.requirements.gap},
                          {"length", l.requirements.length},
                          {"rise", l.requirements.rise},
                          {"drop", l.requirements.drop},
                          {"clearance_width", l.requirements.clearance_width},
                          {"abilities", l.requirements.abilities}}}});
    }
    Json file = {{"format", "navlink-links"}, {"version", kLinkFileVersion}};
    if (made_for) {
        const AgentType& a = made_for->agent_type;
        file["made_for"] = {
            {"agent",
             {{"radius", a.radius}, {"height", a.height}, {"max_climb", a.max_climb}, {"max_slope", a.max_slope}}},
            {"link_settings", recorded_json(made_for->made_with.settings)},
            {"link_plugins", recorded_json(made_for->made_with.plugins)}};
        if (made_for->level_hash != 0) file["made_for"]["level_hash"] = level_hash_text(made_for->level_hash);
    }
    file["links"] = std::move(list);
    return file.dump(1);
}

LinksFile read_links_json(std::string_view text) {
    const Json document = parse_json(text, "links JSON");
    const Reader top(document, "links JSON");
    const Json& format = top.at("format");
    if (!format.is_string() || format.get<std::string>() != "navlink-links")
        fail(ErrorCode::VersionMismatch, "links JSON: format is not \"navlink-links\"");
    const uint64_t version = top.whole("version", 0);
    if (version != uint64_t(kLinkFileVersion))
        fail(ErrorCode::VersionMismatch, "links JSON: version ", version, " is not supported (this library reads ",
             kLinkFileVersion, ")");
    const Json& list = top.at("links");
    if (!list.is_array()) fail(ErrorCode::InvalidArgument, "links JSON: links must be an array");

    LinksFile file;
    std::vector<Link>& links = file.links;
    if (const Json* made_for = top.find("made_for")) {
        const Reader m(*made_for, "links JSON.made_for");
        const Reader a(m.at("agent"), "links JSON.made_for.agent");
        LinksFileProvenance record;
        record.agent_type.radius = a.number("radius", 0.0f);
        record.agent_type.height = a.number("height", 0.0f);
        record.agent_type.max_climb = a.number("max_climb", 0.0f);
        record.agent_type.max_slope = a.number("max_slope", 0.0f);
        if (const Json* settings = m.find("link_settings"); settings && !settings->is_null()) {
            LinkSettings checked;
            apply_settings_json(settings->dump(), checked);
            record.made_with.settings = link_settings_to_json(checked);
        }
        if (const Json* plugins = m.find("link_plugins"); plugins && !plugins->is_null()) {
            if (!plugins->is_object())
                fail(ErrorCode::InvalidArgument, "links JSON.made_for.link_plugins must be an object or null");
            record.made_with.plugins = plugins->dump();
        }
        if (const Json* hash = m.find("level_hash"); hash && !hash->is_null())
            record.level_hash = parse_hex_hash(*hash);
        file.made_for = record;
    }
    for (size_t i = 0; i < list.size(); ++i) {
        const Reader r(list[i], "links[" + std::to_string(i) + "]");
        Link l;
        l.kind = kind_from(r.at("kind"), r.path());
        l.start = r.point("start", true);
        l.end = r.point("end", true);
        l.apex = r.find("apex") ? r.point("apex", true) : higher_end(l);
        l.bidirectional = r.flag("bidirectional", false);
        l.cost_modifier = r.number("cost_modifier", 1.0f);
        if (l.cost_modifier < 0.0f) fail(ErrorCode::InvalidArgument, r.path(), ".cost_modifier must be >= 0");
        l.generated = r.flag("generated", false);
        l.enabled = r.flag("enabled", true);
        l.user_data = r.whole("user_data", 0);
        // The navmesh's polygons under the ends when saved; the loader checks they still fit.
        l.start_polygon = static_cast<uint32_t>(std::min<uint64_t>(r.whole("start_polygon", UINT32_MAX), UINT32_MAX));
        l.end_polygon = static_cast<uint32_t>(std::min<uint64_t>(r.whole("end_polygon", UINT32_MAX), UINT32_MAX));
        // Without "requires", the link asks what its ends measure; with it, what it says (a file
        // from before "length" existed gets the ends' length).
        set_requirements_from_ends(l);
        if (const Json* requirements = r.find("requires")) {
            const Reader q(*requirements, r.path() + ".requires");
            l.requirements.gap = q.number("gap", 0.0f);
            l.requirements.length = q.number("length", l.requirements.length);
            l.requirements.rise = q.number("rise", 0.0f);
            l.requirements.drop = q.number("drop", 0.0f);
            l.requirements.clearance_width = q.number("clearance_width", 0.0f);
            l.requirements.abilities = q.whole("abilities", 0);
            if (l.requirements.gap < 0 || l.requirements.length < 0 || l.requirements.rise < 0 ||
                l.requirements.drop < 0 || l.requirements.clearance_width < 0)
                fail(ErrorCode::InvalidArgument, r.path(), ".requires: distances must be >= 0");
        }
        links.push_back(l);
    }
    return file;
}

std::string link_settings_to_json(const LinkSettings& s) {
    Json out = Json::object();
    for (const NamedFloatSetting& f : kFloatSettings) out[f.name] = shortest_decimal(s.*f.field);
    for (const NamedWholeSetting& w : kWholeSettings) out[w.name] = s.*w.field;
    Json angles = Json::array();
    for (float a : s.drop_angles) angles.push_back(shortest_decimal(a));
    out["drop_angles"] = angles;
    return out.dump();
}

void apply_settings_json(std::string_view text, LinkSettings& s) {
    const Json document = parse_json(text, "settings JSON");
    const Reader r(document, "settings");

    for (const auto& [key, value] : document.items()) {
        bool known = false;
        for (const NamedFloatSetting& f : kFloatSettings) {
            if (known || key != f.name) continue;
            s.*f.field = r.number(f.name, 0.0f, true);
            known = true;
        }
        for (const NamedWholeSetting& w : kWholeSettings) {
            if (known || key != w.name) continue;
            const uint64_t v = r.whole(w.name, 0);
            if (v > 100000) fail(ErrorCode::InvalidArgument, "settings.", key, " is too large");
            s.*w.field = static_cast<unsigned>(v);
            known = true;
        }
        if (!known && key == "drop_angles") {
            if (!value.is_array()) fail(ErrorCode::InvalidArgument, "settings.drop_angles must be an array of numbers");
            s.drop_angles.clear();
            for (size_t i = 0; i < value.size(); ++i) {
                if (!within_float_range(value[i]))
                    fail(ErrorCode::InvalidArgument, "settings.drop_angles[", i,
                         "] must be a number within float range");
                s.drop_angles.push_back(value[i].get<float>());
            }
            known = true;
        }
        if (!known)
            fail(ErrorCode::InvalidArgument, "settings: ", quoted_excerpt(key), " is not a link generation setting");
    }
    naming_fields("settings.", [&] { validate(s); });
}

}  // namespace nl
