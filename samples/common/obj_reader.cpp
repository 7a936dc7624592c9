#include "obj_reader.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "sample_error.h"
#include "text_file.h"

namespace nl::samples {
namespace {

[[noreturn]] void malformed(const std::string& name, size_t line, const std::string& why) {
    throw SampleError(name + ":" + std::to_string(line) + ": " + why);
}

// The vertex index of a face corner "v", "v/vt", "v//vn" or "v/vt/vn", made 0-based.
uint32_t corner_index(const std::string& token, uint32_t vertex_count, const std::string& name, size_t line) {
    const std::string first = token.substr(0, token.find('/'));
    char* end = nullptr;
    const long value = std::strtol(first.c_str(), &end, 10);
    if (first.empty() || *end != '\0') malformed(name, line, "face corner '" + token + "' is not a vertex index");
    const long index = value > 0 ? value - 1 : static_cast<long>(vertex_count) + value;  // negative: relative
    if (value == 0 || index < 0 || index >= static_cast<long>(vertex_count))
        malformed(name, line,
                  "face corner '" + token + "' refers to no vertex (" + std::to_string(vertex_count) + " so far)");
    return static_cast<uint32_t>(index);
}

}  // namespace

std::vector<uint32_t> ObjPolygons::fan_triangles() const {
    std::vector<uint32_t> out;
    size_t first = 0;
    for (uint8_t count : corner_counts) {
        for (uint32_t k = 1; k + 1 < count; ++k) {
            out.push_back(indices[first]);
            out.push_back(indices[first + k]);
            out.push_back(indices[first + k + 1]);
        }
        first += count;
    }
    return out;
}

ObjPolygons parse_obj(const std::string& text, const std::string& name, uint32_t max_corners) {
    ObjPolygons obj;
    std::istringstream lines(text);
    std::string line;
    size_t number = 0;
    while (std::getline(lines, line)) {
        ++number;
        std::istringstream words(line);
        std::string keyword;
        if (!(words >> keyword)) continue;
        if (keyword == "v") {
            float xyz[3];
            for (float& c : xyz) {
                std::string token;
                char* end = nullptr;
                if (!(words >> token)) malformed(name, number, "a vertex needs three coordinates");
                c = std::strtof(token.c_str(), &end);
                if (*end != '\0' || !std::isfinite(c))
                    malformed(name, number, "'" + token + "' is not a finite number");
            }
            obj.positions.insert(obj.positions.end(), xyz, xyz + 3);
        } else if (keyword == "f") {
            std::string token;
            uint32_t count = 0;
            while (words >> token) {
                obj.indices.push_back(corner_index(token, obj.vertex_count(), name, number));
                ++count;
            }
            if (count < 3) malformed(name, number, "a face needs at least three corners");
            if (count > max_corners)
                malformed(
                    name, number,
                    "a face has " + std::to_string(count) + " corners (at most " + std::to_string(max_corners) + ")");
            obj.corner_counts.push_back(static_cast<uint8_t>(count));
        }
    }
    if (obj.corner_counts.empty()) throw SampleError(name + ": no faces");
    return obj;
}

ObjPolygons read_obj_file(const std::string& path, uint32_t max_corners) {
    return parse_obj(read_text_file(path), path, max_corners);
}

}  // namespace nl::samples
