#!/usr/bin/env bash
# The Rust crates built as a user outside the CMake tree builds them: a crate of one's own that depends on
# `navlink` by path, NAVLINK_LIB_DIR and NAVLINK_INCLUDE_DIRS unset, the library found only through a
# navlink.pc (written here for this build tree's library and headers, as an installed NavLink's looks), in
# a folder the loader does not search, and the program run without LD_LIBRARY_PATH:
# 1. with no rpath in the rustflags the build fails (a program built so would exit 127), and the message
#    holds the .cargo/config.toml lines to add;
# 2. with those lines pasted into the crate's .cargo/config.toml, it builds, and the program runs;
# 3. with no navlink.pc anywhere, the build fails and names what to set.
# One full build (step 2); steps 1 and 3 stop in navlink-sys's build script.
#
# Usage: check_pkg_config.sh LIBNAVLINK_SO SOURCE_ROOT GENERATED_INCLUDE_DIR CARGO_TARGET_DIR
# Environment: CARGO (default cargo).
set -euo pipefail
library=$(realpath "${1:?usage: check_pkg_config.sh LIBNAVLINK_SO SOURCE_ROOT GENERATED_INCLUDE_DIR CARGO_TARGET_DIR}")
root=$(cd "$2" && pwd)
generated_include=$3
export CARGO_TARGET_DIR=$4
cargo=${CARGO:-cargo}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
unset NAVLINK_LIB_DIR NAVLINK_INCLUDE_DIRS LD_LIBRARY_PATH NAVLINK_STATIC NAVLINK_RUN_PATH
# Rustflags from the environment would replace the config file's (step 2) or give the rpath (step 1).
unset RUSTFLAGS CARGO_ENCODED_RUSTFLAGS CARGO_BUILD_RUSTFLAGS
while read -r name; do unset "$name"; done < <(env | sed -n 's/^\(CARGO_TARGET_[A-Z0-9_]*_RUSTFLAGS\)=.*/\1/p')
lib_dir=$(dirname "$library")

mkdir "$tmp/pc" "$tmp/empty" "$tmp/consumer"
cat > "$tmp/pc/navlink.pc" <<PC
libdir=$lib_dir
Name: NavLink
Description: this build tree's library, as an installed one
Version: 0.0.0
Libs: -L\${libdir} -lnavlink
Cflags: -I$root/capi/include -I$generated_include
PC
# The consumer: its own workspace, the example as its program.
cat > "$tmp/consumer/Cargo.toml" <<TOML
[package]
name = "navlink-consumer"
version = "0.1.0"
edition = "2021"

[[bin]]
name = "wait_for_path"
path = "$root/bindings/rust/navlink/examples/wait_for_path.rs"

[dependencies]
navlink = { path = "$root/bindings/rust/navlink" }

[workspace]
TOML
cd "$tmp/consumer"

# PKG_CONFIG_LIBDIR replaces pkg-config's system folders, so only the file written here can answer.
if PKG_CONFIG_PATH=$tmp/pc PKG_CONFIG_LIBDIR=$tmp/pc "$cargo" build --offline -j1 --quiet 2> "$tmp/err"; then
  echo "FAIL: built with the library in $lib_dir and no rpath to it: the program would not start"
  exit 1
fi
triple=$("${RUSTC:-rustc}" -vV | sed -n 's/^host: //p')
for needed in "$lib_dir" "navlink.pc" "would not start" "[target.$triple]" \
              "rustflags = [\"-C\", \"link-arg=-Wl,-rpath,$lib_dir\"]" "NAVLINK_STATIC=1" "NAVLINK_RUN_PATH=loader"; do
  grep -qF -- "$needed" "$tmp/err" || { echo "FAIL: the failed build does not say $needed:"; cat "$tmp/err"; exit 1; }
done
echo "ok   with no rpath to $lib_dir the build fails, and says what to add:"
# Cargo indents a build script's output by two spaces; the lines are pasted without it.
mkdir .cargo
sed -n '/^ *\[target\./,/^ *rustflags = /s/^ *//p' "$tmp/err" | tee .cargo/config.toml

PKG_CONFIG_PATH=$tmp/pc PKG_CONFIG_LIBDIR=$tmp/pc "$cargo" run --offline -j1 --quiet > "$tmp/out"
cat "$tmp/out"
grep -q '^waited: Complete, .* 1 link(s)' "$tmp/out" || { echo "FAIL: the example did not wait for a complete path"; exit 1; }
grep -q '^awaited: Complete' "$tmp/out" || { echo "FAIL: the example did not await a complete path"; exit 1; }
echo "ok   with those lines in .cargo/config.toml: built through pkg-config alone, and ran without LD_LIBRARY_PATH"

if PKG_CONFIG_PATH=$tmp/empty PKG_CONFIG_LIBDIR=$tmp/empty "$cargo" build --offline -j1 --quiet 2> "$tmp/err"; then
  echo "FAIL: navlink-sys built with no NAVLINK_LIB_DIR and no navlink.pc"
  exit 1
fi
for needed in NAVLINK_LIB_DIR PKG_CONFIG_PATH "cmake --install"; do
  grep -q -- "$needed" "$tmp/err" || { echo "FAIL: the failed build does not name $needed:"; cat "$tmp/err"; exit 1; }
done
echo "ok   with nothing to find, the build fails naming NAVLINK_LIB_DIR, PKG_CONFIG_PATH and cmake --install"
