#!/bin/sh
# Writes NavLink.dll.config, Mono's map from [DllImport("navlink")] to the libnavlink this NavLink.dll is
# built against (a <dllmap> to its absolute path), so that a Mono program finds it without
# LD_LIBRARY_PATH. The one writer of that file: NavLink.csproj's WriteNavLinkDllConfig target and
# run_tests.sh (when it builds with mcs) both call it.
#
# Usage: write_dll_config.sh CONFIG_FILE [LIBRARY_DIR]
# The library's folder: LIBRARY_DIR (NavLink.csproj's NavLinkLibraryDir property) when given, else
# `pkg-config --variable=libdir navlink` (PKG_CONFIG names another pkg-config). It must hold
# libnavlink.so.0 (mapped to first: the name a program loads) or libnavlink.so. Otherwise nothing is
# written, and the message (in MSBuild's error format, which xbuild and msbuild report as a build error)
# names both ways to give the folder.
set -eu
config=${1:?usage: write_dll_config.sh CONFIG_FILE [LIBRARY_DIR]}
dir=${2:-}

if [ -n "$dir" ]; then
  how="the NavLinkLibraryDir property"
  problem="NavLinkLibraryDir is $dir"
else
  how="pkg-config's navlink.pc"
  pkg_config=${PKG_CONFIG:-pkg-config}
  errors=$(mktemp)
  if dir=$("$pkg_config" --print-errors --variable=libdir navlink 2>"$errors"); then
    problem="NavLinkLibraryDir is not set, and navlink.pc (pkg-config) names libdir $dir"
  else
    reason=$(grep -v '^ *$' "$errors" | head -n 1 || true)
    reason=${reason%.}
    problem="NavLinkLibraryDir is not set, and \`$pkg_config --variable=libdir navlink\` failed: ${reason:-no navlink.pc found}"
    dir=
  fi
  rm -f "$errors"
fi

library=
for name in libnavlink.so.0 libnavlink.so; do
  if [ -n "$dir" ] && [ -f "$dir/$name" ]; then
    library=$(cd "$dir" && pwd)/$name
    break
  fi
done
if [ -z "$library" ]; then
  echo "write_dll_config.sh : error NAVLINK1: NavLink.dll.config: no libnavlink to map [DllImport(\"navlink\")] to: $problem${dir:+, which holds no libnavlink.so.0 or libnavlink.so}." \
       "Give the folder holding it: the NavLinkLibraryDir property (/p:NavLinkLibraryDir=DIR; a CMake build's capi folder)," \
       "or install NavLink (cmake --install build --prefix PREFIX) where pkg-config finds navlink.pc" \
       "(for a prefix of your own, PKG_CONFIG_PATH=PREFIX/lib/pkgconfig)." >&2
  exit 1
fi

# The path as an XML attribute value.
target=$(printf '%s' "$library" | sed -e 's/&/\&amp;/g' -e 's/</\&lt;/g' -e 's/>/\&gt;/g' -e 's/"/\&quot;/g')
mkdir -p "$(dirname "$config")"
cat > "$config" <<XML
<?xml version="1.0" encoding="utf-8"?>
<!-- Written by write_dll_config.sh when NavLink.dll was built: Mono loads libnavlink from here
     (found through $how). Mono only: .NET ignores this file. -->
<configuration>
  <dllmap dll="navlink" target="$target"/>
</configuration>
XML
echo "NavLink.dll.config: [DllImport(\"navlink\")] -> $library (found through $how)"
