#!/usr/bin/env bash
# Builds the C# binding (NavLink.dll) and its test program with Mono's mcs, then runs the test with mono
# against libnavlink.so, as a Unity game's scripts would call it.
#
# Usage: run_tests.sh OUT_DIR
# Environment: NAVLINK_LIB_DIR (folder of libnavlink.so), NAVLINK_LEVELS_DIR (shared levels),
# NAVLINK_INCLUDE_DIRS (PATH-style header folders, for the layout table), MCS and MONO (default mcs, mono).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
out=${1:?usage: run_tests.sh OUT_DIR}
: "${NAVLINK_LIB_DIR:?}" "${NAVLINK_LEVELS_DIR:?}" "${NAVLINK_INCLUDE_DIRS:?}"
mcs=${MCS:-mcs}
mono=${MONO:-mono}
mkdir -p "$out"

# The C compiler's view of every struct, compared with the C# structs by the test.
include_args=()
IFS=: read -r -a include_dirs <<< "$NAVLINK_INCLUDE_DIRS"
for dir in "${include_dirs[@]}"; do include_args+=(-I "$dir"); done
python3 "$here/../layout/c_layout.py" "${include_args[@]}" -o "$out/c_layout.txt"

# C# 7.2 is the newest mcs accepts; unsafe for the fixed-size buffers of the blittable structs.
flags=(-langversion:7.2 -unsafe -debug -warnaserror+ -nologo)
"$mcs" "${flags[@]}" -target:library -out:"$out/NavLink.dll" -recurse:"$here/NavLink/*.cs"
# System.Runtime.Serialization and System.Xml.Linq: the framework's JSON reader, for the made-for JSON.
"$mcs" "${flags[@]}" -r:"$out/NavLink.dll" -r:System.Core -r:System.Runtime.Serialization -r:System.Xml \
       -r:System.Xml.Linq -out:"$out/NavLinkTests.exe" -recurse:"$here/Tests/*.cs"

# [DllImport("navlink")] finds libnavlink.so on the loader's path, as in a Unity player's Plugins folder.
export LD_LIBRARY_PATH="$NAVLINK_LIB_DIR${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
exec "$mono" --debug "$out/NavLinkTests.exe" --levels "$NAVLINK_LEVELS_DIR" --layout "$out/c_layout.txt"
