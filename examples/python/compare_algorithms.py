#!/usr/bin/env python3
"""Renders one scene with the four algorithms and writes them side by side as a PNG, with
each one's error against a path-traced reference (raylab compare, from Python).

    PYTHONPATH=build/release/python python3 examples/python/compare_algorithms.py \
        --scene lessons/scenes/cornell.json --size 160x120 --spp 16 --out compare.png
"""

import argparse

# First: under another python3 than Debian's (pyenv), importing raylab adds Debian's NumPy
# to the path.
import raylab

import numpy as np  # noqa: E402,I100


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", help="scene file (default: the built-in scene)")
    parser.add_argument("--size", default="160x120", help="WxH of each picture")
    parser.add_argument("--spp", type=int, default=16, help="samples per pixel of each")
    parser.add_argument("--reference-spp", type=int, default=0,
                        help="0: 16 x spp (256 at equal time)")
    parser.add_argument("--out", default="compare.png", help="PNG (or .pfm) to write")
    args = parser.parse_args()

    scene = raylab.load_scene(args.scene) if args.scene else raylab.default_scene()
    width, height = (int(n) for n in args.size.lower().split("x"))
    scene.set_camera(width=width, height=height)

    result = raylab.compare(scene, spp=args.spp, reference_spp=args.reference_spp,
                            progress=lambda stage, fraction, spp: print(
                                f"\r{stage:12s} {100 * fraction:5.1f}%", end="", flush=True))
    print()

    # The four pictures in a row, 4 white pixels apart (linear radiance 1 = white).
    gap = np.ones((height, 4, 3), dtype=np.float32)
    row = []
    for figures in result["algorithms"]:
        row += [figures["image"], gap]
        stats = figures["stats"]
        print(f"{figures['title']:38s} rmse {figures['rmse']:.4f}  {stats['rays']:>9d} rays  "
              f"{stats['seconds']:.2f} s")
    raylab.write_image(np.concatenate(row[:-1], axis=1), args.out)
    print(f"reference: path tracing, {result['reference']['spp']} spp")
    print(args.out)


if __name__ == "__main__":
    main()
