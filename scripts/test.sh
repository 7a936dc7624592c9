#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine and runs every NavLink test: the release build's tests, then the
# same tests under AddressSanitizer + UndefinedBehaviorSanitizer. Exits non-zero on any failure.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"

jobs=$(nproc)
configure_and_build() {
  local dir=$1; shift
  cmake -S "$root" -B "$dir" -G Ninja "$@" > "$dir.configure.log" 2>&1 || { cat "$dir.configure.log"; return 1; }
  cmake --build "$dir" -j "$jobs"
}

start=$(date +%s)
echo "== release build and tests (with the C#, Rust and Python binding tests)"
configure_and_build "$root/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNAVLINK_BUILD_BINDINGS=ON
ctest --test-dir "$root/build" --output-on-failure

echo "== sanitizer build (address;undefined) and tests"
configure_and_build "$root/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNAVLINK_SANITIZE="address;undefined" \
  -DNAVLINK_BUILD_BENCHMARKS=OFF -DNAVLINK_INSTALL=OFF
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir "$root/build-asan" --output-on-failure -LE no_sanitizer

echo "== all tests passed in $(( $(date +%s) - start )) s"
