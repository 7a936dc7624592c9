#!/usr/bin/env bash
# The Rust crates built as a user outside the CMake tree builds them: NAVLINK_LIB_DIR and
# NAVLINK_INCLUDE_DIRS unset, the library found only through a navlink.pc (written here for this build
# tree's library and headers, as an installed NavLink's looks), and the example run without
# LD_LIBRARY_PATH (the rpath navlink's build.rs adds from DEP_NAVLINK_LIB_DIR). Then, with no navlink.pc
# anywhere, the build must fail and name what to set.
#
# Usage: check_pkg_config.sh LIBNAVLINK_SO SOURCE_ROOT GENERATED_INCLUDE_DIR CARGO_TARGET_DIR
# Environment: CARGO (default cargo).
set -euo pipefail
library=$(realpath "${1:?usage: check_pkg_config.sh LIBNAVLINK_SO SOURCE_ROOT GENERATED_INCLUDE_DIR CARGO_TARGET_DIR}")
root=$2
generated_include=$3
export CARGO_TARGET_DIR=$4
cargo=${CARGO:-cargo}
manifest=$root/bindings/rust/Cargo.toml
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
unset NAVLINK_LIB_DIR NAVLINK_INCLUDE_DIRS LD_LIBRARY_PATH NAVLINK_STATIC

mkdir "$tmp/pc" "$tmp/empty"
cat > "$tmp/pc/navlink.pc" <<PC
libdir=$(dirname "$library")
Name: NavLink
Description: this build tree's library, as an installed one
Version: 0.0.0
Libs: -L\${libdir} -lnavlink
Cflags: -I$root/capi/include -I$root/plugins/include -I$generated_include
PC

# PKG_CONFIG_LIBDIR replaces pkg-config's system folders, so only the file written here can answer.
PKG_CONFIG_PATH=$tmp/pc PKG_CONFIG_LIBDIR=$tmp/pc \
  "$cargo" run --offline -j1 --quiet --manifest-path "$manifest" -p navlink --example wait_for_path > "$tmp/out"
cat "$tmp/out"
grep -q '^waited: Complete, .* 1 link(s)' "$tmp/out" || { echo "FAIL: the example did not wait for a complete path"; exit 1; }
grep -q '^awaited: Complete' "$tmp/out" || { echo "FAIL: the example did not await a complete path"; exit 1; }
echo "ok   built through pkg-config alone, and ran without LD_LIBRARY_PATH"

if PKG_CONFIG_PATH=$tmp/empty PKG_CONFIG_LIBDIR=$tmp/empty \
   "$cargo" build --offline -j1 --quiet --manifest-path "$manifest" -p navlink-sys 2> "$tmp/err"; then
  echo "FAIL: navlink-sys built with no NAVLINK_LIB_DIR and no navlink.pc"
  exit 1
fi
for needed in NAVLINK_LIB_DIR PKG_CONFIG_PATH "cmake --install"; do
  grep -q -- "$needed" "$tmp/err" || { echo "FAIL: the failed build does not name $needed:"; cat "$tmp/err"; exit 1; }
done
echo "ok   with nothing to find, the build fails naming NAVLINK_LIB_DIR, PKG_CONFIG_PATH and cmake --install"
