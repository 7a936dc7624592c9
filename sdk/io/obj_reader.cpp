#include "io/obj_reader.h"

#include <tiny_obj_loader.h>

#include <fstream>
#include <sstream>

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
    std::ifstream file(path, std::ios::binary);
    if (!file) fail(ErrorCode::NotFound, "cannot open '", path, "'");
    std::ostringstream bytes;
    bytes << file.rdbuf();
    if (file.bad()) fail(ErrorCode::Io, "cannot read '", path, "'");
    return read_obj_text(bytes.str(), path);
}

TriangleMesh read_obj_text(std::string_view text, const std::string& name) {
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
