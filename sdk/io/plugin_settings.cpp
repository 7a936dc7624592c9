#include "io/plugin_settings.h"

#include "io/json_input.h"
#include "util/error.h"
#include "util/excerpt.h"

namespace nl {

PluginSettings plugin_settings_from_json(std::string_view text) {
    PluginSettings out;
    if (text.empty()) return out;
    nlohmann::json all;
    try {
        all = parse_json(text, "plugin_settings_json");
    } catch (const Error& e) {
        throw Error(e.code(), e.what(), true);  // its messages start with the name given
    }
    if (!all.is_object()) fail_field(ErrorCode::InvalidArgument, "plugin_settings_json must be a JSON object");
    for (const auto& [kind_name, own] : all.items()) {
        if (!own.is_object())
            fail_field(ErrorCode::InvalidArgument, "plugin_settings_json: ", quoted_excerpt(kind_name),
                       " must be a JSON object (a plugin's settings), not ", json_excerpt(own));
        out.emplace(kind_name, own.dump());
    }
    return out;
}

}  // namespace nl
