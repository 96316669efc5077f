#!/usr/bin/env python3
"""The bad-input corpus: hostile files and command lines, each with the answer it must get.

  run_bad_input.py PROGRAM [--corpus DIR] [--work DIR] [--only SUBSTRING]
                   [--time-factor F] [--no-memory-limit] [--list]

Every `*.cases` file of the corpus folder holds one case a line (`#` starts a comment):

  name | exit | message substring | program arguments [| option ...]

- arguments are split on spaces; `{dir}` is the corpus folder, `{out}` a fresh empty folder
  of this case, `{gen}` the folder of large inputs that make_large_inputs.py writes first;
- exit is the exit code the program must give (0 when it must succeed);
- the substring must appear in the one line the program writes on stderr for a non-zero exit
  (for exit 0, `-` or a substring of one of its warning or note lines);
- options: `seconds=S` (time limit, default 10), `fsize=BYTES` (a file-size limit, to make a
  write fail half-way as on a full disk), `files=a,b` (exactly these files must be in `{out}`
  afterwards; by default none may be: a failed run leaves no partial file).

A case passes when the program exits with that code within the time limit and under a 4 GiB
address-space limit, and, for a non-zero exit, writes exactly one line on stderr, starting with
`surface_voronoi: error: `, holding the substring, in printable ASCII. Under sanitizers, pass
--time-factor (their slowdown) and --no-memory-limit (their shadow memory needs more address
space than the limit allows; they report leaks and overflows themselves).
"""

import argparse
import os
import resource
import shutil
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ADDRESS_SPACE = 4 << 30
PREFIX = "surface_voronoi: error: "


class Case:
    def __init__(self, source, line, fields):
        self.where = "%s:%d" % (os.path.basename(source), line)
        if len(fields) < 4:
            raise SystemExit(self.where + ": expected 'name | exit | substring | arguments [| option ...]'")
        self.name, exit_text, self.substring, self.arguments = fields[:4]
        self.exit = int(exit_text)
        self.seconds, self.fsize, self.files = 10.0, None, []
        for option in fields[4:]:
            key, _, value = option.partition("=")
            if key == "seconds":
                self.seconds = float(value)
            elif key == "fsize":
                self.fsize = int(value)
            elif key == "files":
                self.files = sorted(f for f in value.split(",") if f)
            else:
                raise SystemExit(self.where + ": unknown option '" + option + "'")


def read_cases(corpus):
    cases = []
    for manifest in sorted(f for f in os.listdir(corpus) if f.endswith(".cases")):
        path = os.path.join(corpus, manifest)
        with open(path) as f:
            for number, text in enumerate(f, 1):
                text = text.split("#", 1)[0].strip() if not text.lstrip().startswith("#") else ""
                if text:
                    cases.append(Case(path, number, [field.strip() for field in text.split(" | ")]))
    names = [c.name for c in cases]
    repeated = sorted({n for n in names if names.count(n) > 1})
    if repeated:
        raise SystemExit("repeated case names: " + ", ".join(repeated))
    return cases


def limits(case, memory_limit):
    def apply():
        if memory_limit:
            resource.setrlimit(resource.RLIMIT_AS, (ADDRESS_SPACE, ADDRESS_SPACE))
        if case.fsize is not None:
            resource.setrlimit(resource.RLIMIT_FSIZE, (case.fsize, case.fsize))
            # a write past the limit must fail with EFBIG, not kill the program
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        os.setsid()
    return apply


def run_case(program, case, corpus, gen, work, time_factor, memory_limit):
    out = os.path.join(work, case.name)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    arguments = [a.replace("{dir}", corpus).replace("{out}", out).replace("{gen}", gen)
                 for a in case.arguments.split()]
    substring = case.substring.replace("{dir}", corpus).replace("{out}", out)
    limit = case.seconds * time_factor
    start = time.monotonic()
    process = subprocess.Popen([program] + arguments, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                               preexec_fn=limits(case, memory_limit))
    try:
        _, stderr = process.communicate(timeout=limit)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.communicate()
        return ["did not finish within %.0f s" % limit]
    seconds = time.monotonic() - start
    problems = []
    if process.returncode != case.exit:
        problems.append("exit %d, expected %d" % (process.returncode, case.exit))
    try:
        text = stderr.decode("ascii")
    except UnicodeDecodeError:
        text = stderr.decode("latin-1")
        problems.append("stderr is not ASCII")
    lines = text.splitlines()
    if any(not all(32 <= ord(c) < 127 or c == "\t" for c in line) for line in lines):
        problems.append("stderr has a non-printable character")
    if case.exit != 0:
        if len(lines) != 1:
            problems.append("%d stderr lines, expected one error line" % len(lines))
        errors = [l for l in lines if l.startswith(PREFIX)]
        if not errors:
            problems.append("no line starts with '" + PREFIX + "'")
        elif substring not in errors[0]:
            problems.append("the message lacks '" + substring + "'")
    elif substring != "-" and not any(substring in l for l in lines):
        problems.append("no stderr line holds '" + substring + "'")
    left = sorted(os.listdir(out))
    if left != case.files:
        problems.append("files left in {out}: [%s], expected [%s]" % (", ".join(left), ", ".join(case.files)))
    if problems:
        problems.append("stderr was: " + (" / ".join(lines)[:400] or "(empty)"))
    else:
        shutil.rmtree(out, ignore_errors=True)
    return problems, seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("program")
    parser.add_argument("--corpus", default=HERE)
    parser.add_argument("--work", default=os.path.join(os.getcwd(), "bad_input_runs"))
    parser.add_argument("--only", default="")
    parser.add_argument("--time-factor", type=float, default=1.0)
    parser.add_argument("--no-memory-limit", action="store_true")
    parser.add_argument("--list", action="store_true")
    args = parser.parse_args()

    corpus = os.path.abspath(args.corpus)
    work = os.path.abspath(args.work)
    cases = [c for c in read_cases(corpus) if args.only in c.name]
    if args.list:
        for c in cases:
            print(c.name)
        return 0
    gen = os.path.join(work, "generated")
    generator = os.path.join(corpus, "make_large_inputs.py")
    if os.path.exists(generator):
        os.makedirs(gen, exist_ok=True)
        subprocess.run([sys.executable, generator, gen], check=True)

    program = os.path.abspath(args.program)
    failed = 0
    for case in cases:
        result = run_case(program, case, corpus, gen, work, args.time_factor, not args.no_memory_limit)
        problems, seconds = (result, None) if isinstance(result, list) else result
        if problems:
            failed += 1
            print("FAIL %s (%s): %s" % (case.name, case.where, "; ".join(problems)))
        else:
            print("ok   %-45s %6.2f s" % (case.name, seconds))
    print("%d cases run, %d passed, %d failed" % (len(cases), len(cases) - failed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
