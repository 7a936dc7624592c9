#!/usr/bin/env bash
# Installs every Debian package NavLink's build, samples, bindings and tests need.
# Idempotent: packages already present are skipped, and apt-get update runs at most once per call.
set -euo pipefail

packages=(
  build-essential cmake pkg-config ninja-build
  libembree-dev libtbb-dev libeigen3-dev nlohmann-json3-dev doctest-dev libtinyobjloader-dev
  librecast-dev libsdl2-dev libstb-dev
  zlib1g-dev  # the CRC-32 of baked navmesh files
  mono-devel python3
  python3-pip python3-venv  # the Python binding's test installs its package with pip, also into a fresh venv
  python3-numpy  # the Python binding's numpy cases (bindings/python/test_navlink.py; skipped without it)
  clang libclang-rt-14-dev  # the sanitizer build and its libFuzzer targets (docs/testing.md)
  dpkg-dev  # dpkg-shlibdeps: the Debian package's Depends (cpack -G DEB, docs/shipping.md)
  ccache  # scripts/test.sh compiles through it: a second run, or a fresh clone, rebuilds nothing unchanged
  python3-clang  # libclang for Python: bindings/generate reads the public headers with it
  clang-format  # the one house style (.clang-format); the test source_format checks it
)
# The Rust binding's test needs cargo; a toolchain from rustup (not a Debian package) serves as well, so
# Debian's cargo (with its rustc) is added only when no cargo is on the PATH.
if ! command -v cargo >/dev/null 2>&1; then packages+=(cargo); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
echo "setup: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
