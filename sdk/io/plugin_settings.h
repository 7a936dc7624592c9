// Settings for the link-kind plugins of one generation: for each kind name, the JSON object given
// under it (as text, handed to the plugin as it is).
#pragma once

#include <map>
#include <string>
#include <string_view>

namespace nl {

using PluginSettings = std::map<std::string, std::string>;

// Reads a JSON object whose members are objects, one per kind name; empty text gives no settings.
// Throws Parse for malformed JSON, InvalidArgument about the field "plugin_settings_json" (fail_field)
// for anything but an object of objects.
PluginSettings plugin_settings_from_json(std::string_view text);

}  // namespace nl
