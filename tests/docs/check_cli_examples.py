#!/usr/bin/env python3
"""Runs every `$ fatek-cli --sim ...` example of a Markdown file and compares it with what the
file shows: the exit code (a "# exit N" comment, else 0) and the shape of the output, since the
demo ladder's values move: per line of standard output, a JSON object's keys, or else its first
word and its number of words; the standard error lines ("fatek-cli: ...") by count and by their
first two words. A documented line "..." stands for any number of lines (values that move).

    check_cli_examples.py FATEK_CLI FILE.md...
Examples run in order in one scratch folder (one may read what an earlier one wrote)."""
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile


def examples(path):
    """(line number, command, exit code, documented output lines) of each --sim example."""
    found = []
    in_block = False
    current = None
    for number, line in enumerate(open(path, encoding="utf-8"), 1):
        line = line.rstrip("\n")
        if line.startswith("```"):
            in_block = not in_block
            if current:
                found.append(current)
                current = None
            continue
        if not in_block:
            continue
        if line.startswith("$ "):
            if current:
                found.append(current)
                current = None
            command = line[2:]
            if command.startswith("fatek-cli --sim"):
                code = 0
                match = re.search(r"#\s*exit (\d+)", command)
                if match:
                    code = int(match.group(1))
                command = command.split("#")[0].strip()
                current = (number, command, code, [])
            continue
        if current is not None and line.strip():
            current[3].append(line)
    return found


def shape(line):
    try:
        value = json.loads(line)
        if isinstance(value, dict):
            return ("json", tuple(sorted(value)))
    except ValueError:
        pass
    if "," in line and "  " not in line:  # CSV: its number of fields
        return ("csv", len(line.split(",")))
    words = line.split()
    return ("text", words[0] if words else "", len(words))


def main():
    cli, files = os.path.abspath(sys.argv[1]), sys.argv[2:]
    failures = 0
    checked = 0
    with tempfile.TemporaryDirectory() as scratch:
        env = dict(os.environ, LANGUAGE="en")
        for path in files:
            for number, command, code, documented in examples(path):
                args = shlex.split(command)
                stdin = subprocess.DEVNULL
                if "<" in args:  # "< /dev/null"
                    args = args[: args.index("<")]
                run = subprocess.run([cli] + args[1:], cwd=scratch, env=env, stdin=stdin,
                                     capture_output=True, text=True, timeout=120)
                where = f"{os.path.basename(path)}:{number}: {command}"
                problems = []
                if run.returncode != code:
                    problems.append(f"exit {run.returncode}, the example says {code}")
                doc_err = [l for l in documented
                           if l.startswith("fatek-cli:") or l.startswith("Try '")]
                doc_out = [l for l in documented if l not in doc_err]
                doc_err = [re.sub(r"\s+\(stderr\)$", "", l) for l in doc_err]
                out = [l for l in run.stdout.splitlines() if l.strip()]
                err = [l for l in run.stderr.splitlines() if l.strip()]
                more = "..." in doc_out
                doc_out = [l for l in doc_out if l != "..."]
                if more:
                    if not out:
                        problems.append("no output lines, the example shows some")
                elif [shape(l) for l in out] != [shape(l) for l in doc_out]:
                    problems.append("output differs in shape:\n    shown:  "
                                    + "\n            ".join(doc_out) + "\n    actual: "
                                    + "\n            ".join(out))
                def start(lines):  # the first two words, numbers as N
                    return [re.sub(r"\d+", "N", " ".join(l.split()[:2])) for l in lines]
                if start(err) != start(doc_err):
                    problems.append("standard error differs:\n    shown:  "
                                    + "\n            ".join(doc_err) + "\n    actual: "
                                    + "\n            ".join(err))
                checked += 1
                if problems:
                    failures += 1
                    print(f"FAIL {where}\n  " + "\n  ".join(problems))
    print(f"{checked} examples checked, {failures} differ")
    return 1 if failures or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
