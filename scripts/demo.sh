#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds NavLink and runs the main job on the bundled default level.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null
cmake --build "$root/build" -j "$(nproc)" --target navlink-raycast
"$root/build/samples/raycast/navlink-raycast" "$@"
