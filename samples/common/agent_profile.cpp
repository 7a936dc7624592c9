#include "agent_profile.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

#include "json_text.h"
#include "sample_error.h"
#include "text_file.h"

namespace nl::samples {
namespace {

using Json = nlohmann::json;

// Reads key `key` of `object` into `out` when present: a finite number in [lo, hi] (lo excluded
// when `lo_open`), else a SampleError naming the key.
void read_number(const Json& object, const char* key, float lo, bool lo_open, float hi, const std::string& source,
                 float& out) {
    const auto it = object.find(key);
    if (it == object.end()) return;
    const std::string range = std::string(lo_open ? "> " : ">= ") + shortest_float(lo) +
                              (std::isinf(hi) ? std::string() : " and <= " + shortest_float(hi));
    if (!it->is_number())
        throw SampleError(source + ": " + key + " must be a number " + range + " (got " + it->dump() + ")");
    const double value = it->get<double>();
    if (!std::isfinite(value) || value < lo || (lo_open && value == lo) || value > hi)
        throw SampleError(source + ": " + key + " must be a number " + range + " (got " + it->dump() + ")");
    out = static_cast<float>(value);
}

}  // namespace

AgentProfile default_agent_profile() {
    AgentProfile profile;
    profile.name = "default";
    profile.body = nl_default_agent_type();
    profile.capabilities = nl_agent_capabilities{};  // every field is set below; abilities none
    const nl_link_settings links = nl_default_link_settings();
    profile.capabilities.max_jump_distance = links.max_jump_gap;
    profile.capabilities.max_jump_height = links.max_jump_up;
    profile.capabilities.max_drop_height = links.max_drop_distance;
    profile.capabilities.radius = profile.body.radius;
    return profile;
}

AgentProfile parse_agent_json(const std::string& text, const std::string& source) {
    const Json json = parse_json_text(text, source);
    if (!json.is_object()) throw SampleError(source + ": an agent must be a JSON object");
    static const char* const known[] = {"name",
                                        "radius",
                                        "height",
                                        "max_climb",
                                        "max_slope",
                                        "max_jump_distance",
                                        "max_jump_height",
                                        "max_drop_height",
                                        "abilities"};
    for (const auto& item : json.items()) {
        bool found = false;
        for (const char* k : known) found = found || item.key() == k;
        if (!found) throw SampleError(source + ": unknown key \"" + item.key() + "\" in the agent");
    }
    AgentProfile profile = default_agent_profile();
    profile.name = source;
    if (const auto it = json.find("name"); it != json.end()) {
        if (!it->is_string()) throw SampleError(source + ": name must be a string (got " + it->dump() + ")");
        profile.name = it->get<std::string>();
    }
    const float inf = std::numeric_limits<float>::infinity();
    read_number(json, "radius", 0.0f, true, 100.0f, source, profile.body.radius);
    read_number(json, "height", 0.0f, true, 100.0f, source, profile.body.height);
    read_number(json, "max_climb", 0.0f, false, 100.0f, source, profile.body.max_climb);
    read_number(json, "max_slope", 0.0f, false, 89.9f, source, profile.body.max_slope);
    read_number(json, "max_jump_distance", 0.0f, false, inf, source, profile.capabilities.max_jump_distance);
    read_number(json, "max_jump_height", 0.0f, false, inf, source, profile.capabilities.max_jump_height);
    read_number(json, "max_drop_height", 0.0f, false, inf, source, profile.capabilities.max_drop_height);
    if (const auto it = json.find("abilities"); it != json.end()) {
        if (!it->is_number_unsigned())
            throw SampleError(source + ": abilities must be a whole number >= 0 (ability bits; got " + it->dump() +
                              ")");
        profile.capabilities.abilities = it->get<uint64_t>();
    }
    profile.capabilities.radius = profile.body.radius;
    for (const char* key : {"max_jump_distance", "max_jump_height", "max_drop_height", "abilities"}) {
        if (json.contains(key)) {
            profile.first_capability_key = key;
            break;
        }
    }
    return profile;
}

AgentProfile read_agent_file(const std::string& path) { return parse_agent_json(read_text_file(path), path); }

}  // namespace nl::samples
