"""Speed of the Python module, measured side by side in one run (best of --repeat):

  step      N calls of world.step() from Python against `asperity run --steps N` (C++ loop)
            and world.step(N) (one call), on scenes/stacking.json;
  state     reading positions, orientations and both velocities of 1000 bodies;
  sweep     a 64-sample sweep of boxes_on_materials (2 s each) on 1 and on 2 threads.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/bench_python.py [step|state|sweep ...]
"""

import argparse
import os
import pathlib
import re
import subprocess
import time
import timeit

import asperity

ROOT = pathlib.Path(__file__).resolve().parents[2]
CLI = pathlib.Path(os.environ.get("ASPERITY_BIN", ROOT / "build" / "bin")) / "asperity"
STACKING = ROOT / "scenes" / "stacking.json"


def bench_step(repeat, steps):
    """Per-step wall time of the three ways, interleaved so that load hits them alike."""
    best = {"cli": 1e9, "python loop": 1e9, "python step(n)": 1e9}
    for _ in range(repeat):
        out = subprocess.run([str(CLI), "run", str(STACKING), "--steps", str(steps)],
                             capture_output=True, text=True, check=True).stdout
        best["cli"] = min(best["cli"], float(re.search(r"([0-9.]+) s wall", out).group(1)))
        world = asperity.World(str(STACKING))
        start = time.perf_counter()
        for _ in range(steps):
            world.step()
        best["python loop"] = min(best["python loop"], time.perf_counter() - start)
        world = asperity.World(str(STACKING))
        start = time.perf_counter()
        world.step(steps)
        best["python step(n)"] = min(best["python step(n)"], time.perf_counter() - start)
    for name, seconds in best.items():
        print(f"step  {name:15s} {1e3 * seconds / steps:8.4f} ms/step  "
              f"({100 * (seconds / best['cli'] - 1):+.2f} % vs cli)")
    # The cost of the call itself (argument conversion, GIL release and re-acquire): a step of
    # zero steps, timed alone so that the noise of stepping does not hide it.
    world = asperity.World(str(STACKING))
    per_call = min(timeit.repeat(lambda: world.step(0), number=10000, repeat=repeat)) / 10000
    print(f"step  one Python call of world.step(0): {1e6 * per_call:.3f} us = "
          f"{100 * per_call / (best['cli'] / steps):.3f} % of the C++ step")


def bench_state(repeat):
    """Reading the four state arrays of a 1000-body world."""
    bodies = [{"name": "ground", "type": "static", "shapes": [{"type": "plane"}]}]
    for i in range(1000):
        bodies.append({"name": f"b{i}", "position": [i % 40, i // 40, 1.0],
                       "shapes": [{"type": "sphere", "radius": 0.1}]})
    world = asperity.World({"bodies": bodies})
    world.step()
    for name in ["positions", "orientations", "linear_velocities", "angular_velocities"]:
        t = min(timeit.repeat(lambda n=name: getattr(world, n), number=1000, repeat=repeat))
        print(f"state {name:19s} {1e3 * t:8.2f} us per read of 1001 bodies")


def bench_sweep(repeat, samples, seconds):
    """The same sweep on 1 and on 2 threads, alternated."""
    scene = str(ROOT / "scenes" / "boxes_on_materials.json")
    vary = {"/bodies/*/linear_velocity/0": "uniform(1.5,2.5)"}
    best = {1: 1e9, 2: 1e9}
    hashes = {}
    for _ in range(repeat):
        for threads in (1, 2):
            start = time.perf_counter()
            r = asperity.sweep(scene, vary=vary, samples=samples, seconds=seconds,
                               threads=threads)
            best[threads] = min(best[threads], time.perf_counter() - start)
            hashes[threads] = list(r["state_hash"])
    assert hashes[1] == hashes[2]
    print(f"sweep {samples} samples x {seconds} s: 1 thread {best[1]:.2f} s, "
          f"2 threads {best[2]:.2f} s, speed-up {best[1] / best[2]:.2f}x (identical hashes)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("what", nargs="*", default=["step", "state", "sweep"])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--steps", type=int, default=500)
    parser.add_argument("--samples", type=int, default=64)
    parser.add_argument("--seconds", type=float, default=2.0)
    args = parser.parse_args()
    if "step" in args.what:
        bench_step(args.repeat, args.steps)
    if "state" in args.what:
        bench_state(args.repeat)
    if "sweep" in args.what:
        bench_sweep(max(1, args.repeat // 2), args.samples, args.seconds)


if __name__ == "__main__":
    main()
