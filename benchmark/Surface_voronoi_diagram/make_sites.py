#!/usr/bin/env python3
"""Sites files as a user's points are: near the surface, not on it (the comparison with geogram).

usage: make_sites.py PROGRAM MESH N OUT [--seed S] [--offset F]

The program's blue-noise sites (`--blue-noise N --seed S --sites-out`), each then moved off the
surface in a random direction by a random distance of at most F (default 1e-3) of the mesh's
bounding-box diagonal, drawn with Python's generator seeded by S. One "x y z" per line, 17
significant digits: the program's `--sites` format and geogram's harness's alike.
"""
import argparse
import math
import os
import random
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "test",
                                "Surface_voronoi_diagram", "regression"))
from run_matrix import read_off  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("program")
    parser.add_argument("mesh")
    parser.add_argument("n", type=int)
    parser.add_argument("out")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--offset", type=float, default=1e-3)
    args = parser.parse_args()

    points, _ = read_off(args.mesh)
    diagonal = math.sqrt(sum((max(p[a] for p in points) - min(p[a] for p in points)) ** 2 for a in range(3)))
    with tempfile.TemporaryDirectory() as work:
        on_surface = os.path.join(work, "sites.txt")
        subprocess.run([args.program, args.mesh, "--blue-noise", str(args.n), "--seed", str(args.seed),
                        "--metric", "euclidean", "--no-refine", "--sites-out", on_surface],
                       check=True, stdout=subprocess.DEVNULL)
        with open(on_surface) as f:
            sites = [[float(x) for x in line.split()[:3]] for line in f if line.strip()]
    rng = random.Random(args.seed)
    with open(args.out, "w") as out:
        for p in sites:
            d = [rng.gauss(0., 1.) for _ in range(3)]
            length = math.sqrt(sum(x * x for x in d)) or 1.
            r = rng.uniform(0., args.offset * diagonal)
            out.write("%.17g %.17g %.17g\n" % tuple(p[a] + r * d[a] / length for a in range(3)))


if __name__ == "__main__":
    main()
