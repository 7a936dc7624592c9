#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine and runs every NavLink test (as many at once as there are cores:
# every test is independent of the others): the release build's tests, then the
# same tests under AddressSanitizer + UndefinedBehaviorSanitizer (built with clang, with the libFuzzer
# targets), then each fuzz target for a bounded time, then the stress tests and soaks under
# ThreadSanitizer. Exits non-zero on any failure (a fuzzer's crash included). docs/testing.md.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"

jobs=$(nproc)
# Every compile goes through ccache (CMake reads these for every configure, the install tests' own
# included), so a rerun or a fresh clone of the same sources compiles nothing again; 10 GB holds the
# three builds and the install tests' libraries.
export CMAKE_C_COMPILER_LAUNCHER=ccache CMAKE_CXX_COMPILER_LAUNCHER=ccache CCACHE_MAXSIZE=10G CCACHE_BASEDIR="$root"
# configure_and_build DIR [CMAKE OPTIONS...] [--target TARGET]...: configures and builds everything, or
# only the TARGETs.
configure_and_build() {
  local dir=$1; shift
  local options=() target=()
  while (( $# )); do
    if [[ $1 == --target ]]; then target+=(--target "$2"); shift 2; else options+=("$1"); shift; fi
  done
  cmake -S "$root" -B "$dir" -G Ninja "${options[@]}" > "$dir.configure.log" 2>&1 || { cat "$dir.configure.log"; return 1; }
  cmake --build "$dir" -j "$jobs" "${target[@]}"
}

start=$(date +%s)
echo "== release build and tests (with the C#, Rust and Python binding tests)"
# Both compilers at -Wall -Wextra -Werror: gcc here, clang in the sanitizer build (its warnings do not
# depend on the sanitizers), so no third build is needed for clang's warnings.
configure_and_build "$root/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNAVLINK_BUILD_BINDINGS=ON -DNAVLINK_WERROR=ON \
  -DNAVLINK_UNITY_BUILD=ON
ctest --test-dir "$root/build" --output-on-failure -j "$jobs"

echo "== sanitizer build (address;undefined, clang, with the fuzz targets) and tests"
configure_and_build "$root/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNAVLINK_SANITIZE="address;undefined" \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DNAVLINK_BUILD_FUZZERS=ON -DNAVLINK_WERROR=ON \
  -DNAVLINK_BUILD_BENCHMARKS=OFF -DNAVLINK_INSTALL=OFF -DNAVLINK_UNITY_BUILD=ON
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$root/build-asan" --output-on-failure -LE "no_sanitizer|fuzz" -j "$jobs"

echo "== fuzzing: each target for NAVLINK_FUZZ_SECONDS (50 s) from its seeds, one per core at once"
ctest --test-dir "$root/build-asan" --output-on-failure -L fuzz -j "$jobs"
unset ASAN_OPTIONS UBSAN_OPTIONS

echo "== ThreadSanitizer build: the path queue stress test, the world, agents and moving surfaces soaks and the host task system"
configure_and_build "$root/build-tsan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNAVLINK_SANITIZE=thread \
  -DNAVLINK_BUILD_BENCHMARKS=OFF -DNAVLINK_BUILD_SAMPLES=OFF -DNAVLINK_INSTALL=OFF -DNAVLINK_UNITY_BUILD=ON \
  --target navlink-path-stress --target navlink-world-soak --target navlink-agents-soak \
  --target navlink-surfaces-soak --target navlink-abi-host-tasks-test
# Debian's Embree and TBB are not instrumented: their calls to intercepted functions (malloc, free,
# memcmp) are ignored as their own memory accesses are (docs/architecture.md, "ThreadSanitizer").
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:ignore_noninstrumented_modules=1"
"$root/build-tsan/tests/stress/navlink-path-stress"
"$root/build-tsan/tests/stress/navlink-world-soak" --seconds 6 --stall 120
"$root/build-tsan/tests/stress/navlink-agents-soak" --agents 1000 --steps 10000 --seconds 90 --stall 120
"$root/build-tsan/tests/stress/navlink-surfaces-soak" --seconds 30 --stall 120
"$root/build-tsan/tests/abi/navlink-abi-host-tasks-test"
unset TSAN_OPTIONS

echo "== all tests passed in $(( $(date +%s) - start )) s"
