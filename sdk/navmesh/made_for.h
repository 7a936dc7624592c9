// What a navmesh and its links were made for and with, kept beside them in the world and saved with
// them, so that a baked file says what it was baked for (navlink info, nl_navmesh_load).
#pragma once

#include <cstdint>
#include <string>

namespace nl {

struct MadeFor {
    std::string builder;           // the builder plugin's name; empty: polygons handed over by the host
    std::string builder_settings;  // the settings the builder was given, as JSON text; empty: its defaults
    uint64_t level_hash = 0;       // of the triangles it was built from (level_hash.h); 0: not built from the level
    std::string link_settings;     // the link generation settings of its generated links, as JSON; empty: none
};

}  // namespace nl
