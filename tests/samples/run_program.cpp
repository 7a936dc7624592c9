#include "run_program.h"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace nl::test {
namespace {

std::string quoted(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

}  // namespace

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void write_file(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

ProgramRun run_program(const std::vector<std::string>& args, const std::string& work_dir,
                       const std::vector<std::string>& env) {
    static int counter = 0;
    const std::string base = work_dir + "/.run" + std::to_string(++counter);
    std::string command = "cd " + quoted(work_dir) + " && env";
    for (const std::string& e : env) command += " " + quoted(e);
    for (const std::string& a : args) command += " " + quoted(a);
    command += " > " + quoted(base + ".out") + " 2> " + quoted(base + ".err") + " < /dev/null";
    const int status = std::system(command.c_str());
    ProgramRun run;
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = read_file(base + ".out");
    run.err = read_file(base + ".err");
    return run;
}

}  // namespace nl::test
