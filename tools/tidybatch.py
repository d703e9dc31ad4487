#!/usr/bin/env python3
"""Runs clang-tidy over many sources in batches (tools/tidy.sh calls it).

Most of clang-tidy's time per source goes into parsing and matching Qt's headers again (about
3.5 of 5.5 s). A batch joins the sources of one folder that share a compile command into one
translation unit, each source's text after a `#line 1 "path"` marker, so the headers are parsed
once per batch while every finding still names its own file and line, and every source is still
the main file for checks that look only there (misc-unused-using-decls). A batch that does not
compile as one (two sources with the same internal name) is halved until its parts do, so a
clash costs time, never a finding.

    tidybatch.py COMPILE_DB OUT_DIR JOBS BATCH_SIZE FILE...

Prints clang-tidy's output of every translation unit checked (the caller counts the findings);
exits 1 if any clang-tidy run failed.
"""
import collections
import concurrent.futures
import json
import os
import re
import shlex
import subprocess
import sys

CLANG_TIDY = "clang-tidy-14"
# A compiler error, not a finding (findings are errors too: WarningsAsErrors).
COMPILE_ERROR = re.compile(r"^/.*:\d+:\d+: (?:fatal )?error: .*\[clang-diagnostic-error\]$", re.M)


def command_key(entry):
    """The compile command without its source and output, and without the precompiled header
    (cmake/FatekPch.cmake): clang cannot read GCC's. Sources with equal keys can share a TU."""
    command = re.sub(r" -Xclang -include-pch -Xclang \S+| -Xclang -include -Xclang \S+cmake_pch\.hxx"
                     r"| -include \S+cmake_pch\.hxx| -Winvalid-pch", "", entry["command"])
    out, skip = [], False
    for a in shlex.split(command):
        if skip:
            skip = False
            continue
        if a in ("-o", "-c"):
            skip = True
            continue
        out.append(a)
    return entry["directory"], tuple(out)


def unbatched(output, layouts):
    """clang-tidy names the batch, not the #line: gives each location back its source and line."""
    def place(match):
        starts = layouts[match.group(1)]
        line = int(match.group(2))
        first, source = [s for s in starts if s[0] <= line][-1]
        return "%s:%d:" % (source, line - first + 1)
    if not layouts:
        return output
    names = "|".join(re.escape(p) for p in layouts)
    return re.sub(r"(%s):(\d+):" % names, place, output)


CONFIG = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), ".clang-tidy")


def run_tidy(source, directory, args):
    """One clang-tidy run of a source or a batch, its compile flags on the command line. The checks
    are the project's, whatever folder a batch is written to."""
    command = [CLANG_TIDY, "-quiet", "--config-file=" + CONFIG, source, "--"] + list(args[1:])
    proc = subprocess.run(command, cwd=directory, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, errors="replace")
    return proc.returncode, proc.stdout


class Batches:
    """Writes batch translation units: the sources' texts one after another, each after a #line."""

    def __init__(self, out_dir):
        self.out_dir, self.count, self.layouts = out_dir, 0, {}

    def write(self, chunk):
        path = os.path.join(self.out_dir, "batch%03d.cpp" % self.count)
        self.count += 1
        starts, line = [], 1
        with open(path, "w") as out:
            for source in chunk:
                text = open(source, encoding="utf-8").read()
                text += "" if text.endswith("\n") else "\n"
                out.write('#line 1 "%s"\n%s' % (source, text))
                starts.append((line + 1, source))
                line += 1 + text.count("\n")
        self.layouts[path] = starts
        return path


def main():
    db_path, out_dir, jobs, batch_size = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    files = [os.path.abspath(f) for f in sys.argv[5:]]
    entries = {os.path.abspath(os.path.join(e["directory"], e["file"])): e for e in json.load(open(db_path))}
    missing = [f for f in files if f not in entries]
    if missing:
        print("tidy: not in the compile commands (configure again?): " + " ".join(missing), file=sys.stderr)
        sys.exit(2)

    groups = collections.OrderedDict()
    for f in sorted(files):
        groups.setdefault((command_key(entries[f]), os.path.dirname(f)), []).append(f)

    batches = Batches(out_dir)
    runs, failed, clashes = 0, 0, 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        def submit(chunk, directory, args, folder):
            nonlocal runs
            runs += 1
            if len(chunk) == 1:
                future = pool.submit(run_tidy, chunk[0], directory, args)
                return future, (chunk, None, directory, args, folder)
            tu = batches.write(chunk)
            # Quoted includes resolve against the batch's folder, not the source's: -iquote it.
            command = list(args) + ["-iquote", folder]
            return pool.submit(run_tidy, tu, directory, command), (chunk, tu, directory, args, folder)

        pending = {}
        for ((directory, args), folder), members in groups.items():
            for i in range(0, len(members), batch_size):
                future, what = submit(members[i:i + batch_size], directory, args, folder)
                pending[future] = what
        while pending:
            done, _ = concurrent.futures.wait(pending, return_when=concurrent.futures.FIRST_COMPLETED)
            for future in done:
                chunk, tu, directory, args, folder = pending.pop(future)
                rc, output = future.result()
                clash = COMPILE_ERROR.search(output) if tu else None
                if clash:
                    # Two sources with the same internal name: check each half on its own.
                    clashes += 1
                    print("tidy: %s did not compile as one (%s): halved" % (
                        " ".join(os.path.relpath(c) for c in chunk), clash.group(0).split(": error: ")[-1]),
                        file=sys.stderr)
                    half = len(chunk) // 2
                    for part in (chunk[:half], chunk[half:]):
                        f, what = submit(part, directory, args, folder)
                        pending[f] = what
                    continue
                failed += rc != 0
                sys.stdout.write(unbatched(output, {tu: batches.layouts[tu]} if tu else {}))
    print("tidy: %d sources in %d clang-tidy runs (%d batches halved: they did not compile as one)"
          % (len(files), runs, clashes), file=sys.stderr)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
