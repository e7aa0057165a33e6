#!/usr/bin/env bash
# The main job of `make demo`: the paper's Fig. 8 friction cones (Sec. 4.5) written into OUT.
# For each texture kind (isotropic Gaussian, anisotropic Gaussian, sawtooth) it generates two
# surfaces B and A (same kind, different seeds) with `asperity texture`, then runs
# `asperity cone` on the pair with mu0 = 0 and 16 directions. Idempotent: files are rewritten.
# Usage: scripts/demo.sh BIN_DIR OUT_DIR
set -euo pipefail
bin=${1:-build/bin}
out=${2:-out}
asperity="$bin/asperity"
[ -x "$asperity" ] || { echo "demo: $asperity not found (run make build first)" >&2; exit 1; }
size=256
mkdir -p "$out/textures" "$out/cones"

# name|generator and parameters: the three rows of Fig. 8. The sawtooth's ramps rise along v
# (axis 90), so its ridges run along t, as in the paper's figure.
rows=(
  "isotropic|gaussian --sx 1 --sy 1"
  "anisotropic|gaussian --sx 0.1 --sy 1"
  "sawtooth|sawtooth --axis 90"
)

echo "demo: friction cones of Fig. 8 (flat patch, mu0 = 0, k_A = k_B = 1, 16 directions)"
for row in "${rows[@]}"; do
  name=${row%%|*}
  read -r -a gen <<<"${row#*|}"
  tex_b="$out/textures/${name}_b.png"
  tex_a="$out/textures/${name}_a.png"
  cone="$out/cones/$name"
  # Surfaces B and A: the same kind of texture, different seeds.
  "$asperity" texture "${gen[@]}" --size "$size" --seed 1 --out "$tex_b"
  "$asperity" texture "${gen[@]}" --size "$size" --seed 2 --out "$tex_a"
  # The cone as JSON and as a figure, then its box for the summary.
  "$asperity" cone "$tex_b" --a "$tex_a" --directions 16 --mu0 0 --json \
    --svg "$cone.svg" --png "$cone.png" >"$cone.json"
  box=$("$asperity" cone "$tex_b" --a "$tex_a" --directions 16 --mu0 0 | grep '^box:')
  printf '  %-12s %s\n' "$name" "$box"
done

echo "demo: wrote into $out/"
echo "  textures/{isotropic,anisotropic,sawtooth}_{b,a}.png   normal maps (${size}x${size}, 8 bit)"
echo "  cones/{isotropic,anisotropic,sawtooth}.{json,svg,png} limit surfaces (polygon and box)"

# The paper's experiments (docs/experiments.md): measured outcomes, plots and Table 1.
"$asperity" report --out "$out"
echo "  report/index.html   the experiments of Sec. 5 against the paper (open in a browser)"
