#!/usr/bin/env python3
"""End to end against geogram's restricted Voronoi diagram: mesh file and sites file in, cells out.

usage: compare_with_geogram.py --program P --harness H --cases CASES [--repeat R] [--work DIR]

CASES: comma-separated MESH:SITES pairs (files). For each, geogram's harness
(`H rvd MESH SITES --threads 1 --repeat 1`: t_load + t_total_mesh) and the program
(`P MESH --sites SITES --metric euclidean --threads 1 --stats`: end_to_end) run alternately, R
times each (default 3), one process per run; the table gives the medians and their ratio.
Sites files come from make_sites.py, the same file for both.
"""
import argparse
import os
import re
import statistics
import subprocess


def geogram_seconds(harness, mesh, sites):
    out = subprocess.run([harness, "rvd", mesh, sites, "--threads", "1", "--repeat", "1"],
                         check=True, capture_output=True, text=True).stdout
    line = [x for x in out.splitlines() if x.startswith("RESULT")][-1]
    value = dict(re.findall(r"(\w+)=([^\s]+)", line))
    return float(value["t_load"]) + float(value["t_total_mesh"])


def program_seconds(program, mesh, sites):
    out = subprocess.run([program, mesh, "--sites", sites, "--metric", "euclidean", "--threads", "1", "--stats"],
                         check=True, capture_output=True, text=True).stdout
    return float(re.search(r"^end_to_end: (\S+)", out, re.M).group(1))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--program", required=True)
    parser.add_argument("--harness", required=True)
    parser.add_argument("--cases", required=True)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    print("load average before: %s\n" % " ".join(open("/proc/loadavg").read().split()[:3]))
    print("| mesh | sites | ours (s) | geogram (s) | ours / geogram |")
    print("|---|---|---|---|---|")
    for case in args.cases.split(","):
        mesh, sites = case.split(":")
        ours, theirs = [], []
        for _ in range(args.repeat):
            theirs.append(geogram_seconds(args.harness, mesh, sites))
            ours.append(program_seconds(args.program, mesh, sites))
        a, b = statistics.median(ours), statistics.median(theirs)
        count = sum(1 for line in open(sites) if line.strip())
        print("| %s | %d | %.3f | %.3f | %.2f |" % (os.path.basename(mesh), count, a, b, a / b))
    print("\nload average after: %s" % " ".join(open("/proc/loadavg").read().split()[:3]))


if __name__ == "__main__":
    main()
