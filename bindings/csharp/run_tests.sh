#!/usr/bin/env bash
# Builds the C# binding (NavLink.dll) from NavLink.csproj with xbuild (the project file a .NET user builds;
# with mcs when there is no xbuild), builds the test program with mcs, then runs it with mono against
# libnavlink.so, as a Unity game's scripts would call it.
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
rm -f "$out/NavLink.dll"
if [ -n "$xbuild" ] && command -v "$xbuild" >/dev/null 2>&1; then
  echo "-- NavLink.dll from NavLink.csproj ($xbuild)"
  "$xbuild" /nologo /verbosity:minimal /p:Configuration=Release /p:OutputPath="$out/" \
            /p:BaseIntermediateOutputPath="$out/obj/" "$here/NavLink.csproj" > "$out/xbuild.log" 2>&1 ||
    { cat "$out/xbuild.log"; echo "FAIL: xbuild could not build NavLink.csproj"; exit 1; }
  [ -f "$out/NavLink.dll" ] || { cat "$out/xbuild.log"; echo "FAIL: xbuild wrote no $out/NavLink.dll"; exit 1; }
else
  echo "-- no xbuild (Debian: mono-xbuild): NavLink.csproj is not checked; NavLink.dll built with mcs"
  "$mcs" "${flags[@]}" -target:library -out:"$out/NavLink.dll" -recurse:"$package/Runtime/*.cs"
fi
# System.Runtime.Serialization and System.Xml.Linq: the framework's JSON reader, for the made-for JSON.
"$mcs" "${flags[@]}" -r:"$out/NavLink.dll" -r:System.Core -r:System.Runtime.Serialization -r:System.Xml \
       -r:System.Xml.Linq -out:"$out/NavLinkTests.exe" -recurse:"$here/Tests/*.cs"

# [DllImport("navlink")] finds libnavlink.so on the loader's path, as in a Unity player's Plugins folder.
# The test runs itself again without it, for the missing-library message.
export LD_LIBRARY_PATH="$NAVLINK_LIB_DIR${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
exec "$mono" --debug "$out/NavLinkTests.exe" --levels "$NAVLINK_LEVELS_DIR" --layout "$out/c_layout.txt" \
     --package "$package" --project "$here/NavLink.csproj" --library-dir "$NAVLINK_LIB_DIR"
