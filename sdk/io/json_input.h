// The one way the library reads JSON it is handed (links, link settings, plugin settings, the Recast
// builder's settings), so every input has the same depth limit and its refusals the same shape.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace nl {

// nlohmann::json's dump, copy and comparison recurse once per level, so a document nested deep enough
// overflows the stack when one of them meets it. NavLink's own documents nest at most 4 levels (a
// links file); a plugin's settings, an object inside plugin_settings_json, may use 62 more.
constexpr int kMaxJsonDepth = 64;

// Parses `text`. Throws Parse for malformed JSON (the byte and the parser's reason), and
// InvalidArgument for a value nested deeper than kMaxJsonDepth or a number beyond a double's range,
// naming the value's path ("links[3].start[1]"). `what` names the input in every message.
nlohmann::json parse_json(std::string_view text, const std::string& what);

// A recorded JSON text (what a navmesh was made with) as JSON: the value it holds, read as parse_json
// reads (a file may say anything), the text itself when it is not JSON, or null when it is empty.
nlohmann::json recorded_json(const std::string& text);

// A short rendering of `value` for a message: a scalar as written (a long string cut short), an array
// or object as its kind and size, so a huge or deep value never lands in a message. (Keys: quoted_excerpt.)
std::string json_excerpt(const nlohmann::json& value);

}  // namespace nl
