// Outputs checked before the work that fills them: a command that runs for seconds and then cannot
// write its result has wasted them, and one that writes some outputs and fails on the next leaves a
// half-done set.
#pragma once

#include <string>

namespace nl::samples {

// Throws SampleError naming `path` unless a file can be written there now: its folder exists and is
// writable, and `path` is not a folder.
void check_writable_file(const std::string& path);

// Creates the folder `dir` (and its parents) if it is missing; throws SampleError naming it when it
// cannot be made, is a file, or is not writable.
void prepare_output_folder(const std::string& dir);

}  // namespace nl::samples
