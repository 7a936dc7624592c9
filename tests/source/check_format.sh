#!/usr/bin/env bash
# The C and C++ sources are as clang-format leaves them (.clang-format at the root). Left out: the public
# headers (capi/include/navlink/, laid out by hand: member docs aligned across lines, which clang-format 14
# cannot keep) and the generated files (bindings/generate writes them). With --fix, formats them instead.
#
# Usage: check_format.sh <source-dir> [--fix]
set -uo pipefail
root=$(cd "$1" && pwd -P) || exit 2
clang_format=${CLANG_FORMAT:-clang-format}
cd "$root" || exit 2
mapfile -t files < <(git ls-files '*.c' '*.cpp' '*.h' '*.hpp' |
  grep -vE '^capi/include/navlink/|^capi/src/generated_fields\.h$')
if [ "${2:-}" = --fix ]; then
  exec "$clang_format" -i "${files[@]}"
fi
if ! "$clang_format" --dry-run --Werror "${files[@]}" 2>"${TMPDIR:-/tmp}/check_format.$$"; then
  grep -E '^[^ ].*error:' "${TMPDIR:-/tmp}/check_format.$$" | cut -d: -f1 | sort -u | sed 's/^/not formatted: /'
  rm -f "${TMPDIR:-/tmp}/check_format.$$"
  echo "FAILED: run tests/source/check_format.sh . --fix (clang-format $("$clang_format" --version | grep -oE '[0-9]+\.[0-9.]+'))"
  exit 1
fi
rm -f "${TMPDIR:-/tmp}/check_format.$$"
echo "formatted: ${#files[@]} files"
