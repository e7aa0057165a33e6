#!/bin/sh
# Lists what breaks STYLE.md's sizes in src/, apps/, include/ and python/src: files over 600
# lines, and functions over 60 lines (clang-tidy's readability-function-size, LineThreshold 60,
# over the build's compile_commands.json). Run by hand (docs/layers.md); it takes minutes.
#   scripts/check-sizes.sh [BUILD_DIR] [JOBS]     (default: build, 2)
# Exit status 1 when something is over, 0 otherwise.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}
jobs=${2:-2}
case $build in /*) ;; *) build="$root/$build" ;; esac
if [ ! -f "$build/compile_commands.json" ]; then
  echo "check-sizes: no $build/compile_commands.json (configure and build first)" >&2
  exit 2
fi
folders='src apps include python/src'
over=0

# Files over 600 lines.
files=$(cd "$root" && find $folders -name '*.cpp' -o -name '*.hpp' -o -name '*.h' | sort)
for f in $files; do
  lines=$(wc -l < "$root/$f")
  if [ "$lines" -gt 600 ]; then
    echo "$f: $lines lines (file over 600)"
    over=1
  fi
done

# Functions over 60 lines: every translation unit of these folders, their own headers too.
log=$(mktemp)
trap 'rm -f "$log"' EXIT
config='{Checks: "-*,readability-function-size", CheckOptions: [{key: readability-function-size.LineThreshold, value: 60}]}'
run-clang-tidy -quiet -j "$jobs" -p "$build" -config="$config" \
  -header-filter="^$root/(src|apps|include|python/src)/" \
  "^$root/(src|apps|python/src)/" > "$log" 2>/dev/null || true
# clang-tidy's warning names the function; its note below gives the count (colours removed).
sed 's/\x1b\[[0-9;]*m//g' "$log" | awk -v root="$root/" '
  /warning: function .* exceeds recommended size/ {
    where = $1; sub(root, "", where); sub(/:[0-9]+:$/, "", where)
    match($0, /function [^ ]+/); name = substr($0, RSTART + 9, RLENGTH - 9)
    next
  }
  where != "" && /note: [0-9]+ lines including/ {
    match($0, /[0-9]+ lines/); n = substr($0, RSTART, RLENGTH)
    key = where " " name
    if (!(key in seen)) { seen[key] = 1; print where ": function " name ": " n }
    where = ""
  }' | sort > "$log.out"
if [ -s "$log.out" ]; then
  cat "$log.out"
  over=1
fi
rm -f "$log.out"
[ "$over" -eq 0 ] && echo "check-sizes: no file over 600 lines, no function over 60"
exit "$over"
