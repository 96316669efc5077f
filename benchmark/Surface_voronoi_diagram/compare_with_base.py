#!/usr/bin/env python3
"""This tree's surface_voronoi program against a base commit's, interleaved.

usage: compare_with_base.py --program NEW --base-program OLD --data DIR [--work DIR]
                            [--repeat 3] [--new-threads 1]
                            [--sections diagram,sites,meshes,lloyd,biharmonic,geodesic,threads]
                            [--out FILE.md | --out -] [--quick]
       compare_with_base.py --build-base COMMIT --base-dir DIR   (a git worktree, Release build)

The report goes to results/compare_with_base.md beside this script unless --out names another
file (or '-': print only); it is also printed section by section as the runs go.

Each configuration runs the two programs alternately (new, old, new, old, ...) `--repeat`
times on the same mesh and the same `--random N --seed 1` sites, with `--output` written,
and reports each stage's median (the program's `--stats`), the whole-process wall time, the
peak RSS (from /usr/bin/time), and the ratio new / old. "compute" is what follows loading and
the embedding: setup + propagation + cutting + repair. Slopes are least-squares fits of
log(compute) against log(sites) or log(faces). The machine's load average is printed with
the table, since timings on a shared machine are noisy.

Meshes come from the data folder (boot.off, igea.off); igea-537k and igea-2M are made once in
the work folder by subdivide_midpoint.py (one and two 1-to-4 midpoint subdivisions).
"""
import argparse
import math
import os
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
STAGES = ["load", "embedding", "setup", "propagation", "cutting", "repair", "output"]
COMPUTE = ["setup", "propagation", "cutting", "repair"]


def build_base(commit, base_dir):
    source = os.path.abspath(os.path.join(HERE, "..", ".."))
    if not os.path.isdir(base_dir):
        subprocess.check_call(["git", "-C", source, "worktree", "add", "--detach", base_dir, commit])
    build = os.path.join(base_dir, "build", "release")
    subprocess.check_call(["cmake", "-S", base_dir, "-B", build, "-DCMAKE_BUILD_TYPE=Release"])
    subprocess.check_call(["cmake", "--build", build, "-j2", "--target", "surface_voronoi"])
    print(os.path.join(build, "surface_voronoi"))


def meshes(data, work, wanted):
    paths = {"boot": os.path.join(data, "boot.off"), "igea": os.path.join(data, "igea.off")}
    for name, times in (("igea-537k", 1), ("igea-2M", 2)):
        if name not in wanted:
            continue
        path = os.path.join(work, name + ".off")
        if not os.path.exists(path):
            subprocess.check_call([sys.executable, os.path.join(HERE, "subdivide_midpoint.py"), paths["igea"], path,
                                   "--times", str(times)])
        paths[name] = path
    return paths


def faces_of(path):
    with open(path) as f:
        f.readline()
        return int(f.readline().split()[1])


def run_once(program, mesh, args, work):
    out = os.path.join(work, "out.ply")
    argv = ["/usr/bin/time", "-f", "peak_kb %M", program, mesh] + args + ["--output", out, "--stats"]
    start = time.monotonic()
    r = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    wall = time.monotonic() - start
    if r.returncode != 0:
        raise RuntimeError("%s failed (exit %d): %s" % (" ".join(argv), r.returncode, r.stderr.strip()[-300:]))
    stats = {"wall": wall}
    for line in (r.stdout + "\n" + r.stderr).splitlines():
        key, _, value = line.partition(":") if ":" in line else line.partition(" ")
        key = key.strip()
        if key in STAGES or key == "lloyd":
            stats[key] = float(value)
        elif line.startswith("peak_kb"):
            stats["peak_mib"] = float(line.split()[1]) / 1024
    stats["compute"] = sum(stats.get(k, 0.0) for k in COMPUTE)
    return stats


# extra arguments of both programs (--threads), set from the command line: the base runs on
# as many threads as the new program, since both default to all cores
NEW_ARGS = []


def compare(new, old, mesh, args, repeat, work, new_args=None, old_args=None):
    runs = {"new": [], "old": []}
    new_args = NEW_ARGS if new_args is None else new_args
    old_args = NEW_ARGS if old_args is None else old_args
    for _ in range(repeat):
        runs["new"].append(run_once(new, mesh, args + list(new_args), work))
        runs["old"].append(run_once(old, mesh, args + list(old_args), work))
    med = {}
    for side, rs in runs.items():
        keys = set().union(*rs)
        med[side] = {k: statistics.median(r.get(k, 0.0) for r in rs) for k in keys}
    return med


def ratio(a, b):
    return "%.2f" % (a / b) if b > 0 else "-"


def table(rows, keys):
    lines = ["| config | " + " | ".join("%s new / old (ratio)" % k for k in keys) + " |",
             "|---|" + "---|" * len(keys)]
    for name, med in rows:
        cells = []
        for k in keys:
            a, b = med["new"].get(k, 0.0), med["old"].get(k, 0.0)
            unit = "" if k == "peak_mib" else " s"
            fmt = "%.0f" if k == "peak_mib" else "%.3f"
            cells.append((fmt + " / " + fmt + "%s (%s)") % (a, b, unit, ratio(a, b)))
        lines.append("| %s | %s |" % (name, " | ".join(cells)))
    return "\n".join(lines)


def slope(xs, ys):
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    den = sum((x - mx) ** 2 for x in lx)
    return sum((x - mx) * (y - my) for x, y in zip(lx, ly)) / den if den > 0 else float("nan")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--program")
    p.add_argument("--base-program")
    p.add_argument("--data")
    p.add_argument("--work", default="/tmp/svd_compare")
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--sections", default="diagram,sites,meshes,lloyd,biharmonic,geodesic,threads")
    p.add_argument("--new-threads", type=int, default=1,
                   help="--threads for both programs in the comparisons with the base (default 1: the goals are single-threaded)")
    p.add_argument("--out", default=os.path.join(HERE, "results", "compare_with_base.md"),
                   help="markdown report (default: results/compare_with_base.md beside this script; '-': print only)")
    p.add_argument("--quick", action="store_true", help="boot only, one repetition")
    p.add_argument("--build-base")
    p.add_argument("--base-dir")
    a = p.parse_args()
    if a.build_base:
        build_base(a.build_base, a.base_dir)
        return
    if not (a.program and a.base_program and a.data):
        p.error("--program, --base-program and --data are needed")
    os.makedirs(a.work, exist_ok=True)
    NEW_ARGS[:] = ["--threads", str(a.new_threads)]
    sections = a.sections.split(",")
    repeat = 1 if a.quick else a.repeat
    big = [] if a.quick else ["igea-537k", "igea-2M"]
    paths = meshes(a.data, a.work, big)
    report = ["# Comparison with the base program", "",
              "new: `%s --threads %d`, old: `%s` (the same threads); %d interleaved run(s) each, medians; load average before: %s" % (
                  a.program, a.new_threads, a.base_program, repeat, " ".join("%.2f" % x for x in os.getloadavg())), ""]

    def section(title, rows, keys):
        report.extend(["## " + title, "", table(rows, keys), ""])
        print("\n".join(report[-4:]), flush=True)

    stage_keys = ["compute", "load", "propagation", "cutting", "repair", "output", "wall", "peak_mib"]
    if "diagram" in sections:
        rows = []
        for name in ["boot", "igea"] + [m for m in big if m != "igea-2M"]:
            rows.append(("%s, Euclidean, 10k" % name,
                         compare(a.program, a.base_program, paths[name], ["--random", "10000", "--seed", "1", "--metric", "euclidean"],
                                 repeat, a.work)))
        section("Euclidean diagram, 10k sites", rows, stage_keys)
    if "sites" in sections:
        rows, xs, ys_new, ys_old = [], [], [], []
        for n in ([1000, 10000] if a.quick else [1000, 3000, 10000, 30000, 100000]):
            med = compare(a.program, a.base_program, paths["boot"], ["--random", str(n), "--seed", "1", "--metric", "euclidean"],
                          repeat, a.work)
            rows.append(("boot, Euclidean, %d" % n, med))
            xs.append(n)
            ys_new.append(med["new"]["compute"])
            ys_old.append(med["old"]["compute"])
        section("Sites sweep on boot", rows, ["compute", "repair", "wall", "peak_mib"])
        report.append("slope of compute against sites: new %.3f, old %.3f\n" % (slope(xs, ys_new), slope(xs, ys_old)))
    if "meshes" in sections and not a.quick:
        rows, xs, ys_new, ys_old = [], [], [], []
        for name in ["boot", "igea", "igea-537k", "igea-2M"]:
            med = compare(a.program, a.base_program, paths[name], ["--random", "10000", "--seed", "1", "--metric", "euclidean"],
                          1 if name == "igea-2M" else repeat, a.work)
            rows.append(("%s (%d faces), Euclidean, 10k" % (name, faces_of(paths[name])), med))
            xs.append(faces_of(paths[name]))
            ys_new.append(med["new"]["compute"])
            ys_old.append(med["old"]["compute"])
        section("Mesh-size sweep, 10k sites", rows, ["compute", "load", "wall", "peak_mib"])
        report.append("slope of compute against faces: new %.3f, old %.3f\n" % (slope(xs, ys_new), slope(xs, ys_old)))
    if "lloyd" in sections:
        rows, steps = [], []
        for metric in ["euclidean", "biharmonic", "geodesic"]:
            by_count = {}
            for count in (1, 11):
                by_count[count] = compare(a.program, a.base_program, paths["boot"],
                                          ["--random", "3000", "--seed", "1", "--metric", metric, "--lloyd", str(count)], repeat, a.work)
                rows.append(("boot, %s, 3000 sites, %d Lloyd step%s" % (metric, count, "s" if count > 1 else ""), by_count[count]))
            # one step: the difference of the two runs over the ten steps between them, which
            # leaves out loading, the embedding and the final diagram (the old program may not
            # print a lloyd time: its wall times then)
            per_step = {}
            for side in ("new", "old"):
                key = "lloyd" if all("lloyd" in by_count[c][side] for c in by_count) else "wall"
                per_step[side] = ((by_count[11][side][key] - by_count[1][side][key]) / 10, key)
            steps.append("| %s | %.3f s (%s) | %.3f s (%s) | %s |" % (metric, per_step["new"][0], per_step["new"][1], per_step["old"][0],
                                                                    per_step["old"][1], ratio(per_step["new"][0], per_step["old"][0])))
        section("Lloyd", rows, ["compute", "lloyd", "embedding", "wall", "peak_mib"])
        report.append("One Lloyd step, boot, 3000 sites ((11 steps - 1 step) / 10, medians):\n\n"
                      "| metric | new | old | ratio |\n|---|---|---|---|\n" + "\n".join(steps) + "\n")
    for metric, title, keys in (("biharmonic", "Biharmonic", ["embedding", "compute", "load", "wall", "peak_mib"]),
                                ("geodesic", "Geodesic", ["compute", "load", "wall", "peak_mib"])):
        if metric not in sections:
            continue
        rows, xs, ys_new, ys_old = [], [], [], []
        for name in ["boot", "igea"] + ([] if a.quick else ["igea-537k"]):
            med = compare(a.program, a.base_program, paths[name], ["--random", "10000", "--seed", "1", "--metric", metric],
                          1 if name == "igea-537k" else repeat, a.work)
            rows.append(("%s, %s, 10k" % (name, "biharmonic d=10" if metric == "biharmonic" else metric), med))
            xs.append(faces_of(paths[name]))
            ys_new.append(med["new"].get("embedding", 0))
            ys_old.append(med["old"].get("embedding", 0))
        section(title, rows, keys)
        if metric == "biharmonic" and min(ys_new + ys_old) > 0:
            report.append("slope of the embedding time against faces: new %.3f, old %.3f\n" % (slope(xs, ys_new), slope(xs, ys_old)))
    if "threads" in sections:
        rows = []
        for name, metric in [("boot", "euclidean"), ("igea", "euclidean")] + [(m, mt) for m in big if m != "igea-2M"
                                                                            for mt in ("euclidean", "geodesic")]:
            rows.append(("%s, %s, 10k" % (name, metric),
                         compare(a.program, a.program, paths[name], ["--random", "10000", "--seed", "1", "--metric", metric],
                                 repeat, a.work, new_args=["--threads", "2"], old_args=["--threads", "1"])))
        section("Both cores: the new program on 2 threads (new) against 1 thread (old)", rows,
                ["compute", "propagation", "cutting", "repair", "wall", "peak_mib"])
    report.append("load average after: %s" % " ".join("%.2f" % x for x in os.getloadavg()))
    if a.out != "-":
        with open(a.out, "w") as f:
            f.write("\n".join(report) + "\n")


if __name__ == "__main__":
    main()
