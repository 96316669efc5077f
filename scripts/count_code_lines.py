#!/usr/bin/env python3
"""Counts the lines of code of the package's public tree: non-blank lines that are not only a
comment (// or /* ... */), per file and in total, in include/CGAL.

usage: python3 scripts/count_code_lines.py [--max N] [--files] [ROOT]
With --max N, exits 1 when the total exceeds N (the budget the CI holds the package to)."""
import argparse
import os
import sys


def code_lines(path):
    count = 0
    in_block = False
    with open(path, encoding="utf-8") as f:
        for line in f:
            rest = line.strip()
            code = False
            while rest:
                if in_block:
                    end = rest.find("*/")
                    if end < 0:
                        rest = ""
                    else:
                        in_block = False
                        rest = rest[end + 2:].strip()
                elif rest.startswith("//"):
                    rest = ""
                elif rest.startswith("/*"):
                    in_block = True
                    rest = rest[2:]
                else:
                    code = True   # a comment after code does not make the line a comment
                    rest = ""
            count += code
    return count


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--max", type=int)
    parser.add_argument("--files", action="store_true", help="print the count of each file")
    parser.add_argument("root", nargs="?",
                        default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "include", "CGAL"))
    args = parser.parse_args()
    counts = []
    for folder, _, names in os.walk(args.root):
        for name in names:
            if name.endswith((".h", ".hpp")):
                path = os.path.join(folder, name)
                counts.append((code_lines(path), os.path.relpath(path, args.root)))
    total = sum(n for n, _ in counts)
    if args.files:
        for n, path in sorted(counts):
            print(f"{n:6d} {path}")
    print(f"{total} lines of code in {len(counts)} headers")
    if args.max is not None and total > args.max:
        print(f"more than the budget of {args.max}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
