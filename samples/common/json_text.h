// JSON files the samples read, with errors in the samples' one-line form.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace nl::samples {

// Parses `text` read from `source`; throws SampleError("SOURCE:LINE:COLUMN: not valid JSON: what is
// wrong") where it is malformed (nlohmann's own exception text and id left out).
nlohmann::json parse_json_text(const std::string& text, const std::string& source);

// `value` as the fewest decimal digits that read back as the same float: 89.9, not 89.9000015258789.
std::string shortest_float(float value);

}  // namespace nl::samples
