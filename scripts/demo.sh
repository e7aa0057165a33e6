#!/usr/bin/env bash
# The main job of `make demo`: writes the paper's Fig. 8 friction cones into OUT.
# Usage: scripts/demo.sh BIN_DIR OUT_DIR
set -euo pipefail
bin=${1:-build/bin}
out=${2:-out}
mkdir -p "$out"
echo "demo: nothing to do yet" >&2
