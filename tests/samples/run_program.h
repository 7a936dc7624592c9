// Runs a program as a user would from a shell, and captures its exit status, stdout and stderr.
#pragma once

#include <string>
#include <vector>

namespace nl::test {

struct ProgramRun {
    int exit_code = -1;
    std::string out;
    std::string err;
};

// Runs `args` (args[0] is the program) in `work_dir`, with extra environment `env` ("NAME=value").
ProgramRun run_program(const std::vector<std::string>& args, const std::string& work_dir,
                       const std::vector<std::string>& env = {});

std::string read_file(const std::string& path);
void write_file(const std::string& path, const std::string& text);

}  // namespace nl::test
