#!/usr/bin/env python3
"""Checks that the #includes of src/ and include/asperity/ point down the layer order.

Every folder of src/ (and its public headers under include/asperity/) belongs to one layer;
a file may include its own layer and the layers below it, never one above. docs/layers.md
gives the order and the reasons for it.

Usage:
  check_include_layers.py [REPO_ROOT]          exit 1 naming FILE:LINE of each upward include
  check_include_layers.py --graph [REPO_ROOT]  print which layers each layer includes

Python 3 standard library only; ctest runs it as the test IncludeLayers.
"""

import os
import re
import sys

# Lowest first. "top" is asperity's top-level headers (include/asperity/error.hpp and the
# like); a folder's sub-folders belong to it (friction/limit_surfaces, sampler/gl).
LAYERS = [
    "top",
    "math",
    "parallel",
    "gl",
    "texture",
    "contact_area",
    "geometry",
    "friction",
    "dynamics",
    "collision",
    "frames",
    "sampler",
    "solver",
    "world",
    "scene",
    "engines",
    "sweep",
    "batch",
    "tribometer",
    "experiments",
    "render",
]
RANK = {name: rank for rank, name in enumerate(LAYERS)}

# The umbrella header includes every public header of the core library on purpose: it sits
# above all layers and no library file includes it.
UMBRELLA = "include/asperity/asperity.hpp"

# Known upward includes, as (layer, included layer), each with the reason it is still there.
# Empty: the solve stage's restructuring (issue 31) removed the last ones.
ALLOWED: set = set()

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


# Public folders that belong to another folder's layer: include/asperity/c/ is the C face of
# the engines layer's contact friction API.
FOLDER_LAYER = {"c": "engines"}


def layer_of(relative):
    """The layer of a path relative to src/ or include/asperity/ (None: not a layer)."""
    parts = relative.split("/")
    if len(parts) == 1:
        return "top"
    folder = FOLDER_LAYER.get(parts[0], parts[0])
    return folder if folder in RANK else None


def included_layer(header, including_layer):
    """The layer of a quoted #include, or None for a header outside the layers."""
    parts = header.split("/")
    if parts[0] == "asperity":
        return layer_of("/".join(parts[1:]))
    if len(parts) > 1 and parts[0] in RANK:
        return parts[0]
    # A header beside the including file (experiment_support.hpp) or a third-party one.
    return including_layer if len(parts) == 1 and not header.endswith(".h") else None


def source_files(root):
    """(path relative to the repository, path relative to its tree) of every C++ file."""
    for tree in ("src", os.path.join("include", "asperity")):
        base = os.path.join(root, tree)
        for folder, _, files in sorted(os.walk(base)):
            for name in sorted(files):
                if name.endswith((".hpp", ".cpp", ".h")):
                    path = os.path.join(folder, name)
                    yield os.path.relpath(path, root), os.path.relpath(path, base)


def scan(root):
    """Every include between layers: (file, line, layer, included layer, header)."""
    edges, unknown = [], []
    for repo_path, tree_path in source_files(root):
        if repo_path.replace(os.sep, "/") == UMBRELLA:
            continue
        layer = layer_of(tree_path.replace(os.sep, "/"))
        if layer is None:
            unknown.append(repo_path)
            continue
        with open(os.path.join(root, repo_path), encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                target = included_layer(match.group(1), layer)
                if target is not None:
                    edges.append((repo_path, number, layer, target, match.group(1)))
    return edges, unknown


def check(root):
    edges, unknown = scan(root)
    failures = []
    # A folder outside the order has to be placed in it first.
    for path in unknown:
        failures.append(f"{path}: its folder is not a layer (add it to LAYERS and docs/layers.md)")
    used_allowances = set()
    for path, number, layer, target, header in edges:
        if RANK[target] <= RANK[layer]:
            continue
        if (layer, target) in ALLOWED:
            used_allowances.add((layer, target))
            print(f"{path}:{number}: allowed for now: {layer} includes {target} ({header})")
            continue
        failures.append(
            f"{path}:{number}: {layer} includes {target} ({header}), a higher layer")
    # Entries whose includes are gone: a reminder, not a failure (branches merge in any order).
    for layer, target in sorted(ALLOWED - used_allowances):
        print(f"note: the allowance {layer} -> {target} is no longer used: remove it")
    for failure in failures:
        print(failure)
    if failures:
        print(f"{len(failures)} upward include(s); layer order, lowest first: "
              + ", ".join(LAYERS))
        return 1
    return 0


def graph(root):
    edges, _ = scan(root)
    targets = {}
    for _, _, layer, target, _ in edges:
        if target != layer:
            targets.setdefault(layer, set()).add(target)
    for layer in LAYERS:
        below = sorted(targets.get(layer, ()), key=RANK.get)
        print(f"{layer}: {', '.join(below) if below else '-'}")
    return 0


def main(argv):
    show_graph = "--graph" in argv
    args = [a for a in argv if a != "--graph"]
    root = args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    return graph(root) if show_graph else check(root)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
