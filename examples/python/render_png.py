"""A headless rendering to PNG: step a scene from Python and save one frame.

Renders through EGL (Mesa's llvmpipe without a GPU); prints why where no OpenGL context
can be made.

    /usr/bin/python3 examples/python/render_png.py [--scene scenes/stacking.json] [--at 1.0]
"""

import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.image  # noqa: E402

import asperity  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=str(ROOT / "scenes" / "stacking.json"))
    parser.add_argument("--at", type=float, default=1.0, help="simulated time of the frame (s)")
    parser.add_argument("--size", default="640x360")
    parser.add_argument("--out", default="frame.png")
    args = parser.parse_args()

    width, height = (int(x) for x in args.size.split("x"))
    world = asperity.World(args.scene)
    world.step(round(args.at / world.dt))
    try:
        image = world.render(width, height)
    except RuntimeError as e:
        raise SystemExit(str(e))
    matplotlib.image.imsave(args.out, image)
    print(f"wrote {args.out} ({width}x{height}, t = {world.time:.2f} s)")


if __name__ == "__main__":
    main()
