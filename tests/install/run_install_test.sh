#!/usr/bin/env bash
# Installs the built project into a fresh prefix under the build tree and uses it as a host would,
# linking the library given (default: the one the build makes; `static` for the libnavlink.a a shared
# build installs beside libnavlink.so):
#   1. the installed tree: headers, CMake package, navlink.pc, docs, and when the samples are built the
#      navlink tool (runs --help and --version from the prefix alone) and the viewer, the plugin
#      modules; each binary stripped when NAVLINK_INSTALL_STRIPPED is on;
#   2. a shared libnavlink.so exports only nl_* and has the SONAME libnavlink.so.0; a static
#      libnavlink.a defines no other global symbol than nl_* (but the weak instances of std templates);
#   3. a CMake project finds it with find_package(NavLink <major.minor> CONFIG REQUIRED), builds a C
#      and a C++ program, runs them: a ray on a triangle, and a navmesh built, links generated and a
#      path found over a jump (every library NavLink links is needed for that);
#   4. a plain `cc $(pkg-config --cflags --libs navlink)` build does the same (`--static` for libnavlink.a).
# Beside libnavlink.so, the archive is asked for as a host would: find_package(NavLink ... COMPONENTS
# static) and NavLink::navlink_static, `pkg-config --static navlink-static`; its programs must not load
# libnavlink.so. The consumer sees only the installed headers, never the source tree's.
#
# Usage: run_install_test.sh <build-dir> <cmake-command> <source-dir> [shared|static]
# Quiet on success; on failure prints what failed and the output of the failing step.
set -uo pipefail

usage="usage: $0 <build-dir> <cmake-command> <source-dir> [shared|static]"
if [ $# -lt 3 ] || [ $# -gt 4 ]; then
  echo "$usage" >&2
  exit 2
fi
build=$(cd "$1" && pwd -P) || exit 2
cmake=$2
source=$(cd "$3" && pwd -P) || exit 2

# What the build was configured to install.
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt" 2>/dev/null; }
is_on() { case "$1" in ON|on|1|TRUE|true|YES|yes) return 0 ;; *) return 1 ;; esac; }
shared=ON; is_on "$(cache_value NAVLINK_SHARED)" || shared=OFF
stripped=ON; is_on "$(cache_value NAVLINK_INSTALL_STRIPPED)" || stripped=OFF
samples=ON; is_on "$(cache_value NAVLINK_BUILD_SAMPLES)" || samples=OFF

# The library the consumers link.
linking=${4:-$([ "$shared" = ON ] && echo shared || echo static)}
case "$linking" in
  static) ;;
  shared)
    if [ "$shared" = OFF ]; then
      echo "FAILED: $build is a static build (NAVLINK_SHARED=OFF): it has no libnavlink.so"
      exit 1
    fi ;;
  *) echo "$usage" >&2; exit 2 ;;
esac

# One folder per library, so that both tests can run at once.
work=$build/tests/install/work-$linking
prefix=$work/prefix
log=$work/step.log
failures=0

# Runs a step quietly; on failure reports it with its output and counts it.
step() {
  local what=$1
  shift
  local rc=0
  "$@" >"$log" 2>&1 || rc=$?
  if [ "$rc" -ne 0 ]; then
    echo "FAILED: $what (exit code $rc)"
    echo "  command: $*"
    sed 's/^/  | /' "$log" | tail -n 40
    failures=$((failures + 1))
    return 1
  fi
  return 0
}

fail() {
  echo "FAILED: $*"
  failures=$((failures + 1))
}

finish() {
  if [ "$failures" -ne 0 ]; then
    echo "install test: $failures check(s) failed (work directory kept: $work)"
    exit 1
  fi
  rm -rf "$work"
  exit 0
}

# A fresh prefix every run: nothing from an earlier install may satisfy this one.
rm -rf "$work" || { echo "FAILED: cannot clean $work"; exit 1; }
mkdir -p "$work" || { echo "FAILED: cannot create $work"; exit 1; }

step "cmake --install into $prefix" "$cmake" --install "$build" --prefix "$prefix" || finish

# Where GNUInstallDirs put the library (lib, lib64 or lib/<multiarch>): the one holding navlink.pc.
pc=$(find "$prefix" -name navlink.pc -path '*/pkgconfig/*' | head -n 1)
if [ -z "$pc" ]; then
  fail "no navlink.pc installed under $prefix"
  finish
fi
libdir=$(dirname "$(dirname "$pc")")

for f in include/navlink/navlink.h include/navlink/base.h include/navlink/agents.h include/navlink/navlink.hpp include/navlink/export.h include/navlink/version.h; do
  [ -f "$prefix/$f" ] || fail "$f is not installed"
done
[ -f "$libdir/cmake/NavLink/NavLinkConfig.cmake" ] || fail "NavLinkConfig.cmake is not in $libdir/cmake/NavLink"
[ -f "$libdir/cmake/NavLink/NavLinkConfigVersion.cmake" ] || fail "NavLinkConfigVersion.cmake is not installed"

# The debug info is the build tree's; installed binaries have none (39 MB against under 1 MB).
check_stripped() {
  if [ "$stripped" = ON ] && readelf -S "$1" 2>/dev/null | grep -q '\.debug_'; then
    fail "$1 is installed with its debug info (NAVLINK_INSTALL_STRIPPED is on)"
  fi
}

# --- The installed tree -----------------------------------------------------------------------
docdir=$prefix/share/doc/navlink
for f in README.md CHANGELOG.md LICENSE docs.md c-api.md architecture.md platforms.md shipping.md; do
  [ -f "$docdir/$f" ] || fail "the docs' $f is not in $docdir"
done
if [ "$samples" = ON ]; then
  for program in navlink navlink-viewer; do
    if [ -x "$prefix/bin/$program" ]; then check_stripped "$prefix/bin/$program"; else fail "bin/$program is not installed"; fi
  done
  # Run from the prefix alone: the programs find the installed libnavlink through their RUNPATH.
  if step "bin/navlink --help" env -u LD_LIBRARY_PATH "$prefix/bin/navlink" --help; then
    grep -q "^usage: navlink COMMAND" "$log" || fail "bin/navlink --help printed: $(head -n 3 "$log")"
  fi
  if step "bin/navlink --version" env -u LD_LIBRARY_PATH "$prefix/bin/navlink" --version; then
    installed_version=$(sed -n 's/^#define NL_VERSION_[A-Z]* \([0-9]*\)$/\1/p' "$prefix/include/navlink/version.h" | paste -sd.)
    grep -qx "navlink $installed_version (libnavlink $installed_version)" "$log" ||
      fail "bin/navlink --version printed '$(cat "$log")', expected version $installed_version"
  fi
  plugin=$libdir/navlink/plugins/libnavlink-climb-plugin.so
  if [ -f "$plugin" ]; then check_stripped "$plugin"; else fail "the climb plugin is not at $plugin"; fi
fi

# --- The installed library --------------------------------------------------------------------
if [ "$linking" = shared ]; then
  lib=$libdir/libnavlink.so
  if [ ! -e "$lib" ]; then
    fail "libnavlink.so is not in $libdir"
    finish
  fi
  [ -L "$lib" ] || fail "libnavlink.so is not a symlink (to the versioned library)"
  [ -e "$libdir/libnavlink.so.0" ] || fail "libnavlink.so.0 is not installed"
  real=$(readlink -f "$lib")
  check_stripped "$real"

  soname=$(readelf -d "$real" 2>/dev/null | sed -n 's/.*(SONAME).*\[\(.*\)\].*/\1/p')
  [ "$soname" = "libnavlink.so.0" ] || fail "SONAME is '$soname', expected libnavlink.so.0"

  if step "nm -D --defined-only $real" nm -D --defined-only "$real"; then
    # "address type name[@version]"; a named version node in the version script shows up as an absolute
    # (A) symbol, which is not an export. Everything else must be nl_*.
    symbols=$(awk 'NF >= 3 && $2 != "A" { print $3 }' "$log")
    if [ -z "$symbols" ]; then
      fail "the library exports no symbols"
    else
      stray=$(printf '%s\n' "$symbols" | sed 's/@.*//' | grep -v '^nl_' | sort -u)
      if [ -n "$stray" ]; then
        fail "the library exports symbols other than nl_*:"
        printf '%s\n' "$stray" | head -n 20 | sed 's/^/  | /'
      fi
      grep -q '^nl_get_version$' <<<"$symbols" || fail "nl_get_version is not exported"
    fi
  fi
else
  real=$libdir/libnavlink.a
  if [ ! -f "$real" ]; then
    fail "libnavlink.a is not in $libdir"
    finish
  fi
  if [ "$shared" = OFF ]; then
    [ -e "$libdir/libnavlink.so" ] && fail "a static build installed libnavlink.so too"
  else
    [ -f "$libdir/cmake/NavLink/NavLinkStaticTargets.cmake" ] || fail "NavLinkStaticTargets.cmake is not installed"
  fi
  [ -f "$libdir/pkgconfig/navlink-static.pc" ] || fail "navlink-static.pc is not in $libdir/pkgconfig"
  check_stripped "$real"
  # Strong global definitions (text, data, bss, read-only): only nl_*, or the core's symbols would clash
  # with a host's. Weak ones (W, V, u) are the std templates' instances, the same in every program.
  if step "nm -g --defined-only $real" nm -g --defined-only "$real"; then
    symbols=$(awk 'NF >= 3 && $2 ~ /^[TDBRGSC]$/ { print $3 }' "$log")
    stray=$(printf '%s\n' "$symbols" | grep -v '^nl_' | sort -u)
    if [ -n "$stray" ]; then
      fail "libnavlink.a defines global symbols other than nl_*:"
      printf '%s\n' "$stray" | head -n 20 | sed 's/^/  | /'
    fi
    grep -q '^nl_get_version$' <<<"$symbols" || fail "libnavlink.a does not define nl_get_version"
  fi
fi

# Relocatable: nothing installed may point back into the build or source tree.
if grep -rIlF -e "$build" -e "$source" "$prefix" >"$log" 2>/dev/null; then
  fail "installed files refer to the build or source tree:"
  sed 's/^/  | /' "$log"
fi
if readelf -d "$real" 2>/dev/null | grep -E 'R(UN)?PATH' | grep -qF -e "$build" -e "$source"; then
  fail "the installed library has an RPATH/RUNPATH into the build or source tree"
fi

# The version the consumers ask for: the installed one, from the installed header.
version_of() { sed -n "s/^#define NL_VERSION_$1 \([0-9][0-9]*\).*/\1/p" "$prefix/include/navlink/version.h"; }
major=$(version_of MAJOR)
minor=$(version_of MINOR)
patch=$(version_of PATCH)
if [ -z "$major" ] || [ -z "$minor" ] || [ -z "$patch" ]; then
  fail "cannot read the version from the installed version.h"
  finish
fi

# A sanitized build's library needs the sanitizer runtime in the consumer too.
sanitize=$(cache_value NAVLINK_SANITIZE | tr ';' ',')
san_flags=()
if [ -n "$sanitize" ]; then
  san_flags=("-fsanitize=$sanitize" -fno-omit-frame-pointer)
fi

# The consumer's sources are copied out of the tree, so nothing next to them can be included by accident.
consumer_src=$work/consumer-src
mkdir -p "$consumer_src"
cp "$source"/tests/install/consumer/{CMakeLists.txt,consumer.c,path_consumer.c,path_consumer.cpp} "$consumer_src/"

# Only the installed copy: no package registries, no system prefixes ahead of ours.
cmake_common=(-DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
              -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF -DCMAKE_BUILD_TYPE=Release
              -DCMAKE_EXPORT_COMPILE_COMMANDS=ON)
if [ ${#san_flags[@]} -gt 0 ]; then
  cmake_common+=(-DCMAKE_C_FLAGS="${san_flags[*]}" -DCMAKE_CXX_FLAGS="${san_flags[*]}"
                 -DCMAKE_EXE_LINKER_FLAGS="${san_flags[*]}")
fi

# How the consumers ask for the library: beside libnavlink.so, the archive by the names it has there.
# libnavlink.a needs what it links on the command line too: the .pc file's Libs.private and Requires.private.
cm_static=(); pc_module=navlink; pc_static=()
if [ "$linking" = static ]; then
  pc_static=(--static)
  if [ "$shared" = ON ]; then
    cm_static=(-DNAVLINK_CONSUMER_STATIC=ON)
    pc_module=navlink-static
  fi
fi

# Checks that a consumer binary loads the installed library, not the build tree's; linked with
# libnavlink.a, that it loads no libnavlink at all.
check_loads_installed() {
  local binary=$1 how=$2
  shift 2
  local resolved
  resolved=$(env "$@" ldd "$binary" 2>/dev/null | awk '/libnavlink\.so/ { print $3 }')
  if [ "$linking" = static ]; then
    [ -z "$resolved" ] || fail "$how consumer, linked with libnavlink.a, loads a libnavlink.so ($resolved)"
    if readelf -d "$binary" 2>/dev/null | grep -q '(NEEDED).*\[libnavlink'; then
      fail "$how consumer, linked with libnavlink.a, names libnavlink in its NEEDED entries"
    fi
    return
  fi
  case "$resolved" in
    "$libdir"/*) ;;
    *) fail "$how consumer resolves libnavlink.so to '$resolved', not into $libdir" ;;
  esac
}

# Runs a consumer program and checks what it printed: `expected` is a grep pattern of its first line.
run_consumer() {
  local what=$1 expected=$2
  shift 2
  if step "run $what" "$@"; then
    grep -q "$expected" "$log" || fail "$what printed: $(cat "$log")"
  fi
}
hit_line="^NavLink $major\.$minor\.$patch: hit"
path_line="^path over 1 link"

# --- (a) CMake: find_package(NavLink major.minor CONFIG REQUIRED) -------------------------------
cm_build=$work/cmake-consumer
if step "configure the CMake consumer (find_package(NavLink $major.$minor${cm_static[*]:+ COMPONENTS static}))" \
    "$cmake" -S "$consumer_src" -B "$cm_build" -DNAVLINK_CONSUMER_VERSION="$major.$minor" "${cm_static[@]}" \
    "${cmake_common[@]}"; then
  found=$(sed -n 's/^NavLink_DIR:PATH=//p' "$cm_build/CMakeCache.txt")
  [ "$found" = "$libdir/cmake/NavLink" ] || fail "find_package found NavLink in '$found', not in $libdir/cmake/NavLink"
  if step "build the CMake consumer" "$cmake" --build "$cm_build"; then
    # Every include directory of the consumer's compile lies in the prefix.
    includes=$(tr ' ' '\n' <"$cm_build/compile_commands.json" | sed -n -e 's/^-I//p' -e '/^-isystem$/{n;p;}' | sort -u)
    [ -n "$includes" ] || fail "the CMake consumer compiles without any include directory from the package"
    for dir in $includes; do
      case "$dir" in
        "$prefix"/*) ;;
        *) fail "the CMake consumer compiles with the include directory $dir, outside $prefix" ;;
      esac
    done
    # Found through the build runpath CMake gives programs linking an imported library.
    run_consumer "the CMake consumer" "$hit_line" env -u LD_LIBRARY_PATH "$cm_build/consumer"
    run_consumer "the CMake path consumer (C)" "$path_line" env -u LD_LIBRARY_PATH "$cm_build/path_consumer"
    run_consumer "the CMake path consumer (C++)" "$path_line" env -u LD_LIBRARY_PATH "$cm_build/path_consumer_cxx"
    check_loads_installed "$cm_build/consumer" "the CMake" -u LD_LIBRARY_PATH
    check_loads_installed "$cm_build/path_consumer" "the CMake path" -u LD_LIBRARY_PATH
    check_loads_installed "$cm_build/path_consumer_cxx" "the CMake C++ path" -u LD_LIBRARY_PATH
  fi
fi

# A newer minor (or major, from 1.0 on) than the installed one must be refused by the version file.
if [ "$major" -eq 0 ]; then newer="0.$((minor + 1))"; else newer="$((major + 1)).0"; fi
if "$cmake" -S "$consumer_src" -B "$work/cmake-consumer-newer" -DNAVLINK_CONSUMER_VERSION="$newer" \
    "${cm_static[@]}" "${cmake_common[@]}" >"$log" 2>&1; then
  fail "find_package(NavLink $newer) accepted the installed $major.$minor.$patch"
fi

# --- (b) pkg-config -----------------------------------------------------------------------------
export PKG_CONFIG_PATH=$libdir/pkgconfig
unset PKG_CONFIG_SYSROOT_DIR
if step "pkg-config --modversion $pc_module" pkg-config --modversion "$pc_module"; then
  [ "$(cat "$log")" = "$major.$minor.$patch" ] || fail "pkg-config says version '$(cat "$log")', expected $major.$minor.$patch"
fi
pc_command="pkg-config ${pc_static[*]:+${pc_static[*]} }--cflags --libs $pc_module"
if step "$pc_command" pkg-config "${pc_static[@]}" --cflags --libs "$pc_module"; then
  read -r -a pc_flags <"$log"
  # The flags must lead into the prefix (the .pc file is relocatable) and nowhere else in the project.
  for flag in "${pc_flags[@]}"; do
    case "$flag" in
      -I*|-L*) path=${flag:2} ;;
      -Wl,-rpath,*) path=${flag#-Wl,-rpath,} ;;
      /*) path=$(dirname "$flag") ;;  # navlink-static.pc's archive
      *) continue ;;
    esac
    dir=$(cd "$path" 2>/dev/null && pwd -P)
    case "$dir" in
      "$prefix"/*) ;;
      *) fail "pkg-config flag $flag does not lead into $prefix" ;;
    esac
  done
  if [ "$linking" = shared ]; then
    printf '%s\n' "${pc_flags[@]}" | grep -q '^-Wl,-rpath,' || fail "navlink.pc's Libs carry no runpath to $libdir"
  fi
  for program in consumer path_consumer; do
    pc_bin=$work/pkgconfig-$program
    if step "build $program.c with cc \$($pc_command)" \
        cc -std=c11 -Wall -Wextra -pedantic -Werror "${san_flags[@]}" "$consumer_src/$program.c" -o "$pc_bin" \
        "${pc_flags[@]}" -lm; then
      # navlink.pc's runpath: the program finds the library it was built against with no
      # LD_LIBRARY_PATH (a program built so used to exit 127, libnavlink.so.0 not found).
      check_loads_installed "$pc_bin" "the pkg-config $program" -u LD_LIBRARY_PATH
    fi
  done
  run_consumer "the pkg-config consumer (no LD_LIBRARY_PATH)" "$hit_line" env -u LD_LIBRARY_PATH "$work/pkgconfig-consumer"
  run_consumer "the pkg-config path consumer (no LD_LIBRARY_PATH)" "$path_line" \
    env -u LD_LIBRARY_PATH "$work/pkgconfig-path_consumer"
fi

finish
