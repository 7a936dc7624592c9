#!/usr/bin/env bash
# Builds the Debian package of a built tree (`cpack -G DEB`, into a fresh folder under it) and checks
# what it holds (`dpkg-deb -c`: the library, headers, CMake package, navlink.pc, docs, and the
# programs and plugin modules when the samples are built), that every binary in it is stripped, and
# that its Depends were read from the binaries (dpkg-shlibdeps: Embree and TBB among them).
#
# Usage: run_package_test.sh <build-dir>
set -uo pipefail

if [ $# -ne 1 ]; then
  echo "usage: $0 <build-dir>" >&2
  exit 2
fi
build=$(cd "$1" && pwd -P) || exit 2
work=$build/tests/install/package
failures=0
fail() {
  echo "FAILED: $*"
  failures=$((failures + 1))
}

rm -rf "$work" && mkdir -p "$work" || { echo "FAILED: cannot create $work"; exit 1; }
if ! (cd "$work" && cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work") >"$work/cpack.log" 2>&1; then
  echo "FAILED: cpack -G DEB --config $build/CPackConfig.cmake"
  tail -n 40 "$work/cpack.log" | sed 's/^/  | /'
  exit 1
fi
deb=$(find "$work" -maxdepth 1 -name 'navlink_*.deb' | head -n 1)
if [ -z "$deb" ]; then
  echo "FAILED: cpack wrote no navlink_*.deb into $work"
  exit 1
fi

contents=$(dpkg-deb -c "$deb" | awk '{ print $6 }' | sed 's|^\./|/|')
# A here-string, not a pipe: grep -q stops at the first match, and under pipefail the writer's SIGPIPE
# would count as a failure.
has() { grep -qE "$1" <<<"$contents" || fail "the package holds no $2 ($1)"; }
has '^/usr/lib/([^/]+/)?libnavlink\.(so\.[0-9.]+|a)$' "libnavlink"
has '^/usr/include/navlink/navlink\.h$' "navlink.h"
has '^/usr/include/navlink/navlink\.hpp$' "navlink.hpp"
has '^/usr/include/navlink/plugin\.h$' "plugin.h"
has '^/usr/lib/([^/]+/)?cmake/NavLink/NavLinkConfig\.cmake$' "CMake package"
has '^/usr/lib/([^/]+/)?pkgconfig/navlink\.pc$' "navlink.pc"
has '^/usr/share/doc/navlink/shipping\.md$' "docs"
if grep -q '^NAVLINK_BUILD_SAMPLES:BOOL=ON' "$build/CMakeCache.txt"; then
  has '^/usr/bin/navlink$' "navlink tool"
  has '^/usr/bin/navlink-viewer$' "viewer"
  has '^/usr/lib/([^/]+/)?navlink/plugins/libnavlink-climb-plugin\.so$' "climb plugin"
fi

# Every ELF file in it without debug info.
unpacked=$work/unpacked
dpkg-deb -x "$deb" "$unpacked"
while IFS= read -r -d '' file; do
  if readelf -h "$file" >/dev/null 2>&1 && readelf -S "$file" 2>/dev/null | grep -q '\.debug_'; then
    fail "${file#"$unpacked"} is packaged with its debug info"
  fi
done < <(find "$unpacked" -type f -print0)

depends=$(dpkg-deb -f "$deb" Depends)
for library in libembree3 libtbb libc6; do
  grep -q "$library" <<<"$depends" || fail "Depends has no $library: '$depends'"
done

if [ "$failures" -ne 0 ]; then
  echo "package test: $failures check(s) failed (work directory kept: $work)"
  exit 1
fi
echo "$(basename "$deb"): $(du -k "$deb" | cut -f1) KB; Depends: $depends"
rm -rf "$work"
