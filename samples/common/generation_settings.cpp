#include "generation_settings.h"

#include <nlohmann/json.hpp>

#include "json_text.h"
#include "sample_error.h"
#include "text_file.h"

namespace nl::samples {

GenerationSettings& GenerationSettings::operator=(const GenerationSettings& other) {
    links = other.links;
    recast_json = other.recast_json;
    plugins_json = other.plugins_json;
    links.plugin_settings_json = plugins_json.empty() ? nullptr : plugins_json.c_str();
    links.plugin_settings_json_length = plugins_json.size();
    return *this;
}

GenerationSettings parse_generation_settings(const std::string& text, const std::string& source) {
    nlohmann::json json = parse_json_text(text, source);
    if (!json.is_object()) throw SampleError(source + ": settings must be a JSON object");
    GenerationSettings settings;
    for (const char* key : {"recast", "plugins"}) {
        const auto it = json.find(key);
        if (it == json.end()) continue;
        if (!it->is_object())
            throw SampleError(source + ": " + key + " must be a JSON object (got " + it->dump() + ")");
        (std::string(key) == "recast" ? settings.recast_json : settings.plugins_json) = it->dump();
        json.erase(it);
    }
    const std::string links = json.dump();
    check(nl_link_settings_from_json(links.data(), links.size(), &settings.links), source);
    settings.links.plugin_settings_json = settings.plugins_json.empty() ? nullptr : settings.plugins_json.c_str();
    settings.links.plugin_settings_json_length = settings.plugins_json.size();
    return settings;
}

GenerationSettings read_generation_settings_file(const std::string& path) {
    return parse_generation_settings(read_text_file(path), path);
}

std::string with_tile_size(const std::string& recast_json, uint32_t tile_size) {
    nlohmann::json json = recast_json.empty() ? nlohmann::json::object() : nlohmann::json::parse(recast_json);
    json["tile_size"] = tile_size;
    return json.dump();
}

}  // namespace nl::samples
