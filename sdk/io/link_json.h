// Links and link settings as JSON (schema in docs/link-generation.md):
//   {"format": "navlink-links", "version": 1, "links": [{"kind": "jump", "start": [x, y, z], ...}]}
#pragma once

#include <string>
#include <optional>
#include <string_view>
#include <vector>

#include "links/link.h"
#include "links/link_settings.h"
#include "navmesh/provenance.h"
#include "navmesh/navmesh.h"

namespace nl {

constexpr int kLinkFileVersion = 1;

// What a links file says its links were made for: the body of the navmesh they were generated on,
// and what the generation ran with (empty when not recorded).
struct LinksFileProvenance {
    AgentType agent_type;
    LinkProvenance made_with;
    uint64_t level_hash = 0;  // of the level the navmesh was built from (level_hash.h); 0: not recorded
};

// A links file: its links, and what they were made for when it says (files written before 0.3 do not).
struct LinksFile {
    std::vector<Link> links;
    std::optional<LinksFileProvenance> made_for;
};

// Throws InvalidArgument for a cross link (Link::crosses): its landing navmesh cannot be named in a file.
// With `made_for`, the file records it ("made_for": {"agent": {...}, "link_settings": {...},
// "link_plugins": {...}, "level_hash": "16 hex digits", when known}).
std::string links_to_json(const std::vector<Link>& links, const LinksFileProvenance* made_for = nullptr);

// Throws Parse (malformed JSON, with the parser's position), VersionMismatch (another format or a
// newer version) or InvalidArgument (a field missing, of the wrong type or out of range, named by its
// path, e.g. "links[3].start[1]").
LinksFile read_links_json(std::string_view text);
// The links alone.
inline std::vector<Link> links_from_json(std::string_view text) { return read_links_json(text).links; }

// Applies the keys of a JSON object to `settings` (keys are LinkSettings' field names; unknown keys
// are refused so a typo is not silently ignored), then validates the result.
void apply_settings_json(std::string_view text, LinkSettings& settings);

// The settings as a JSON object that apply_settings_json reads back to the same settings.
std::string link_settings_to_json(const LinkSettings& settings);

const char* link_kind_name(LinkKind kind);

}  // namespace nl
