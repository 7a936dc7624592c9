#!/usr/bin/env bash
# Builds the Debian package of a built tree (`cpack -G DEB`, into a fresh folder under it) and checks
# what it holds (`dpkg-deb -c`: libnavlink.so and libnavlink.a beside it, or the archive alone in a
# static build, headers, CMake package, the .pc files, docs, and the programs and plugin modules when
# the samples are built), that every binary in it is stripped (the archive keeping its nl_* symbols),
# that its Depends were read from the binaries (dpkg-shlibdeps: Embree and TBB among them), and that
# it names the -dev packages the archive's consumers link with.
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
shared=OFF
grep -q '^NAVLINK_SHARED:BOOL=ON' "$build/CMakeCache.txt" && shared=ON
if [ "$shared" = ON ]; then
  has '^/usr/lib/([^/]+/)?libnavlink\.so\.[0-9.]+$' "libnavlink.so"
  has '^/usr/lib/([^/]+/)?cmake/NavLink/NavLinkStaticTargets\.cmake$' "NavLink::navlink_static"
fi
has '^/usr/lib/([^/]+/)?libnavlink\.a$' "libnavlink.a"
has '^/usr/include/navlink/navlink\.h$' "navlink.h"
has '^/usr/include/navlink/navlink\.hpp$' "navlink.hpp"
has '^/usr/include/navlink/plugin\.h$' "plugin.h"
has '^/usr/lib/([^/]+/)?cmake/NavLink/NavLinkConfig\.cmake$' "CMake package"
has '^/usr/lib/([^/]+/)?pkgconfig/navlink\.pc$' "navlink.pc"
has '^/usr/lib/([^/]+/)?pkgconfig/navlink-static\.pc$' "navlink-static.pc"
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
# Stripped of its debug info only: what its consumers link against is still there.
archive=$(find "$unpacked" -name libnavlink.a | head -n 1)
if [ -n "$archive" ] && ! grep -q ' T nl_get_version$' <<<"$(nm -g --defined-only "$archive" 2>/dev/null)"; then
  fail "the packaged libnavlink.a does not define nl_get_version"
fi

depends=$(dpkg-deb -f "$deb" Depends)
for library in libembree3 libtbb libc6; do
  grep -q "$library" <<<"$depends" || fail "Depends has no $library: '$depends'"
done
# What libnavlink.a links: needed by every host of a static build, suggested beside libnavlink.so.
dev_field=Depends; [ "$shared" = ON ] && dev_field=Suggests
dev_packages=$(dpkg-deb -f "$deb" "$dev_field")
grep -q "libembree-dev" <<<"$dev_packages" || fail "$dev_field has no libembree-dev: '$dev_packages'"

if [ "$failures" -ne 0 ]; then
  echo "package test: $failures check(s) failed (work directory kept: $work)"
  exit 1
fi
echo "$(basename "$deb"): $(du -k "$deb" | cut -f1) KB; Depends: $depends"
rm -rf "$work"
