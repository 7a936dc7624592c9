// Whole files read and written, with the failures a host can act on: a missing file is NotFound,
// a failed read or write Io, each naming the path and the reason.
#pragma once

#include <string>
#include <string_view>

namespace nl {

// The file's bytes.
std::string read_file_bytes(const std::string& path);
// Writes `bytes` to `path` whole or not at all: into a file beside it, then renamed over it, so a
// failure never leaves a half-written file where a good one was.
void write_file_bytes(const std::string& path, std::string_view bytes);

}  // namespace nl
