#!/usr/bin/env bash
# Builds NavLink's library alone as libnavlink.a (NAVLINK_SHARED=OFF: no tests, samples nor
# benchmarks) with the compilers of the build that runs this test, then runs the install test on that
# build: the installed archive, and C and C++ consumers linked with it through find_package(NavLink)
# and through `pkg-config --static`, which build a navmesh and find a path (run_install_test.sh).
# The static build is kept between runs under the calling build, so a second run only recompiles what
# changed. NAVLINK_TEST_BUILD_JOBS sets its parallel jobs (default: as many as there are cores).
#
# Usage: run_static_install_test.sh <build-dir> <cmake-command> <source-dir>
set -uo pipefail

if [ $# -ne 3 ]; then
  echo "usage: $0 <build-dir> <cmake-command> <source-dir>" >&2
  exit 2
fi
build=$(cd "$1" && pwd -P) || exit 2
cmake=$2
source=$(cd "$3" && pwd -P) || exit 2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd -P)

static_build=$build/tests/install/static-library
log=$build/tests/install/static-library.log
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt"; }

# Release: the archive is what ships, and without -g it compiles in a third less time. A unity build
# (sources compiled in batches) halves the time again: the headers (Eigen, Embree, json) dominate.
if ! "$cmake" -S "$source" -B "$static_build" -G "$(cache_value CMAKE_GENERATOR)" \
    -DCMAKE_C_COMPILER="$(cache_value CMAKE_C_COMPILER)" -DCMAKE_CXX_COMPILER="$(cache_value CMAKE_CXX_COMPILER)" \
    -DCMAKE_BUILD_TYPE=Release -DNAVLINK_UNITY_BUILD=ON -DNAVLINK_SHARED=OFF -DNAVLINK_WERROR="$(cache_value NAVLINK_WERROR)" \
    -DNAVLINK_BUILD_TESTS=OFF -DNAVLINK_BUILD_SAMPLES=OFF -DNAVLINK_BUILD_BENCHMARKS=OFF \
    -DNAVLINK_BUILD_BINDINGS=OFF -DNAVLINK_INSTALL=ON >"$log" 2>&1; then
  echo "FAILED: configure the static library build in $static_build"
  tail -n 40 "$log" | sed 's/^/  | /'
  exit 1
fi
if ! "$cmake" --build "$static_build" --parallel "${NAVLINK_TEST_BUILD_JOBS:-$(nproc)}" >"$log" 2>&1; then
  echo "FAILED: build the static library in $static_build"
  tail -n 40 "$log" | sed 's/^/  | /'
  exit 1
fi
exec bash "$here/run_install_test.sh" "$static_build" "$cmake" "$source"
