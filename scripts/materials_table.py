#!/usr/bin/env python3
"""The tables of docs/materials.md: each material preset's tribometer numbers on itself and on
steel, with the gains and mu0 of the paper's experiment it comes from, beside the handbook
ranges, and the gain that brings mu_k into a range it misses.

Usage: PYTHONPATH=build/python /usr/bin/python3 scripts/materials_table.py
Each pair is written as a small scene (plate and block, the experiment's surfaces) and measured
with asperity.tribometer(scene=..., bodies=["block", "plate"]), 16 directions, both tests.
"""

import json
import math
import os
import tempfile

import numpy as np

import asperity

# name: (generator, texels, texture size (m), gain, mu0, the experiment) as the scenes have them.
PRESETS = {
    "acrylic": ("acrylic", 128, 0.2, 1.0, 0.2, "stacking"),
    "oak": ("oak", 160, 0.2, 1.0, 0.2, "stacking"),
    "cut_pvc": ("cut_pvc", 128, 0.2, 1.0, 0.2, "stacking"),
    "plaster": ("plaster", 128, 0.032, 2.0, 0.2, "boxes"),
    "concrete": ("concrete", 256, 0.256, 2.0, 0.2, "boxes"),
    "cast_iron": ("cast_iron", 256, 0.256, 2.0, 0.2, "boxes"),
    "steel": ("steel", 256, 0.256, 2.0, 0.2, "boxes"),
    "stone": ("stone", 128, 0.1, 4.0, 0.1, "bunnies"),
    "metal": ("metal", 128, 0.1, 4.0, 0.1, "bunnies"),
    "plastic": ("plastic", 128, 0.1, 4.0, 0.1, "bunnies"),
}

# Handbook ranges (dry friction, engineering handbooks) (mu_s, mu_k), (lo, hi) or None, for a (block, plate) pair and what
# it stands for.
HANDBOOK = {
    ("steel", "steel"): ("steel on steel", (0.74, 0.80), (0.42, 0.62)),
    ("cast_iron", "cast_iron"): ("cast iron on cast iron", (1.1, 1.1), (0.15, 0.15)),
    ("oak", "oak"): ("wood on wood", (0.25, 0.50), None),
    ("oak", "concrete"): ("wood on concrete", (0.62, 0.62), None),
    ("acrylic", "acrylic"): ("acrylic on acrylic", (0.8, 0.8), None),
    ("acrylic", "steel"): ("plastic on steel", (0.20, 0.45), (0.18, 0.35)),
    ("cut_pvc", "steel"): ("plastic on steel", (0.20, 0.45), (0.18, 0.35)),
    ("plastic", "steel"): ("plastic on steel", (0.20, 0.45), (0.18, 0.35)),
    ("metal", "metal"): ("steel on steel", (0.74, 0.80), (0.42, 0.62)),
    ("metal", "steel"): ("steel on steel", (0.74, 0.80), (0.42, 0.62)),
}
OAK = {"along": ((0.62, 0.62), (0.48, 0.48)), "across": ((0.54, 0.54), (0.32, 0.32))}

# Every preset on itself and on steel, and wood on concrete.
PAIRS = [(name, name) for name in PRESETS] + \
        [(name, "steel") for name in PRESETS if name != "steel"] + [("oak", "concrete")]


def surface(name, seed, gain):
    gen, size, texture_size, _, _, _ = PRESETS[name]
    return {"normal_map": {"generator": gen, "size": size, "seed": seed}, "gain": gain,
            "texture_size": texture_size}


def pair_scene(folder, block, plate, k_block, k_plate, mu0):
    """A scene of the plate and the block with the presets' surfaces (the block's of another
    seed); its path."""
    scene = {"settings": {"mu0": mu0, "friction_provider": "cpu", "patch_width": 0.02},
             "bodies": [
                 {"name": "plate", "type": "static",
                  "shapes": [{"type": "plane", "surface": surface(plate, 1, k_plate)}]},
                 {"name": "block", "position": [0, 0, 0.0125],
                  "shapes": [{"type": "box", "half_extents": [0.05, 0.05, 0.0125],
                              "surface": surface(block, 2, k_block)}]}]}
    path = os.path.join(folder, "%s_on_%s_%g_%g.json" % (block, plate, k_block, k_plate))
    with open(path, "w", encoding="utf-8") as f:
        json.dump(scene, f)
    return path


def measure(folder, block, plate, k_block, k_plate, mu0, tests=("tilt", "drag")):
    path = pair_scene(folder, block, plate, k_block, k_plate, mu0)
    return asperity.tribometer(scene=path, bodies=["block", "plate"], tests=list(tests))


def span(values):
    """'0.412' or '0.40 to 0.43' over the directions (NaN: no slide / stuck)."""
    v = np.asarray(values)
    if np.isnan(v).any():
        return "none in %d of %d" % (int(np.isnan(v).sum()), len(v))
    lo, hi, mean = v.min(), v.max(), v.mean()
    return "%.3f" % mean if hi - lo < 0.02 else "%.3f (%.2f to %.2f)" % (mean, lo, hi)


def verdict(value, rng):
    if rng is None:
        return ""
    lo, hi = rng
    if lo <= value <= hi:
        return "in"
    return "below" if value < lo else "above"


def gain_for(folder, block, plate, target, mu0, k_plate):
    """The gain whose mean mu_model is `target`: of both surfaces when they are one material,
    else of the block; mu_model is linear in the gains (docs/calibration.md)."""
    if block == plate:
        unit = measure(folder, block, plate, 1.0, 1.0, 0.0, ("drag",))["mu_model"].mean()
        return (target - mu0) / unit
    rest = measure(folder, block, plate, 0.0, k_plate, mu0, ("drag",))["mu_model"].mean()
    unit = measure(folder, block, plate, 1.0, 0.0, 0.0, ("drag",))["mu_model"].mean()
    return (target - rest) / unit


def against(folder, block, plate, value, rng, which, mu0, k_plate):
    """'in', or how far off and the gain that reaches the range's middle."""
    status = verdict(value, rng)
    if status not in ("below", "above"):
        return status
    target = 0.5 * sum(rng)
    if target <= mu0:
        return "%s %s: %.2f is below mu0 = %g, no gain reaches it" % (which, status, target, mu0)
    g = gain_for(folder, block, plate, target, mu0, k_plate)
    if g < 0.0:
        # mu0 and the plate's texture alone already give more: no block gain comes down to it.
        return "%s %s: mu0 and the plate (k %g) alone give more than %.2f" % (which, status,
                                                                            k_plate, target)
    return "%s %s: k %.3g%s gives %.2f" % (which, status, g,
                                           " (both)" if block == plate else " (block)", target)


def row(folder, block, plate):
    """One table row: the pair with the paper's gains and mu0 (the block's experiment's mu0)."""
    _, _, _, k, mu0, experiment = PRESETS[block]
    k_plate = PRESETS[plate][3]
    r = measure(folder, block, plate, k, k_plate, mu0)
    label, hb_s, hb_k = HANDBOOK.get((block, plate), ("", None, None))
    mu_s, mu_k = np.nanmean(r["mu_s"]), np.nanmean(r["mu_k"])
    notes = [n for n in (against(folder, block, plate, mu_s, hb_s, "mu_s", mu0, k_plate),
                         against(folder, block, plate, mu_k, hb_k, "mu_k", mu0, k_plate)) if n]
    return ["`%s` on %s" % (block, "itself" if block == plate else "`%s`" % plate),
            "%s: k %g / %g, mu0 %g" % (experiment, k, k_plate, mu0), span(r["mu_s"]),
            span(r["mu_k"]), label or "none listed", fmt_range(hb_s), fmt_range(hb_k),
            "; ".join(notes)]


def fmt_range(rng):
    if rng is None:
        return "-"
    return "%.2f" % rng[0] if rng[0] == rng[1] else "%.2f to %.2f" % rng


def oak_grain(folder):
    """Oak on oak along (0, 180 degrees) and across (90, 270) the grain, and the gain of both
    surfaces that reaches the handbook's kinetic value along the grain."""
    r = measure(folder, "oak", "oak", 1.0, 1.0, 0.2)
    unit = measure(folder, "oak", "oak", 1.0, 1.0, 0.0, ("drag",))["mu_model"]
    lines = []
    for name, ks in (("along", [0, 8]), ("across", [4, 12])):
        s, k = np.mean(r["mu_s"][ks]), np.mean(r["mu_k"][ks])
        hb_s, hb_k = OAK[name]
        gain = (hb_k[0] - 0.2) / np.mean(unit[ks])
        lines.append("| oak on oak, %s the grain | %.3f | %.3f | %.2f | %.2f | %.2f |"
                     % (name, s, k, hb_s[0], hb_k[0], gain))
    return lines


def main():
    with tempfile.TemporaryDirectory() as folder:
        print("| pair | gains (experiment) | mu_s | mu_k | handbook pair | handbook mu_s |"
              " handbook mu_k | against it |")
        print("|---|---|---|---|---|---|---|---|")
        for block, plate in PAIRS:
            print("| " + " | ".join(row(folder, block, plate)) + " |")
        print()
        print("| oak, stacking's gains (k 1, mu0 0.2) | mu_s | mu_k | handbook mu_s |"
              " handbook mu_k | k (both) for the handbook's mu_k |")
        print("|---|---|---|---|---|---|")
        for line in oak_grain(folder):
            print(line)


if __name__ == "__main__":
    main()
