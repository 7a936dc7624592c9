// Whole files read and written, with the failures a host can act on: a missing file is NotFound,
// a failed read or write Io, each naming the path and the reason.
//
// Only regular files (and, for reading, pipes) are files here: a device, a socket or a directory at
// the path is refused with Io before anything is read or written. A device could be read for ever
// (/dev/zero) and replacing one with a regular file would leave the host's /dev/null a file.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "util/function_ref.h"

namespace nl {

// The file's bytes.
std::string read_file_bytes(const std::string& path);
// A file whose header says how long it is: reads `header_bytes` (fewer if it ends first), then up to
// the length that `declared(header)` gives for the whole file (0 for a header not of the format: the
// header alone is returned, for its parser to refuse). A length over `max_bytes` is refused with Parse
// (`what` names the format) before anything more is read, and so is a file that goes on past its
// length, reading one byte more at most: a stream that never ends is not read to the end of memory.
// A file that ends before is returned short, for its parser to say so. A pipe is read as its writer
// writes: the call returns once the writer has closed it or written past the length.
std::string read_file_bytes_up_to_declared(const std::string& path, size_t header_bytes, uint64_t max_bytes,
                                           FunctionRef<uint64_t(std::string_view header)> declared, const char* what);
// Writes `bytes` to `path` whole or not at all: into a file beside it, then renamed over it, so a
// failure never leaves a half-written file where a good one was. A symbolic link at `path` stays: the
// file it leads to (through any chain of links) is the one written.
void write_file_bytes(const std::string& path, std::string_view bytes);

}  // namespace nl
