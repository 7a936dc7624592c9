// Whole-file reads and writes with one-line errors that name the file.
#pragma once

#include <string>

namespace nl::samples {

// The file's bytes; throws SampleError("cannot open 'PATH': REASON") when it cannot be read.
std::string read_text_file(const std::string& path);

// Writes `text` to `path` (replacing it); throws SampleError naming the file on failure.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace nl::samples
