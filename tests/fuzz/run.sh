#!/usr/bin/env bash
# Runs every libFuzzer target for a set time on a scratch copy of its seed corpus, and prints
# executions per target. A crash, leak, sanitizer report or timeout fails the run; its input is
# kept in $BIN/../fuzz-artifacts/ (turn it into a regression test under tests/fuzz/regressions/).
# Usage: tests/fuzz/run.sh BIN_DIR SECONDS_PER_TARGET [TARGET...]   (default: every target)
set -euo pipefail
bin=$1
seconds=$2
shift 2
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(scene png obj generators asset cli state)
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
artifacts="$bin/../fuzz-artifacts"
mkdir -p "$artifacts"
status=0
for target in "${targets[@]}"; do
  exe="$bin/asperity_fuzz_$target"
  mkdir -p "$work/$target"
  # New inputs go to the scratch corpus; the checked-in seeds and regressions are read only.
  seeds=("$here/corpus/$target")
  [ -d "$here/regressions/$target" ] && seeds+=("$here/regressions/$target")
  log="$work/$target.log"
  # An asset is read twice by design, each read allowed 60 s (src/geometry/child_probe.hpp):
  # first in a child, then in the program once the child got through.
  timeout=25
  [ "$target" = asset ] && timeout=130
  # A forged state must not make a step slow: a world, a load and two steps well inside 5 s.
  [ "$target" = state ] && timeout=5
  # intercept_tls_get_addr=0: see `make sanitize` in the Makefile.
  if ASAN_OPTIONS=detect_leaks=1:intercept_tls_get_addr=0 LSAN_OPTIONS="suppressions=$here/../sanitizer/lsan.supp" "$exe" -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$artifacts/$target-" "$work/$target" "${seeds[@]}" \
      >"$log" 2>&1; then
    result="0 crashes"
  else
    result="FAILED (see $artifacts)"
    status=1
    tail -40 "$log"
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  echo "fuzz $target: ${runs:-?} executions in ${seconds} s, $result"
done
exit $status
