#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds the navlink tool and runs its demo: the generated default
# level, its jump and drop links, and one route planned for three agents (a walker, a short jumper, a
# long jumper who may drop). Prints their routes and writes demo.png and demo.links.json in the
# current folder. Arguments go to `navlink demo` (e.g. --seed 2, --oblique).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null
cmake --build "$root/build" -j "$(nproc)" --target navlink-cli
"$root/build/samples/cli/navlink" demo "$@"
