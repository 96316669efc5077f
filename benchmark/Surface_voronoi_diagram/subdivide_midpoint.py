#!/usr/bin/env python3
"""One 1-to-4 midpoint subdivision of a triangle OFF mesh (issue 12's igea-537k and igea-2M).

usage: subdivide_midpoint.py IN.off OUT.off [--times K]

Each edge gets its midpoint; each triangle becomes four. Vertices keep their order, edge
midpoints follow in order of first appearance, so the output is the same on every machine.
"""
import sys


def read_off(path):
    with open(path) as f:
        words = []
        for line in f:
            line = line.split('#', 1)[0]
            words.extend(line.split())
    if words[0] != 'OFF':
        sys.exit(f'{path}: not an OFF file')
    nv, nf = int(words[1]), int(words[2])
    at = 4
    points = [tuple(float(w) for w in words[at + 3 * i: at + 3 * i + 3]) for i in range(nv)]
    at += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(words[at])
        if n != 3:
            sys.exit(f'{path}: a face of {n} corners; triangles only')
        faces.append((int(words[at + 1]), int(words[at + 2]), int(words[at + 3])))
        at += 1 + n
    return points, faces


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
    for _ in range(times):
        points, faces = subdivide(points, faces)
    with open(args[1], 'w') as f:
        f.write(f'OFF\n{len(points)} {len(faces)} 0\n')
        f.writelines(f'{p[0]!r} {p[1]!r} {p[2]!r}\n' for p in points)
        f.writelines(f'3 {a} {b} {c}\n' for a, b, c in faces)


if __name__ == '__main__':
    main()
