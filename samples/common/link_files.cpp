#include "link_files.h"

#include "sample_error.h"
#include "text_file.h"

namespace nl::samples {

std::string links_json(nl_world* world, nl_navmesh_id navmesh) {
    size_t length = 0;
    check(nl_navmesh_save_links_json(world, navmesh, nullptr, 0, &length), "saving the links");
    std::string text(length + 1, '\0');
    check(nl_navmesh_save_links_json(world, navmesh, text.data(), text.size(), &length), "saving the links");
    text.resize(length);
    return text;
}

uint32_t load_links_file(nl_world* world, nl_navmesh_id navmesh, const std::string& path, uint32_t flags) {
    const std::string text = read_text_file(path);
    uint32_t count = 0;
    check(nl_navmesh_load_links_json(world, navmesh, text.data(), text.size(), flags, &count), path);
    return count;
}

}  // namespace nl::samples
