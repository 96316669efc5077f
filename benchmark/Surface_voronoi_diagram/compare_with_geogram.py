#!/usr/bin/env python3
"""The program against geogram's restricted Voronoi diagram, section by section.

usage: compare_with_geogram.py --program P --harness H --data MESHES --work DIR
                               [--sections e2e,sites,lloyd,memory,threads] [--repeat R]
                               [--cases MESH:SITES,...]

Every figure is a median of R (default 3) runs per side, one process per run, the two sides
alternating. Sites files are made in DIR by make_sites.py (blue noise, seed 0, moved off the
surface), the same file for both sides; igea-537k.off (and igea-2M.off with --big) are made in
DIR from igea.off by subdivide_midpoint.py when missing.

  e2e      end to end, mesh and sites files in, cells out: the program's `end_to_end` against
           the harness's t_load + t_total_mesh (`rvd --threads 1`); the program with
           --metric euclidean --threads 1. Cases: boot, igea and igea-537k with 1k and 10k
           sites (and igea-2M with 100k with --big), or --cases.
  sites    boot with 1k to 100k sites: the program's compute (setup + propagation + cutting +
           repair) against t_total_mesh, and the slope of each over 10k-100k (log-log).
  lloyd    boot, 3,000 blue-noise sites, one thread: the median of `lloyd_step_2` to
           `lloyd_step_10` of `--lloyd 10` (euclidean, biharmonic, geodesic) against the
           median iteration of the harness's `cvt --lloyd 10 --threads 1`.
  memory   the e2e cases: each process's peak resident memory, no output written (the same runs
           as e2e when both are asked).
  threads  the program's compute with --threads 2 against --threads 1 (igea and igea-537k,
           10k sites); geogram's RVD uses one thread.
"""
import argparse
import math
import os
import re
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def run(argv):
    """stdout and the peak resident memory (MB) of one process."""
    p = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    out = p.stdout.read()
    _, status, usage = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    if p.returncode != 0:
        sys.exit("failed (%d): %s" % (p.returncode, " ".join(argv)))
    return out, usage.ru_maxrss / 1024.0


def harness_rvd(harness, mesh, sites):
    out, peak = run([harness, "rvd", mesh, sites, "--threads", "1", "--repeat", "1"])
    line = [x for x in out.splitlines() if x.startswith("RESULT")][-1]
    value = dict(re.findall(r"(\w+)=([^\s]+)", line))
    return float(value["t_load"]), float(value["t_total_mesh"]), peak


def program_stats(program, mesh, args):
    out, peak = run([program, mesh] + args + ["--stats"])
    stats = dict(re.findall(r"^(\w+): (\S+)$", out, re.M))
    return stats, peak


def compute_of(stats):
    return sum(float(stats[k]) for k in ("setup", "propagation", "cutting", "repair"))


def median_pairs(repeat, first, second):
    a, b = [], []
    for _ in range(repeat):
        a.append(first())
        b.append(second())
    return a, b


def load():
    return " ".join(open("/proc/loadavg").read().split()[:3])


class Inputs:
    def __init__(self, args):
        self.args = args
        os.makedirs(args.work, exist_ok=True)

    def mesh(self, name):
        path = os.path.join(self.args.data, name)
        if os.path.exists(path):
            return path
        path = os.path.join(self.args.work, name)
        if not os.path.exists(path):
            source = {"igea-537k.off": "igea.off", "igea-2M.off": "igea-537k.off"}[name]
            subprocess.run([sys.executable, os.path.join(HERE, "subdivide_midpoint.py"), self.mesh(source), path],
                           check=True)
        return path

    def sites(self, mesh_name, n):
        path = os.path.join(self.args.work, "%s_%d.txt" % (os.path.splitext(mesh_name)[0], n))
        if not os.path.exists(path):
            subprocess.run([sys.executable, os.path.join(HERE, "make_sites.py"), self.args.program,
                            self.mesh(mesh_name), str(n), path], check=True)
        return path


def e2e_cases(args, inputs):
    if args.cases:
        return [tuple(c.split(":")) for c in args.cases.split(",")]
    names = [("boot.off", 1000), ("boot.off", 10000), ("igea.off", 1000), ("igea.off", 10000),
             ("igea-537k.off", 1000), ("igea-537k.off", 10000)]
    if args.big:
        names.append(("igea-2M.off", 100000))
    return [(inputs.mesh(m), inputs.sites(m, n)) for m, n in names]


def count_lines(path):
    return sum(1 for line in open(path) if line.strip())


def section_e2e(args, inputs, times, memory):
    """The e2e cases, run once: their end to end times and their peak memory, as asked."""
    euclid = ["--metric", "euclidean", "--threads", "1"]
    rows_time, rows_memory = [], []
    for mesh, sites in e2e_cases(args, inputs):
        theirs, ours = median_pairs(args.repeat, lambda: harness_rvd(args.harness, mesh, sites),
                                    lambda: program_stats(args.program, mesh, ["--sites", sites] + euclid))
        name, count = os.path.basename(mesh), count_lines(sites)
        a = statistics.median(float(s["end_to_end"]) for s, _ in ours)
        b = statistics.median(l + t for l, t, _ in theirs)
        rows_time.append("| %s | %d | %.3f | %.3f | %.2f |" % (name, count, a, b, a / b))
        a = statistics.median(p for _, p in ours)
        b = statistics.median(p for _, _, p in theirs)
        rows_memory.append("| %s | %d | %.1f | %.1f | %.2f |" % (name, count, a, b, a / b))
    for wanted, title, rows in ((times, "End to end (s), one thread", rows_time),
                                (memory, "Peak memory (MB), end to end, no output", rows_memory)):
        if wanted:
            print("\n## %s\n" % title)
            print("| mesh | sites | ours | geogram | ours / geogram |")
            print("|---|---|---|---|---|")
            print("\n".join(rows))
    sys.stdout.flush()


def slope(xs, ys):
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = statistics.mean(lx), statistics.mean(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)


def section_sites(args, inputs):
    print("\n## Compute against the number of sites, boot, one thread (s)\n")
    print("| sites | ours | geogram | ours / geogram |")
    print("|---|---|---|---|")
    mesh = inputs.mesh("boot.off")
    counts = [1000, 3000, 10000, 30000, 100000]
    a_all, b_all = [], []
    for n in counts:
        sites = inputs.sites("boot.off", n)
        theirs, ours = median_pairs(args.repeat, lambda: harness_rvd(args.harness, mesh, sites),
                                    lambda: program_stats(args.program, mesh,
                                                          ["--sites", sites, "--metric", "euclidean", "--threads", "1"]))
        a = statistics.median(compute_of(s) for s, _ in ours)
        b = statistics.median(t for _, t, _ in theirs)
        a_all.append(a)
        b_all.append(b)
        print("| %d | %.3f | %.3f | %.2f |" % (n, a, b, a / b))
        sys.stdout.flush()
    print("\nslope over 10k-100k sites (log-log): ours %.3f, geogram %.3f"
          % (slope(counts[2:], a_all[2:]), slope(counts[2:], b_all[2:])))


def section_lloyd(args, inputs):
    print("\n## One Lloyd step, boot, 3,000 sites, one thread (s)\n")
    print("| metric | ours | geogram (Euclidean CVT) | ours / geogram |")
    print("|---|---|---|---|")
    mesh = inputs.mesh("boot.off")

    def theirs():
        out, _ = run([args.harness, "cvt", mesh, "3000", "--lloyd", "10", "--threads", "1"])
        return float(re.search(r"t_iter_median=(\S+)", out).group(1))

    for metric in ("euclidean", "biharmonic", "geodesic"):
        def ours():
            stats, _ = program_stats(args.program, mesh, ["--blue-noise", "3000", "--metric", metric, "--threads", "1",
                                                          "--lloyd", "10"])
            return statistics.median(float(stats["lloyd_step_%d" % k]) for k in range(2, 11))
        b, a = median_pairs(args.repeat, theirs, ours)
        a, b = statistics.median(a), statistics.median(b)
        print("| %s | %.4f | %.4f | %.2f |" % (metric, a, b, a / b))
        sys.stdout.flush()


def section_threads(args, inputs):
    print("\n## Two threads against one, compute (s)\n")
    print("| mesh | sites | one thread | two threads | speed-up |")
    print("|---|---|---|---|---|")
    for name in ("igea.off", "igea-537k.off"):
        mesh, sites = inputs.mesh(name), inputs.sites(name, 10000)
        base = ["--sites", sites, "--metric", "euclidean"]
        one, two = median_pairs(args.repeat, lambda: program_stats(args.program, mesh, base + ["--threads", "1"]),
                                lambda: program_stats(args.program, mesh, base + ["--threads", "2"]))
        a = statistics.median(compute_of(s) for s, _ in one)
        b = statistics.median(compute_of(s) for s, _ in two)
        print("| %s | %d | %.3f | %.3f | %.2f |" % (name, count_lines(sites), a, b, a / b))
        sys.stdout.flush()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--program", required=True)
    parser.add_argument("--harness", required=True)
    parser.add_argument("--data", required=True, help="folder of boot.off and igea.off")
    parser.add_argument("--work", required=True, help="folder for made meshes and sites files")
    parser.add_argument("--sections", default="e2e,sites,lloyd,memory,threads")
    parser.add_argument("--cases", default="", help="MESH:SITES,... for e2e and memory instead of the default cases")
    parser.add_argument("--big", action="store_true", help="add igea-2M with 100k sites to e2e and memory")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    inputs = Inputs(args)
    print("load average before: %s; medians of %d runs per side" % (load(), args.repeat))
    sections = args.sections.split(",")
    for section in sections:
        if section in ("e2e", "memory"):
            # one set of runs gives both tables, printed where the first of them is asked
            if section == next(x for x in sections if x in ("e2e", "memory")):
                section_e2e(args, inputs, "e2e" in sections, "memory" in sections)
            continue
        {"sites": lambda: section_sites(args, inputs), "lloyd": lambda: section_lloyd(args, inputs),
         "threads": lambda: section_threads(args, inputs)}[section]()
    print("\nload average after: %s" % load())


if __name__ == "__main__":
    main()
