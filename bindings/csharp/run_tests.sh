#!/usr/bin/env bash
# Builds the C# binding (NavLink.dll) from NavLink.csproj with xbuild (the project file a .NET user builds;
# with mcs when there is no xbuild), with the NavLink.dll.config beside it that maps [DllImport("navlink")]
# to $NAVLINK_LIB_DIR's library (write_dll_config.sh, which the project file runs), builds the test program
# with mcs, then runs it with mono against libnavlink.so, as a Unity game's scripts would call it, with the
# library's folder off LD_LIBRARY_PATH: NavLink.dll.config alone finds it.
#
# Usage: run_tests.sh OUT_DIR
# Environment: NAVLINK_LIB_DIR (folder of libnavlink.so), NAVLINK_LEVELS_DIR (shared levels),
# NAVLINK_INCLUDE_DIRS (PATH-style header folders, for the layout table), MCS and MONO (default mcs, mono),
# XBUILD (default xbuild; empty or missing: NavLink.csproj is not checked).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
out=${1:?usage: run_tests.sh OUT_DIR}
: "${NAVLINK_LIB_DIR:?}" "${NAVLINK_LEVELS_DIR:?}" "${NAVLINK_INCLUDE_DIRS:?}"
mcs=${MCS:-mcs}
mono=${MONO:-mono}
xbuild=${XBUILD-xbuild}
package="$here/com.navlink.sdk"
mkdir -p "$out"

# The C compiler's view of every struct, compared with the C# structs by the test.
include_args=()
IFS=: read -r -a include_dirs <<< "$NAVLINK_INCLUDE_DIRS"
for dir in "${include_dirs[@]}"; do include_args+=(-I "$dir"); done
python3 "$here/../layout/c_layout.py" "${include_args[@]}" -o "$out/c_layout.txt"

# C# 7.2 is the newest mcs accepts; unsafe for the fixed-size buffers of the blittable structs. NavLink.csproj
# sets the same for the library (LangVersion, AllowUnsafeBlocks, TreatWarningsAsErrors).
flags=(-langversion:7.2 -unsafe -debug -warnaserror+ -nologo)
rm -f "$out/NavLink.dll" "$out/NavLink.dll.config"
if [ -n "$xbuild" ] && command -v "$xbuild" >/dev/null 2>&1; then
  echo "-- NavLink.dll from NavLink.csproj ($xbuild)"
  "$xbuild" /nologo /verbosity:minimal /p:Configuration=Release /p:OutputPath="$out/" \
            /p:BaseIntermediateOutputPath="$out/obj/" /p:NavLinkLibraryDir="$NAVLINK_LIB_DIR" \
            "$here/NavLink.csproj" > "$out/xbuild.log" 2>&1 ||
    { cat "$out/xbuild.log"; echo "FAIL: xbuild could not build NavLink.csproj"; exit 1; }
  for file in NavLink.dll NavLink.dll.config; do
    [ -f "$out/$file" ] || { cat "$out/xbuild.log"; echo "FAIL: xbuild wrote no $out/$file"; exit 1; }
  done
else
  echo "-- no xbuild (Debian: mono-xbuild): NavLink.csproj is not checked; NavLink.dll built with mcs"
  "$mcs" "${flags[@]}" -target:library -out:"$out/NavLink.dll" -recurse:"$package/Runtime/*.cs"
  sh "$here/write_dll_config.sh" "$out/NavLink.dll.config" "$NAVLINK_LIB_DIR"
fi
# System.Runtime.Serialization and System.Xml.Linq: the framework's JSON reader, for the made-for JSON.
"$mcs" "${flags[@]}" -r:"$out/NavLink.dll" -r:System.Core -r:System.Runtime.Serialization -r:System.Xml \
       -r:System.Xml.Linq -out:"$out/NavLinkTests.exe" -recurse:"$here/Tests/*.cs"

# [DllImport("navlink")] finds libnavlink.so through NavLink.dll.config alone: its folder is taken off
# LD_LIBRARY_PATH if the caller had it there (the test checks). The test runs itself again from a copy whose
# NavLink.dll.config names a folder without the library, for the missing-library message.
library_dir=$(realpath "$NAVLINK_LIB_DIR")
kept=
IFS=: read -r -a folders <<< "${LD_LIBRARY_PATH:-}"
for folder in "${folders[@]}"; do
  if [ -n "$folder" ] && [ "$(realpath -m "$folder")" != "$library_dir" ]; then kept=${kept:+$kept:}$folder; fi
done
if [ -n "$kept" ]; then export LD_LIBRARY_PATH=$kept; else unset LD_LIBRARY_PATH; fi
exec "$mono" --debug "$out/NavLinkTests.exe" --levels "$NAVLINK_LEVELS_DIR" --layout "$out/c_layout.txt" \
     --package "$package" --project "$here/NavLink.csproj" --library-dir "$NAVLINK_LIB_DIR"
