"""Slide distance against surface roughness Ra: a sweep of boxes_on_materials.

Every sample gives the plastic plane (a 'roughness' generator) an Ra drawn on a grid and
records how far each box slides in 2 s; the plot shows the plastic box's distance against Ra.

    /usr/bin/python3 examples/python/slide_vs_ra.py [--samples 12] [--out slide_vs_ra.png]
"""

import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import asperity  # noqa: E402

SCENE = pathlib.Path(__file__).resolve().parents[2] / "scenes" / "boxes_on_materials.json"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=12)
    parser.add_argument("--seconds", type=float, default=2.0)
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--out", default="slide_vs_ra.png")
    args = parser.parse_args()

    # Ra (mm) of the plastic plane's generator, on a grid from smooth to rough.
    ra = "/bodies/3/shapes/0/surface/normal_map/params/ra_mm"
    result = asperity.sweep(str(SCENE), vary={ra: f"grid(0,1.5,{args.samples})"},
                            samples=args.samples, seconds=args.seconds,
                            measure=["distance:box_plastic"], threads=args.threads)
    for r, d in zip(result[ra], result["distance:box_plastic"]):
        print(f"Ra = {r:.3f} mm: slide {d:.3f} m")

    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.plot(result[ra], result["distance:box_plastic"], "o-")
    ax.set_xlabel("Ra of the plastic plane (mm)")
    ax.set_ylabel(f"slide distance in {args.seconds:g} s (m)")
    ax.set_title("boxes_on_materials: rougher slides less")
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
