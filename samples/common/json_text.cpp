#include "json_text.h"

#include <cstdio>
#include <cstdlib>

#include "sample_error.h"

namespace nl::samples {
namespace {

// What nlohmann says is wrong, without its "[json.exception.parse_error.101] parse error at line 1,
// column 12: syntax error while parsing value - " preamble.
std::string reason_of(const nlohmann::json::parse_error& e) {
    std::string what = e.what();
    if (const size_t column = what.find(", column "); column != std::string::npos) {
        if (const size_t colon = what.find(": ", column); colon != std::string::npos) what.erase(0, colon + 2);
    }
    if (what.rfind("syntax error while parsing ", 0) == 0) {
        if (const size_t dash = what.find(" - "); dash != std::string::npos) what.erase(0, dash + 3);
    }
    return what;
}

}  // namespace

nlohmann::json parse_json_text(const std::string& text, const std::string& source) {
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        // e.byte counts from 1 and points at the character that could not be read.
        size_t line = 1, column = 1;
        for (size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
            if (text[i] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        throw SampleError(source + ":" + std::to_string(line) + ":" + std::to_string(column) +
                          ": not valid JSON: " + reason_of(e));
    }
}

std::string shortest_float(float value) {
    char text[32];
    for (int digits = 1; digits <= 9; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, static_cast<double>(value));
        if (std::strtof(text, nullptr) == value) break;
    }
    return text;
}

}  // namespace nl::samples
