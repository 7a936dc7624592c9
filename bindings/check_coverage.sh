#!/usr/bin/env bash
# Fails unless the C#, Rust and Python bindings bind every public nl_* function: each symbol exported by
# libnavlink.so (nm -D --defined-only) and each function the public headers declare (NL_API). Also fails
# on a bound name that is neither (a typo binds nothing and fails only when called).
#
# Usage: check_coverage.sh LIBNAVLINK_SO [SOURCE_ROOT]   (SOURCE_ROOT defaults to this script's ../)
# Environment: NM (default nm).
set -euo pipefail
library=${1:?usage: check_coverage.sh path/to/libnavlink.so [source-root]}
root=${2:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"${NM:-nm}" -D --defined-only "$library" | awk '$3 ~ /^nl_/ { print $3 }' | sort -u > "$tmp/exported"
grep -h '^NL_API' "$root"/capi/include/navlink/*.h "$root"/plugins/include/navlink/*.h |
  sed -E 's/^[^(]*[ *](nl_[a-z0-9_]+)\(.*/\1/' | sort -u > "$tmp/declared"
sort -u "$tmp/exported" "$tmp/declared" > "$tmp/public"

# One name per line, as each binding declares its functions.
grep -ho 'static extern [^(]* nl_[a-z0-9_]*(' "$root"/bindings/csharp/NavLink/Native/*.cs |
  sed -E 's/.* (nl_[a-z0-9_]+)\($/\1/' | sort -u > "$tmp/csharp"
grep -ho 'pub fn nl_[a-z0-9_]*(' "$root"/bindings/rust/navlink-sys/src/*.rs | sed -E 's/pub fn (nl_[a-z0-9_]+)\(/\1/' |
  sort -u > "$tmp/rust"
grep -ho '^    "nl_[a-z0-9_]*": (' "$root"/bindings/python/navlink.py | sed -E 's/^    "(nl_[a-z0-9_]+)".*/\1/' |
  sort -u > "$tmp/python"

echo "libnavlink.so exports $(wc -l < "$tmp/exported") nl_* symbols; the headers declare $(wc -l < "$tmp/declared")"
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
done
exit $failed
