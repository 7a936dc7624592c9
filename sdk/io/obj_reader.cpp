#include "io/obj_reader.h"

#include <tiny_obj_loader.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

#include "util/error.h"

namespace nl {
namespace {

std::string first_line(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    return line.empty() ? std::string("unknown error") : line;
}

TriangleMesh to_triangle_mesh(const tinyobj::ObjReader& reader, const std::string& name) {
    const auto& positions = reader.GetAttrib().vertices;
    TriangleMesh mesh;
    mesh.vertices.reserve(positions.size() / 3);
    for (size_t i = 0; i + 2 < positions.size(); i += 3) {
        mesh.vertices.emplace_back(positions[i], positions[i + 1], positions[i + 2]);
    }
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const auto& indices = shape.mesh.indices;
        size_t offset = 0;
        for (const unsigned int corner_count : shape.mesh.num_face_vertices) {
            if (offset + corner_count > indices.size())
                fail(ErrorCode::Parse, name, ": face list is inconsistent in shape '", shape.name, "'");
            for (unsigned int k = 0; k < corner_count; ++k) {
                if (indices[offset + k].vertex_index < 0)
                    fail(ErrorCode::Parse, name, ": a face in shape '", shape.name,
                         "' refers to a vertex before the first one");
            }
            for (unsigned int k = 1; k + 1 < corner_count; ++k) {
                mesh.triangles.push_back({static_cast<uint32_t>(indices[offset].vertex_index),
                                          static_cast<uint32_t>(indices[offset + k].vertex_index),
                                          static_cast<uint32_t>(indices[offset + k + 1].vertex_index)});
            }
            offset += corner_count;
        }
    }
    if (mesh.triangles.empty()) fail(ErrorCode::Parse, name, ": no faces");
    return mesh;
}

std::vector<std::string_view> tokens_of(std::string_view line) {
    std::vector<std::string_view> out;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        const size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

bool parse_finite_float(std::string_view token) {
    float value = 0.0f;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return ec == std::errc() && end == token.data() + token.size() && std::isfinite(value);
}

// tinyobjloader reads what it cannot parse as 0 and wraps oversized indices; a level that silently
// gains a vertex at the origin is worse than a refusal, so positions and faces are checked first.
void check_positions_and_faces(std::string_view text, const std::string& name) {
    int64_t vertices = 0;
    size_t line_number = 0;
    size_t begin = 0;
    while (begin <= text.size()) {
        size_t end = text.find('\n', begin);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(begin, end - begin);
        begin = end + 1;
        ++line_number;
        line = line.substr(0, line.find('#'));
        const auto tokens = tokens_of(line);
        if (tokens.empty()) continue;
        if (tokens[0] == "v") {
            if (tokens.size() < 4) fail(ErrorCode::Parse, name, ":", line_number, ": a vertex needs x y z");
            for (size_t k = 1; k < tokens.size() && k <= 4; ++k) {
                if (!parse_finite_float(tokens[k]))
                    fail(ErrorCode::Parse, name, ":", line_number, ": '", tokens[k], "' is not a finite number");
            }
            ++vertices;
        } else if (tokens[0] == "f") {
            if (tokens.size() < 4) fail(ErrorCode::Parse, name, ":", line_number, ": a face needs 3 vertices or more");
            for (size_t k = 1; k < tokens.size(); ++k) {
                const std::string_view position = tokens[k].substr(0, tokens[k].find('/'));
                int64_t index = 0;
                const auto [at, ec] = std::from_chars(position.data(), position.data() + position.size(), index);
                if (ec != std::errc() || at != position.data() + position.size())
                    fail(ErrorCode::Parse, name, ":", line_number, ": '", tokens[k], "' is not a vertex index");
                // Positive indices may point forward (to vertices listed later); negative ones are
                // relative to the vertices so far.
                if (index == 0 || index < -vertices || index > std::numeric_limits<int32_t>::max())
                    fail(ErrorCode::Parse, name, ":", line_number, ": vertex index ", index, " is out of range");
            }
        }
        if (end == text.size()) break;
    }
}

tinyobj::ObjReaderConfig config() {
    tinyobj::ObjReaderConfig c;
    c.triangulate = false;  // we fan-triangulate ourselves, as the levels' authors did
    c.vertex_color = false;
    return c;
}

}  // namespace

TriangleMesh read_obj_file(const std::string& path) {
    // Read the bytes ourselves so a missing file is NotFound, not a parse error, and .mtl files
    // referenced by the level are never opened.
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) fail(ErrorCode::NotFound, "cannot open '", path, "': no such file");
    if (std::filesystem::is_directory(status)) fail(ErrorCode::Io, "cannot read '", path, "': it is a directory");
    std::ifstream file(path, std::ios::binary);
    if (!file) fail(ErrorCode::Io, "cannot open '", path, "': ", std::strerror(errno));
    std::ostringstream bytes;
    bytes << file.rdbuf();
    if (file.bad()) fail(ErrorCode::Io, "cannot read '", path, "'");
    return read_obj_text(bytes.str(), path);
}

TriangleMesh read_obj_text(std::string_view text, const std::string& name) {
    check_positions_and_faces(text, name);
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(std::string(text), std::string(), config()))
        fail(ErrorCode::Parse, name, ": ", first_line(reader.Error()));
    // tinyobjloader only warns about faces that point past the last vertex; for us it is malformed.
    const std::string& warning = reader.Warning();
    if (const auto at = warning.find("out of bounds"); at != std::string::npos)
        fail(ErrorCode::Parse, name, ": ", first_line(warning.substr(warning.rfind('\n', at) + 1)));
    return to_triangle_mesh(reader, name);
}

}  // namespace nl
