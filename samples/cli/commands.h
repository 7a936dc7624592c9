// The navlink commands. Each takes the whole argv (argv[1] is the command's name) and returns the
// exit status; failures throw nl::samples::SampleError, which main turns into one line and status 2.
#pragma once

namespace nl::cli {

int run_generate(int argc, char** argv);
int run_bake(int argc, char** argv);
int run_info(int argc, char** argv);
int run_path(int argc, char** argv);
int run_demo(int argc, char** argv);
int run_simulate(int argc, char** argv);
int run_level(int argc, char** argv);

}  // namespace nl::cli
