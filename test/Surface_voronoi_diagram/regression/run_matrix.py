#!/usr/bin/env python3
"""The regression matrix: program runs whose results must not change by accident.

Every entry runs the surface_voronoi program on a mesh file with a deterministic sites file
(and, for some, a breaklines file) and records, one line each, what must not change while
tolerating what may (a change of summation order moves the last bits, not the diagram):

  exit, stderr  the exit code and the first line of stderr, exactly;
  stats         the --stats keys that are not timings: the counts (sites, cells, empty_cells,
                pieces, sites_added, dual_* ...) and the words (metric) exactly; the floating
                values surface_area, mean_candidates_per_face and lloyd_energy_* to a relative
                1e-6, unreached_area to 1e-9 of the surface area;
  files         which output files were written;
  owners        per input face (the PLY's input_face), the set of sites owning its pieces,
                pieces of area under 1e-12 of the surface area ignored: the number of faces
                by number of owners (owners:faces), and a hash of the whole list (too long
                to store);
  cell_pieces   per cell, its number of pieces (edge-connected parts of its faces): the
                histogram (pieces:cells) and every cell with other than one (site:pieces);
  neighbours    per cell, its neighbouring sites (sharing a side longer than 1e-9 of the root
                of the surface area, between pieces that are not ignored): the number of
                pairs, the histogram of the degrees (degree:cells), and a hash of the list
                of pairs;
  areas         per site, its area (and the area no site reaches) in units of 1e-10 of the
                surface area, compared to 1e-9 of the surface area (plus the two roundings);
  threads_1_vs_2, sites_out_roundtrip
                bit equality inside one run, for the entries of BIT_CHECKS: the same run
                with --threads 1 and --threads 2, and the run again with --sites on the
                sites file it wrote, give the same output bytes.

The surface area is the sum of the arrangement's pieces. The expected records are committed
in expected.txt; a run compares them entry by entry and prints every difference.

  run_matrix.py PROGRAM [--record] [--data DIR] [--work DIR] [--only SUBSTRING] [--part K/N] [--keep]

PROGRAM     the surface_voronoi binary
--record    write expected.txt from this run (only after checking why it changed)
--data DIR  a folder of real models (default: ../shared/data/meshes beside the checkout, used
            when it exists); their entries are compared only when the folder is there
--work DIR  where outputs go (default: build/regression)
--only S    run only the entries whose name contains S
--part K/N  run only the K-th of N interleaved shares of the entries (1 <= K <= N), so that
            N processes run the matrix side by side (ctest runs it in two parts)
--keep      keep the outputs

Inputs are files: the bundled example mesh, three generated shells written out once (in
meshes/), and the real models when present. Sites and breaklines are generated here from the
mesh alone with integer arithmetic and correctly rounded floating point, so they are the same
on every machine.
"""

import argparse
import hashlib
import math
import os
import struct
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
EXPECTED = os.path.join(HERE, "expected.txt")
TIMING_KEYS = {"load", "insertion", "embedding", "setup", "propagation", "cutting", "repair", "output", "lloyd",
               "end_to_end"}


# ---------------------------------------------------------------- inputs

def read_off(path):
    with open(path) as f:
        tokens = []
        for line in f:
            line = line.split("#", 1)[0]
            tokens.extend(line.split())
    if tokens[0] != "OFF":
        raise SystemExit(path + ": not an OFF file")
    nv, nf = int(tokens[1]), int(tokens[2])
    pos = 4
    points = []
    for _ in range(nv):
        points.append(tuple(float(t) for t in tokens[pos:pos + 3]))
        pos += 3
    faces = []
    for _ in range(nf):
        k = int(tokens[pos])
        faces.append(tuple(int(t) for t in tokens[pos + 1:pos + 1 + k]))
        pos += 1 + k
    return points, faces


def triangle_area(p, q, r):
    u = (q[0] - p[0], q[1] - p[1], q[2] - p[2])
    w = (r[0] - p[0], r[1] - p[1], r[2] - p[2])
    c = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
    return 0.5 * math.sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2])


class Lcg:
    """64-bit linear congruential generator (Knuth's MMIX constants): the same numbers anywhere."""

    def __init__(self, seed):
        self.state = (seed * 2862933555777941757 + 3037000493) % (1 << 64)

    def uniform(self):
        self.state = (self.state * 6364136223846793005 + 1442695040888963407) % (1 << 64)
        return (self.state >> 11) / float(1 << 53)


def fan_triangles(faces):
    for f in faces:
        for k in range(1, len(f) - 1):
            yield (f[0], f[k], f[k + 1])


def sample_sites(points, faces, n, seed, weight_scale=0.0):
    """n area-uniform points; with weight_scale > 0 a 4th column in [0, weight_scale * A/n)."""
    tris = list(fan_triangles(faces))
    cumulative = []
    total = 0.0
    for t in tris:
        total += triangle_area(points[t[0]], points[t[1]], points[t[2]])
        cumulative.append(total)
    rng = Lcg(seed)
    lines = []
    for _ in range(n):
        x = rng.uniform() * total
        lo, hi = 0, len(cumulative) - 1
        while lo < hi:
            mid = (lo + hi) // 2
            if cumulative[mid] <= x:
                lo = mid + 1
            else:
                hi = mid
        a, b, c = (points[i] for i in tris[lo])
        r1 = math.sqrt(rng.uniform())
        r2 = rng.uniform()
        w = (1 - r1, r1 * (1 - r2), r1 * r2)
        p = [w[0] * a[j] + w[1] * b[j] + w[2] * c[j] for j in range(3)]
        fields = [repr(v) for v in p]
        if weight_scale > 0:
            fields.append(repr(weight_scale * total / n * rng.uniform()))
        lines.append(" ".join(fields))
    return "# generated by run_matrix.py\n" + "\n".join(lines) + "\n"


def breaklines(points, faces):
    """The edges between the faces whose centroid lies below the median x and the others: a
    closed cut across the surface."""
    xs = sorted(sum(points[i][0] for i in f) / len(f) for f in faces)
    x0 = xs[len(xs) // 2]
    side = {}
    pairs = set()
    for f in faces:
        below = sum(points[i][0] for i in f) / len(f) < x0
        for k in range(len(f)):
            e = (min(f[k], f[(k + 1) % len(f)]), max(f[k], f[(k + 1) % len(f)]))
            if e in side and side[e] != below:
                pairs.add(e)
            side[e] = below
    return "# generated by run_matrix.py\n" + "".join("%d %d\n" % e for e in sorted(pairs))


# ---------------------------------------------------------------- the matrix

METRICS = ["biharmonic", "euclidean", "rvd", "geodesic"]


def entries_for(mesh_name, real):
    """(name, inputs, arguments, outputs) for one mesh."""
    out = []

    def add(name, args, outputs=("out.ply", "sites.xyz")):
        out.append(("%s/%s" % (mesh_name, name), args, outputs))

    for n in (100, 2000):
        for m in METRICS:
            add("%s/n%d" % (m, n), ["--sites", "@sites%d" % n, "--metric", m] +
                (["--dual", "dual.off"] if n == 2000 else []),
                ("out.ply", "sites.xyz", "dual.off") if n == 2000 else ("out.ply", "sites.xyz"))
    for m in METRICS:
        add("%s/power" % m, ["--sites", "@sites100b" if m == "biharmonic" else "@sites100w", "--metric", m])
    for m in ("biharmonic", "euclidean", "geodesic"):
        add("%s/breaklines" % m, ["--sites", "@sites100", "--metric", m, "--breaklines", "@breaklines"])
    if not real:
        for m in ("biharmonic", "euclidean", "geodesic"):
            add("%s/insert" % m, ["--sites", "@sites100", "--metric", m, "--insert-sites"])
    if not real:
        # sites drawn on the creases first, kept by Lloyd, and the remesh along them
        for m in ("biharmonic", "euclidean", "geodesic"):
            add("%s/features" % m, ["--blue-noise", "300", "--seed", "1", "--metric", m, "--sharp-edges", "45",
                                    "--lloyd", "3", "--dual", "dual.off"], ("out.ply", "sites.xyz", "dual.off"))
    if not real:
        # the full spectrum (Biharmonic_green_metric): many sites, and the program's stages
        # sharing it (Lloyd, sites added for a valid dual, the final diagram)
        add("biharmonic_full/n2000", ["--sites", "@sites2000", "--metric", "biharmonic", "--dimension", "full",
                                      "--dual", "dual.off"], ("out.ply", "sites.xyz", "dual.off"))
        add("biharmonic_full/lloyd", ["--sites", "@sites100", "--metric", "biharmonic", "--dimension", "full",
                                      "--lloyd", "5", "--dual", "dual.off", "--valid-dual"],
            ("out.ply", "sites.xyz", "dual.off"))
    for m in METRICS if not real else ("biharmonic", "euclidean"):
        add("%s/lloyd" % m, ["--sites", "@sites100", "--metric", m, "--lloyd", "5", "--dual", "dual.off"],
            ("out.ply", "sites.xyz", "dual.off"))
    return out


def meshes(data_dir):
    found = [("lampshade_thin", os.path.join(SOURCE, "examples", "Surface_voronoi_diagram", "data", "lampshade_thin.off"), False)]
    for name in ("u_fold", "box", "torus"):
        found.append((name, os.path.join(HERE, "meshes", name + ".off"), False))
    real = []
    if data_dir and os.path.isdir(data_dir):
        for f in sorted(os.listdir(data_dir)):
            if f.endswith(".off"):
                real.append(("real_" + f[:-4], os.path.join(data_dir, f), True))
    return found, real


def prepare_inputs(mesh_name, path, work):
    folder = os.path.join(work, "inputs", mesh_name)
    os.makedirs(folder, exist_ok=True)
    points, faces = read_off(path)
    files = {
        "sites100": sample_sites(points, faces, 100, 1),
        "sites2000": sample_sites(points, faces, 2000, 2),
        "sites100w": sample_sites(points, faces, 100, 3, 0.3),
        # biharmonic distances are about 20 times smaller than lengths: weights 400 times smaller
        "sites100b": sample_sites(points, faces, 100, 3, 0.3 / 400),
        "breaklines": breaklines(points, faces),
    }
    paths = {}
    for key, text in files.items():
        p = os.path.join(folder, key + ".txt")
        with open(p, "w") as f:
            f.write(text)
        paths[key] = p
    return paths


# ---------------------------------------------------------------- bit equality inside one run

# Entries run twice more: with --threads 1 against the record's --threads 2, and again with
# --sites on the sites file the first run wrote. Both reruns must give the same bytes.
BIT_CHECKS = {
    "lampshade_thin/euclidean/n2000": ("threads", "roundtrip"),
    "box/biharmonic/power": ("threads", "roundtrip"),
    "torus/geodesic/breaklines": ("threads", "roundtrip"),
    "u_fold/biharmonic_full/lloyd": ("threads", "roundtrip"),
    "torus/rvd/n2000": ("threads",),
    "real_fertility/biharmonic/n2000": ("threads", "roundtrip"),
}
# what the round trip drops: the options that make or move the sites
SITE_OPTIONS = {"--sites": 1, "--random": 1, "--blue-noise": 1, "--seed": 1, "--lloyd": 1, "--valid-dual": 0,
                "--sharp-edges": 1}


def roundtrip_arguments(args):
    kept, k = [], 0
    while k < len(args):
        if args[k] in SITE_OPTIONS:
            k += 1 + SITE_OPTIONS[args[k]]
        else:
            kept.append(args[k])
            k += 1
    return kept


# ---------------------------------------------------------------- records

TINY_AREA = 1e-12    # pieces below this fraction of the surface area own nothing
SHORT_EDGE = 1e-9    # shared sides below this fraction of sqrt(surface area) make no neighbours
AREA_TOLERANCE = 1e-9   # per-site areas, absolute, as a fraction of the surface area
AREA_UNIT = 1e-10       # areas are recorded as integers in this fraction of the surface area
RELATIVE = 1e-6      # floating --stats values
FLOAT_STATS = {"surface_area", "mean_candidates_per_face"}   # and lloyd_energy_*
AREA_STATS = {"unreached_area"}                              # compared like the areas


def sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def short_hash(text):
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def histogram(values):
    counts = {}
    for v in values:
        counts[v] = counts.get(v, 0) + 1
    """value:count,... in increasing value"""
    return ",".join("%d:%d" % (v, counts[v]) for v in sorted(counts))


def read_arrangement(path):
    """Points, faces (vertex ids, site, input face) of the program's binary PLY."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    if "format binary_little_endian 1.0" not in header:
        raise ValueError("not a binary little-endian PLY")
    nv = nf = 0
    face_props = []
    element = None
    for line in header:
        w = line.split()
        if w[:1] == ["element"]:
            element = w[1]
            if w[1] == "vertex":
                nv = int(w[2])
            if w[1] == "face":
                nf = int(w[2])
        elif w[:1] == ["property"] and element == "face":
            face_props.append(w[-1])
    if face_props[:7] != ["vertex_indices", "site", "red", "green", "blue", "alpha", "input_face"]:
        raise ValueError("face properties " + " ".join(face_props))
    pts = struct.unpack_from("<%dd" % (3 * nv), data, end)
    pos = end + 24 * nv
    faces = []
    layouts = {}   # per number of vertices: ids, site, colour, input face
    for _ in range(nf):
        k = data[pos]
        layout = layouts.get(k)
        if layout is None:
            layout = layouts[k] = struct.Struct("<%dii4Bi" % k)
        w = layout.unpack_from(data, pos + 1)
        pos += 1 + layout.size
        faces.append((w[:k], w[k], w[-1]))
    return pts, faces


def polygon_area(pts, v):
    """Area of a planar polygon (fan from its first vertex: the pieces are convex)."""
    i = 3 * v[0]
    px, py, pz = pts[i], pts[i + 1], pts[i + 2]
    sx = sy = sz = 0.0
    for j in range(1, len(v) - 1):
        a, b = 3 * v[j], 3 * v[j + 1]
        ux, uy, uz = pts[a] - px, pts[a + 1] - py, pts[a + 2] - pz
        wx, wy, wz = pts[b] - px, pts[b + 1] - py, pts[b + 2] - pz
        sx += uy * wz - uz * wy
        sy += uz * wx - ux * wz
        sz += ux * wy - uy * wx
    return 0.5 * math.sqrt(sx * sx + sy * sy + sz * sz)


def arrangement_records(path):
    """The record lines of what must not change in the arrangement: per input face its owners,
    per cell its pieces and neighbours, per site its area."""
    pts, faces = read_arrangement(path)
    areas = [polygon_area(pts, v) for v, _, _ in faces]
    total = math.fsum(areas)
    tiny = TINY_AREA * total
    short2 = (SHORT_EDGE * SHORT_EDGE) * total

    # per input face, the sites owning its pieces (-1: no site reaches)
    owners = {}
    for (v, site, f), a in zip(faces, areas):
        if a >= tiny:
            owners.setdefault(f, set()).add(site)
    text = ";".join("%d:%s" % (f, ",".join(str(s) for s in sorted(owners[f]))) for f in sorted(owners))
    lines = ["owners: faces=%d owners_per_face=%s sha256=%s" % (
        len(owners), histogram(len(o) for o in owners.values()), short_hash(text))]

    # per cell, its pieces (edge-connected parts of its faces) and its neighbours
    parent = list(range(len(faces)))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    # the arrangement is a polygon mesh: a side has one face, or two sharing its vertex ids
    open_sides = {}
    pairs = set()
    nv = len(pts) // 3
    for i, (v, si, _) in enumerate(faces):
        n = len(v)
        for j in range(n):
            a, b = v[j], v[j + 1 if j + 1 < n else 0]
            key = a * nv + b if a < b else b * nv + a
            other = open_sides.pop(key, None)
            if other is None:
                open_sides[key] = i
                continue
            sj = faces[other][1]
            if si == sj:
                ri, rj = find(i), find(other)
                if ri != rj:
                    parent[ri] = rj
            elif si >= 0 and sj >= 0:
                pair = (si, sj) if si < sj else (sj, si)
                if pair not in pairs and areas[i] >= tiny and areas[other] >= tiny:
                    d2 = (pts[3 * a] - pts[3 * b]) ** 2 + (pts[3 * a + 1] - pts[3 * b + 1]) ** 2 + \
                         (pts[3 * a + 2] - pts[3 * b + 2]) ** 2
                    if d2 >= short2:
                        pairs.add(pair)
    site_count = 1 + max([s for _, s, _ in faces] + [-1])
    roots = [set() for _ in range(site_count)]
    site_area = [[] for _ in range(site_count)]
    unreached = []
    for i, (_, s, _) in enumerate(faces):
        if s >= 0:
            roots[s].add(find(i))
            site_area[s].append(areas[i])
        else:
            unreached.append(areas[i])
    pieces = [len(r) for r in roots]
    lines.append("cell_pieces: pieces_per_cell=%s cells_not_one_piece=%s" % (
        histogram(pieces), ",".join("%d:%d" % (s, n) for s, n in enumerate(pieces) if n != 1) or "none"))
    degree = [0] * site_count
    for s, t in pairs:
        degree[s] += 1
        degree[t] += 1
    text = ";".join("%d-%d" % p for p in sorted(pairs))
    lines.append("neighbours: pairs=%d degrees=%s sha256=%s" % (len(pairs), histogram(degree), short_hash(text)))

    # per site, its area in units of AREA_UNIT * surface area
    unit = AREA_UNIT * total
    lines.append("areas: unreached=%d sites=%s" % (
        round(math.fsum(unreached) / unit), " ".join(str(round(math.fsum(a) / unit)) for a in site_area)))
    return lines


def run_program(program, argv_tail, folder):
    os.makedirs(folder, exist_ok=True)
    for o in ("out.ply", "sites.xyz", "dual.off"):
        if os.path.exists(os.path.join(folder, o)):
            os.remove(os.path.join(folder, o))
    return subprocess.run([program] + argv_tail + ["--output", "out.ply", "--sites-out", "sites.xyz", "--stats"],
                          cwd=folder, stdout=subprocess.PIPE, stderr=subprocess.PIPE)


def same_bytes(folder_a, folder_b, outputs):
    """'same' or the outputs whose bytes differ between two runs."""
    differ = [o for o in outputs if not (os.path.exists(os.path.join(folder_a, o)) and os.path.exists(os.path.join(folder_b, o))
                                         and sha256(os.path.join(folder_a, o)) == sha256(os.path.join(folder_b, o)))]
    return "same" if not differ else "differ:" + ",".join(differ)


def run_entry(program, name, args, outputs, inputs, work):
    folder = os.path.join(work, "out", name)
    mesh_path = inputs["@mesh"]

    def argv_of(arguments):
        return [mesh_path] + [inputs[a[1:]] if a.startswith("@") else a for a in arguments]

    checks = BIT_CHECKS.get(name, ())
    if checks:
        args = args + ["--threads", "2"]
    r = run_program(program, argv_of(args), folder)
    lines = ["[%s]" % name, "arguments: " + " ".join(args), "exit: %d" % r.returncode]
    err = r.stderr.decode("utf-8", "replace").replace(mesh_path, "MESH").strip().splitlines()
    lines.append("stderr: " + (err[0] if err else ""))
    stats = []
    for line in r.stdout.decode().splitlines():
        if ":" in line:
            k, v = line.split(":", 1)
            if k.strip() not in TIMING_KEYS and not k.startswith("lloyd_step_"):
                stats.append("%s=%s" % (k.strip(), v.strip()))
    lines.append("stats: " + " ".join(stats))
    lines.append("files: " + " ".join(o for o in outputs if os.path.exists(os.path.join(folder, o))))
    if os.path.exists(os.path.join(folder, "out.ply")):
        lines.extend(arrangement_records(os.path.join(folder, "out.ply")))
    if "threads" in checks:
        run_program(program, argv_of(args[:-2] + ["--threads", "1"]), os.path.join(folder, "threads1"))
        lines.append("threads_1_vs_2: " + same_bytes(folder, os.path.join(folder, "threads1"), outputs))
    if "roundtrip" in checks:
        again = ["--sites", os.path.join(folder, "sites.xyz")] + roundtrip_arguments(args)
        run_program(program, argv_of(again), os.path.join(folder, "roundtrip"))
        lines.append("sites_out_roundtrip: " + same_bytes(folder, os.path.join(folder, "roundtrip"), outputs))
    return lines


# ---------------------------------------------------------------- comparison

def fields(line):
    """'key: a=1 b=2 rest' as (key, {a: 1, b: 2}, [rest])."""
    key, _, value = line.partition(": ")
    named, loose = {}, []
    for w in value.split():
        if "=" in w:
            k, _, v = w.partition("=")
            named[k] = v
        else:
            loose.append(w)
    return key, named, loose


def close(a, b, tolerance):
    return abs(a - b) <= tolerance


def compare_stats(old, new, surface_area):
    _, o, _ = fields(old)
    _, n, _ = fields(new)
    problems = []
    for k in sorted(set(o) | set(n)):
        if k not in o or k not in n:
            problems.append("%s only in the %s" % (k, "record" if k in o else "run"))
            continue
        if k in FLOAT_STATS or k.startswith("lloyd_energy_"):
            a, b = float(o[k]), float(n[k])
            ok = close(a, b, RELATIVE * max(abs(a), abs(b)))
        elif k in AREA_STATS:
            ok = close(float(o[k]), float(n[k]), AREA_TOLERANCE * surface_area)
        else:
            ok = o[k] == n[k]
        if not ok:
            problems.append("%s: %s, now %s" % (k, o[k], n[k]))
    return problems


def compare_areas(old, new):
    """Per-site areas within AREA_TOLERANCE of the surface area (each side rounded to AREA_UNIT)."""
    _, o, _ = fields(old)
    _, n, _ = fields(new)
    old_sites = old.split(" sites=", 1)[1].split() if " sites=" in old else []
    new_sites = new.split(" sites=", 1)[1].split() if " sites=" in new else []
    if len(old_sites) != len(new_sites):
        return ["%d sites, now %d" % (len(old_sites), len(new_sites))]
    limit = AREA_TOLERANCE / AREA_UNIT + 1   # the tolerance, and the two roundings
    problems = []
    if abs(int(o["unreached"]) - int(n["unreached"])) > limit:
        problems.append("unreached %s, now %s" % (o["unreached"], n["unreached"]))
    for s, (x, y) in enumerate(zip(old_sites, new_sites)):
        if abs(int(x) - int(y)) > limit:
            problems.append("site %d: %s, now %s (units of %g of the surface area)" % (s, x, y, AREA_UNIT))
    return problems


def compare_records(old, new):
    """The differences that matter between a recorded entry and this run (empty: it passes)."""
    o = dict(line.partition(": ")[::2] for line in old)
    n = dict(line.partition(": ")[::2] for line in new)
    problems = []
    surface_area = 0.0
    if "stats" in n:
        surface_area = float(fields("stats: " + n["stats"])[1].get("surface_area", "0"))
    for key in list(o) + [k for k in n if k not in o]:
        if key not in o or key not in n:
            problems.append("%s: %s" % (key, "missing in this run" if key in o else "not recorded"))
        elif key == "stats":
            problems.extend("stats " + p for p in compare_stats("stats: " + o[key], "stats: " + n[key], surface_area))
        elif key == "areas":
            problems.extend("areas " + p for p in compare_areas("areas: " + o[key], "areas: " + n[key]))
        elif o[key] != n[key]:
            problems.append("%s\n        expected %s\n        got      %s" % (key, o[key][:300], n[key][:300]))
    return problems


def parse_records(text):
    records = {}
    current = None
    for line in text.splitlines():
        if line.startswith("[") and line.endswith("]"):
            current = line[1:-1]
            records[current] = []
        elif current is not None and line.strip():
            records[current].append(line)
    return records


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("program")
    ap.add_argument("--record", action="store_true")
    ap.add_argument("--data", default=os.path.join(SOURCE, "..", "shared", "data", "meshes"))
    ap.add_argument("--work", default=os.path.join(SOURCE, "build", "regression"))
    ap.add_argument("--only", default="")
    ap.add_argument("--part", default="1/1")
    ap.add_argument("--keep", action="store_true")
    a = ap.parse_args()
    part, parts = (int(x) for x in a.part.split("/"))
    if not 1 <= part <= parts:
        raise SystemExit("--part K/N needs 1 <= K <= N")
    program = os.path.abspath(a.program)
    work = os.path.abspath(a.work)

    expected = parse_records(open(EXPECTED).read()) if os.path.exists(EXPECTED) else {}
    generated, real = meshes(a.data)
    produced = {}
    failed = []
    chosen = set()
    index = 0
    for mesh_name, path, is_real in generated + real:
        for e in entries_for(mesh_name, is_real):
            if a.only in e[0]:
                if index % parts == part - 1:
                    chosen.add(e[0])
                index += 1
    for mesh_name, path, is_real in generated + real:
        plan = [e for e in entries_for(mesh_name, is_real) if e[0] in chosen]
        if not plan:
            continue
        inputs = prepare_inputs(mesh_name, path, work)
        inputs["@mesh"] = path
        for name, args, outputs in plan:
            lines = run_entry(program, name, args, outputs, inputs, work)
            produced[name] = lines[1:]
            problems = compare_records(expected[name], lines[1:]) if name in expected else None
            state = "new" if problems is None else ("CHANGED" if problems else "ok")
            print("%-7s %s" % (state, name), flush=True)
            if problems:
                failed.append(name)
                for p in problems[:20]:
                    print("    " + p)
                if len(problems) > 20:
                    print("    ... %d more" % (len(problems) - 20))
            if not a.keep:
                for sub in ("", "threads1", "roundtrip"):
                    for o in outputs:
                        p = os.path.join(work, "out", name, sub, o)
                        if os.path.exists(p):
                            os.remove(p)

    if a.record:
        merged = dict(expected)
        merged.update(produced)
        with open(EXPECTED, "w") as f:
            f.write("# The regression matrix (run_matrix.py): one record per program run. Real-model\n"
                    "# entries (real_*) are compared only where the models are present.\n")
            for name in sorted(merged):
                f.write("[%s]\n" % name + "\n".join(merged[name]) + "\n\n")
        print("recorded %d entries in %s" % (len(produced), EXPECTED))
        return 0

    missing = [n for n in produced if n not in expected]
    skipped = [n for n in expected if n not in produced and (a.only in n) and parts == 1]
    print("matrix: %d entries run, %d match, %d changed, %d not recorded, %d recorded but not run"
          % (len(produced), len(produced) - len(failed) - len(missing), len(failed), len(missing), len(skipped)))
    return 1 if failed or missing else 0


if __name__ == "__main__":
    sys.exit(main())
