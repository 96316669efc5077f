#!/usr/bin/env python3
"""Writes the large inputs of the bad-input corpus (the cases' {gen} folder).

  make_large_inputs.py FOLDER

Deterministic: the same files, byte for byte, on every run. Files already there with the
right content are kept (the runner calls this before every run).
- polygon_N.off: one face, a star-shaped (non-convex) N-gon in the plane z = 0, its corners
  alternately at radius 1 and 0.9 (N = 20,000 and 100,000): the reader's polygon
  triangulation must be fast (it was quadratic);
- polygon_20000_self_intersecting.off: the same 20,000-gon with corners 7000 and 7002 swapped, so
  edges cross: refused as not simple, quickly.
"""

import math
import os
import sys


def regular_polygon(n, swap=None):
    radius = [1.0, 0.9]
    corners = ["%r %r 0" % (radius[k % 2] * math.cos(2 * math.pi * k / n), radius[k % 2] * math.sin(2 * math.pi * k / n))
               for k in range(n)]
    order = list(range(n))
    if swap is not None:
        order[swap], order[swap + 2] = order[swap + 2], order[swap]
    return "OFF\n%d 1 0\n%s\n%d %s\n" % (n, "\n".join(corners), n, " ".join(str(k) for k in order))


def write(folder, name, text):
    path = os.path.join(folder, name)
    data = text.encode("ascii")
    if os.path.exists(path) and os.path.getsize(path) == len(data):
        with open(path, "rb") as f:
            if f.read() == data:
                return
    with open(path + ".tmp", "wb") as f:
        f.write(data)
    os.replace(path + ".tmp", path)


def main():
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    folder = sys.argv[1]
    os.makedirs(folder, exist_ok=True)
    write(folder, "polygon_20000.off", regular_polygon(20000))
    write(folder, "polygon_100000.off", regular_polygon(100000))
    write(folder, "polygon_20000_self_intersecting.off", regular_polygon(20000, swap=7000))


if __name__ == "__main__":
    main()
