#include "io/obj_reader.h"

#include <tiny_obj_loader.h>

#include "io/file_bytes.h"
#include "io/obj_records.h"
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

// The file is read here, so a missing file is NotFound and a failed read Io (not a parse error of
// what was read before it failed), and .mtl files the level names are never opened.
TriangleMesh read_obj_file(const std::string& path) { return read_obj_text(read_file_bytes(path), path); }

TriangleMesh read_obj_text(std::string_view text, const std::string& name) {
    // A binary file would otherwise come out as "no faces"; no OBJ text holds a NUL byte.
    if (const size_t nul = text.find('\0'); nul != std::string_view::npos)
        fail(ErrorCode::Parse, name, ": not a text file (a NUL byte at offset ", nul, "): an OBJ file is text");
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(checked_obj_records(text, name), std::string(), config()))
        fail(ErrorCode::Parse, name, ": ", first_line(reader.Error()));
    return to_triangle_mesh(reader, name);
}

}  // namespace nl
