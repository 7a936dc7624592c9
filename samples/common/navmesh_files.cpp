#include "navmesh_files.h"

#include <cstring>
#include <fstream>
#include <iterator>

#include "sample_error.h"

namespace nl::samples {
namespace {

std::string file_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SampleError(path + ": cannot open");
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

void save_navmesh_file(nl_world* world, nl_navmesh_id navmesh, const std::string& path) {
    check(nl_navmesh_save_file(world, navmesh, path.c_str()), "saving the navmesh");
}

nl_navmesh_id load_navmesh_file(nl_world* world, const std::string& path) {
    nl_navmesh_id navmesh{};
    check(nl_navmesh_load_file(world, path.c_str(), nullptr, &navmesh), "loading the navmesh");
    return navmesh;
}

NavmeshFileContents describe_navmesh_file(const std::string& path) {
    const std::string bytes = file_bytes(path);
    NavmeshFileContents out;
    std::memset(&out.info, 0, sizeof out.info);
    out.info.size = sizeof out.info;
    size_t length = 0;
    check(nl_navmesh_file_describe(bytes.data(), bytes.size(), &out.info, nullptr, 0, &length), path);
    out.made_for_json.assign(length + 1, '\0');
    check(nl_navmesh_file_describe(bytes.data(), bytes.size(), nullptr, out.made_for_json.data(),
                                   out.made_for_json.size(), &length),
          path);
    out.made_for_json.resize(length);
    return out;
}

bool is_navmesh_file(const std::string& path) {
    static const char kMagic[8] = {'\x89', 'N', 'L', 'N', 'A', 'V', '\r', '\n'};
    std::ifstream in(path, std::ios::binary);
    char head[8] = {};
    return in.read(head, sizeof head) && std::memcmp(head, kMagic, sizeof head) == 0;
}

}  // namespace nl::samples
