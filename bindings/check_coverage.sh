#!/usr/bin/env bash
# Fails unless the C#, Rust and Python bindings bind every public nl_* function: each symbol exported by
# libnavlink.so (nm -D --defined-only) and each function the public headers declare (NL_API). Also fails
# on a bound name that is neither (a typo binds nothing and fails only when called).
#
# The headers' static inline initialisers (NL_DEFINE_OUTPUT_INIT(T, nl_*_init)) are not exported: each
# binding writes its own, under the same name, and it must have every one and no other. They are found
# apart from the bound functions: C# `public static T nl_*()` in Runtime/Generated/ or Runtime/Native/ (not
# extern), Rust `pub fn nl_*()` outside navlink-sys's `extern "C"` blocks, Python `def nl_*():` at module
# level. Their behaviour (the `size` they set) is each binding's layout test's job.
#
# Constants: each binding's layout test requires every integer #define of the headers with its value. A
# constant the headers no longer define is caught by the C# and Python tests too; navlink-sys's `pub const
# NL_*` are checked here, as names of the headers' #defines.
#
# Usage: check_coverage.sh LIBNAVLINK_SO [SOURCE_ROOT]   (SOURCE_ROOT defaults to this script's ../)
# Environment: NM (default nm).
set -euo pipefail
library=${1:?usage: check_coverage.sh path/to/libnavlink.so [source-root]}
root=${2:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"${NM:-nm}" -D --defined-only "$library" | awk '$3 ~ /^nl_/ { print $3 }' | sort -u > "$tmp/exported"
grep -h '^NL_API' "$root"/capi/include/navlink/*.h |
  sed -E 's/^[^(]*[ *](nl_[a-z0-9_]+)\(.*/\1/' | sort -u > "$tmp/declared"
sort -u "$tmp/exported" "$tmp/declared" > "$tmp/public"

# The inline initialisers the headers define (the macro's own #define line excluded).
grep -h '^[[:space:]]*NL_DEFINE_OUTPUT_INIT(' "$root"/capi/include/navlink/*.h |
  sed -E 's/^[[:space:]]*NL_DEFINE_OUTPUT_INIT\( *[a-z0-9_]+ *, *(nl_[a-z0-9_]+) *\).*/\1/' | sort -u > "$tmp/inline"

# One name per line, as each binding declares its functions: bound ones in $binding, its own
# initialisers in $binding.inline.
grep -ho 'static extern [^(]* nl_[a-z0-9_]*(' "$root"/bindings/csharp/com.navlink.sdk/Runtime/{Generated,Native}/*.cs |
  sed -E 's/.* (nl_[a-z0-9_]+)\($/\1/' | sort -u > "$tmp/csharp"
grep -hoE 'public static [A-Za-z0-9_]+ nl_[a-z0-9_]*\(' "$root"/bindings/csharp/com.navlink.sdk/Runtime/{Generated,Native}/*.cs |
  sed -E 's/.* (nl_[a-z0-9_]+)\($/\1/' | sort -u > "$tmp/csharp.inline"
# Rust: functions inside `extern "C" {` ... `}` blocks are bound; other `pub fn nl_*` are initialisers.
awk '/^extern "C" \{/ { in_extern = 1; next }
     in_extern && /^\}/ { in_extern = 0; next }
     match($0, /pub fn nl_[a-z0-9_]*\(/) {
       name = substr($0, RSTART + 7, RLENGTH - 8)
       print name > (in_extern ? bound : inline)
     }' bound="$tmp/rust.unsorted" inline="$tmp/rust.inline.unsorted" "$root"/bindings/rust/navlink-sys/src/*.rs
touch "$tmp/rust.unsorted" "$tmp/rust.inline.unsorted"
sort -u "$tmp/rust.unsorted" > "$tmp/rust"
sort -u "$tmp/rust.inline.unsorted" > "$tmp/rust.inline"
grep -ho '^    "nl_[a-z0-9_]*": (' "$root"/bindings/python/_navlink_abi.py | sed -E 's/^    "(nl_[a-z0-9_]+)".*/\1/' |
  sort -u > "$tmp/python"
{ grep -ho '^def nl_[a-z0-9_]*(' "$root"/bindings/python/_navlink_abi.py || true; } | sed -E 's/^def (nl_[a-z0-9_]+)\(/\1/' |
  sort -u > "$tmp/python.inline"

# Object-like #define NL_* of the headers (version.h from its template), and navlink-sys's constants.
cat "$root"/capi/include/navlink/*.h "$root"/capi/include/navlink/version.h.in |
  sed -nE 's/^#[[:space:]]*define[[:space:]]+(NL_[A-Z0-9_]+)([[:space:]].*)?$/\1/p' | sort -u > "$tmp/defines"
{ grep -hoE '^pub const NL_[A-Z0-9_]+' "$root"/bindings/rust/navlink-sys/src/*.rs || true; } | awk '{ print $3 }' |
  sort -u > "$tmp/rust.constants"

echo "libnavlink.so exports $(wc -l < "$tmp/exported") nl_* symbols; the headers declare $(wc -l < "$tmp/declared")" \
     "and define $(wc -l < "$tmp/inline") inline initialisers"
exported_inline=$(comm -12 "$tmp/exported" "$tmp/inline")
[ -z "$exported_inline" ] || echo "note: inline initialisers also exported: $(echo $exported_inline)"
not_exported=$(comm -13 "$tmp/exported" "$tmp/declared")
[ -z "$not_exported" ] || echo "note: declared but not exported by this library: $(echo $not_exported)"
not_declared=$(comm -23 "$tmp/exported" "$tmp/declared")
[ -z "$not_declared" ] || echo "note: exported but declared in no public header: $(echo $not_declared)"

failed=0
for binding in csharp rust python; do
  missing=$(comm -23 "$tmp/public" "$tmp/$binding")
  unknown=$(comm -13 "$tmp/public" "$tmp/$binding")
  if [ -n "$missing" ]; then
    echo "FAIL $binding binds $(wc -l < "$tmp/$binding") functions; missing:"
    echo "$missing" | sed 's/^/  /'
    failed=1
  fi
  if [ -n "$unknown" ]; then
    echo "FAIL $binding binds functions the library neither exports nor declares:"
    echo "$unknown" | sed 's/^/  /'
    failed=1
  fi
  [ -n "$missing$unknown" ] || echo "ok   $binding binds all $(wc -l < "$tmp/public") public functions"
  missing=$(comm -23 "$tmp/inline" "$tmp/$binding.inline")
  unknown=$(comm -13 "$tmp/inline" "$tmp/$binding.inline")
  if [ -n "$missing" ]; then
    echo "FAIL $binding lacks the headers' inline initialisers:"
    echo "$missing" | sed 's/^/  /'
    failed=1
  fi
  if [ -n "$unknown" ]; then
    echo "FAIL $binding defines nl_* functions that are no inline initialiser of the headers:"
    echo "$unknown" | sed 's/^/  /'
    failed=1
  fi
  [ -n "$missing$unknown" ] || echo "ok   $binding defines all $(wc -l < "$tmp/inline") inline initialisers"
done
unknown=$(comm -13 "$tmp/defines" "$tmp/rust.constants")
if [ -n "$unknown" ]; then
  echo "FAIL rust (navlink-sys) defines constants the headers do not:"
  echo "$unknown" | sed 's/^/  /'
  failed=1
else
  echo "ok   rust's $(wc -l < "$tmp/rust.constants") constants are all the headers' ($(wc -l < "$tmp/defines") defined)"
fi
exit $failed
