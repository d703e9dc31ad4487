#!/usr/bin/env python3
"""Runs clang-tidy over many sources in batches (tools/tidy.sh calls it).

Most of clang-tidy's time per source goes into parsing and matching Qt's headers again (about
3.5 of 5.5 s). A batch joins the sources of one folder that share a compile command into one
translation unit, each source's text after a `#line 1 "path"` marker, so the headers are parsed
once per batch while every finding still names its own file and line, and every source is still
the main file for checks that look only there (misc-unused-using-decls). A batch that does not
compile as one (two sources with the same internal name) is checked again source by source, so
a clash costs time, never a finding.

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
    """The compile command without its source and output: sources with equal keys can share a TU."""
    args = shlex.split(entry["command"])
    out, skip = [], False
    for a in args:
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


def run_tidy(db_dir, source):
    # The checks are the project's whatever folder the batch is written to.
    config = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), ".clang-tidy")
    proc = subprocess.run([CLANG_TIDY, "-quiet", "--config-file=" + config, "-p", db_dir, source], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, errors="replace")
    return proc.returncode, proc.stdout


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

    batch_db, batches, layouts = [], [], {}
    for (key, folder), members in groups.items():
        directory, args = key
        for i in range(0, len(members), batch_size):
            chunk = members[i:i + batch_size]
            if len(chunk) == 1:
                batches.append((chunk[0], chunk))
                continue
            path = os.path.join(out_dir, "batch%03d.cpp" % len(batches))
            starts, line = [], 1
            with open(path, "w") as out:
                for source in chunk:
                    text = open(source, encoding="utf-8").read()
                    text += "" if text.endswith("\n") else "\n"
                    out.write('#line 1 "%s"\n%s' % (source, text))
                    starts.append((line + 1, source))
                    line += 1 + text.count("\n")
            layouts[path] = starts
            # Quoted includes resolve against the batch's folder, not the source's: -iquote it.
            command = list(args) + ["-iquote", folder, "-c", path, "-o", path + ".o"]
            batch_db.append({"directory": directory, "file": path, "command": shlex.join(command)})
            batches.append((path, chunk))

    # One database with the batches and the single sources as they were.
    db_dir = os.path.join(out_dir, "db")
    os.makedirs(db_dir, exist_ok=True)
    json.dump(list(entries.values()) + batch_db, open(os.path.join(db_dir, "compile_commands.json"), "w"))

    retries, failed = [], 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        results = list(pool.map(lambda b: (b, run_tidy(db_dir, b[0])), batches))
        for (tu, chunk), (rc, output) in results:
            clash = COMPILE_ERROR.search(output) if len(chunk) > 1 else None
            if clash:
                print("tidy: %s did not compile as one (%s): checked alone" % (
                    " ".join(os.path.relpath(c) for c in chunk), clash.group(0).split(": error: ")[-1]),
                    file=sys.stderr)
                retries.extend(chunk)
                continue
            failed += rc != 0
            sys.stdout.write(unbatched(output, {tu: layouts[tu]} if tu in layouts else {}))
        for source, (rc, output) in zip(retries, pool.map(lambda s: run_tidy(db_dir, s), retries)):
            failed += rc != 0
            sys.stdout.write(output)
    print("tidy: %d sources in %d translation units, %d checked again alone (a batch did not compile)"
          % (len(files), len(batches), len(retries)), file=sys.stderr)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
