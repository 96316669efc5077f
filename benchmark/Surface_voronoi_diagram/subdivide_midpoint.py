#!/usr/bin/env python3
"""One 1-to-4 midpoint subdivision of a triangle OFF mesh (compare_with_base.py's igea-537k and igea-2M).

usage: subdivide_midpoint.py IN.off OUT.off [--times K]

Each edge gets its midpoint; each triangle becomes four. Vertices keep their order, edge
midpoints follow in order of first appearance, so the output is the same on every machine.
"""
import os
import sys


# the regression matrix's OFF reader (the same grammar)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "test",
                                "Surface_voronoi_diagram", "regression"))
from run_matrix import read_off  # noqa: E402


def subdivide(points, faces):
    points = list(points)
    midpoint = {}

    def mid(a, b):
        key = (a, b) if a < b else (b, a)
        m = midpoint.get(key)
        if m is None:
            p, q = points[a], points[b]
            m = len(points)
            points.append(((p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2))
            midpoint[key] = m
        return m

    out = []
    for a, b, c in faces:
        ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return points, out


def main():
    args = sys.argv[1:]
    times = 1
    if '--times' in args:
        i = args.index('--times')
        times = int(args[i + 1])
        del args[i:i + 2]
    if len(args) != 2:
        sys.exit(__doc__.strip().splitlines()[2])
    points, faces = read_off(args[0])
    if any(len(f) != 3 for f in faces):
        sys.exit(f'{args[0]}: a face that is not a triangle; triangles only')
    for _ in range(times):
        points, faces = subdivide(points, faces)
    with open(args[1], 'w') as f:
        f.write(f'OFF\n{len(points)} {len(faces)} 0\n')
        f.writelines(f'{p[0]!r} {p[1]!r} {p[2]!r}\n' for p in points)
        f.writelines(f'3 {a} {b} {c}\n' for a, b, c in faces)


if __name__ == '__main__':
    main()
