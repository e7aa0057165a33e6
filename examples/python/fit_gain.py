"""From appearance and one observation to friction: fit a surface's gain k so that a
simulated slide matches an observed distance.

The box on the concrete plane of boxes_on_materials slides some distance in 2 s. Given an
observed distance, bisection on the plane's gain k (Eq. 7: mu = mu0 + k_A mubar_A + k_B
mubar_B) finds the k whose simulation slides that far; each bisection step is one small
sweep (a grid of k values run in parallel), narrowing the bracket.

    /usr/bin/python3 examples/python/fit_gain.py [--observed 0.45]

Without --observed the observation is the scene's own slide, so the fit recovers k = 2.
"""

import argparse
import pathlib

import numpy as np

import asperity

SCENE = pathlib.Path(__file__).resolve().parents[2] / "scenes" / "boxes_on_materials.json"
GAIN = "/bodies/0/shapes/0/surface/gain"  # plane_concrete's k
MEASURE = "distance:box_concrete"


def slides(lo, hi, n, seconds):
    """Slide distances for n gains evenly spaced in [lo, hi]."""
    r = asperity.sweep(str(SCENE), vary={GAIN: f"grid({lo},{hi},{n})"}, samples=n,
                       seconds=seconds, measure=MEASURE)
    return r[GAIN], r[MEASURE]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--observed", type=float, default=None,
                        help="slide distance (m); default: the scene's own slide (k = 2), "
                             "so the fit should give k back")
    parser.add_argument("--seconds", type=float, default=2.0)
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()

    if args.observed is None:
        r = asperity.sweep(str(SCENE), samples=1, seconds=args.seconds, measure=MEASURE)
        args.observed = float(r[MEASURE][0])
        print(f"observed: {args.observed:.3f} m (the scene as written, k = 2)")
    lo, hi = 0.0, 6.0
    for round_ in range(args.rounds):
        gains, dist = slides(lo, hi, 5, args.seconds)
        print(f"round {round_}: k in [{lo:.3f}, {hi:.3f}] ->",
              ", ".join(f"{k:.2f}: {d:.3f} m" for k, d in zip(gains, dist)))
        # More gain, more friction, shorter slides: keep the bracket around the observation.
        above = np.nonzero(dist >= args.observed)[0]
        below = np.nonzero(dist < args.observed)[0]
        if len(above) == 0 or len(below) == 0:
            raise SystemExit(f"observed {args.observed} m is outside the slides "
                             f"{dist.min():.3f}..{dist.max():.3f} m of k in [{lo}, {hi}]")
        lo, hi = gains[above[-1]], gains[below[0]]
    # Linear interpolation inside the last bracket.
    (d_lo,), (d_hi,) = slides(lo, lo, 1, args.seconds)[1], slides(hi, hi, 1, args.seconds)[1]
    k = lo + (hi - lo) * (d_lo - args.observed) / (d_lo - d_hi)
    print(f"fitted k = {k:.3f} (slides {d_lo:.3f} m at k = {lo:.3f}, {d_hi:.3f} m at {hi:.3f})")


if __name__ == "__main__":
    main()
