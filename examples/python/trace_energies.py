#!/usr/bin/env python3
"""Traces one pixel sample and plots the energy each ray of its tree carries, coloured by
the ray's kind, with matplotlib (python3-matplotlib); writes a PNG.

    PYTHONPATH=build/release/python python3 examples/python/trace_energies.py \
        --scene lessons/scenes/materials.json --algorithm distributed --pixel 64 150 --out energies.png
"""

import argparse

# First: under another python3 than Debian's (pyenv), importing raylab adds Debian's packages
# (NumPy, matplotlib) to the path.
import raylab

import matplotlib  # noqa: E402,I100

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

KIND_COLOURS = {"camera": "tab:blue", "reflection": "tab:purple", "refraction": "tab:cyan",
                "diffuse": "tab:orange", "glossy": "tab:green", "shadow": "tab:gray"}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", help="scene file (default: the built-in scene)")
    parser.add_argument("--algorithm", default="distributed", choices=raylab.ALGORITHMS)
    parser.add_argument("--pixel", type=int, nargs=2, default=(200, 150), metavar=("X", "Y"))
    parser.add_argument("--sample", type=int, default=0)
    parser.add_argument("--out", default="energies.png")
    args = parser.parse_args()

    scene = raylab.load_scene(args.scene) if args.scene else raylab.default_scene()
    trace = raylab.trace(scene, tuple(args.pixel), args.sample, algorithm=args.algorithm)
    print(trace.summary())
    arrays = trace.arrays()

    figure, (by_ray, by_depth) = plt.subplots(1, 2, figsize=(10, 4))
    ids = np.arange(len(trace))
    energies = np.maximum(arrays["energies"], 1e-6)  # log scale: empty paths at the floor
    for kind, colour in KIND_COLOURS.items():
        mine = arrays["kinds"] == kind
        if mine.any():
            by_ray.bar(ids[mine], energies[mine], color=colour, label=kind)
            by_depth.scatter(arrays["depths"][mine], energies[mine], color=colour, label=kind)
    for axes in (by_ray, by_depth):
        axes.set_yscale("log")
        axes.set_ylabel("energy (luminance of throughput x radiance)")
    by_ray.set_xlabel("ray id (processing order)")
    by_depth.set_xlabel("depth (bounces from the camera ray)")
    by_ray.legend(fontsize=8)
    figure.suptitle(f"{trace.algorithm}: pixel {trace.pixel}, sample {trace.sample}, "
                    f"{len(trace)} rays, estimate {np.round(trace.estimate, 4)}")
    figure.tight_layout()
    figure.savefig(args.out, dpi=80)
    print(args.out)


if __name__ == "__main__":
    main()
