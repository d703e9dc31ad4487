#!/usr/bin/env python3
"""Runs every `$ fatek-cli --sim ...` example of a Markdown file and compares it with what the
file shows; with --sim FATEK_SIM also the examples against a simulator started in the same block
(`$ fatek-sim --tcp 5300 ... &`, started on a free port that replaces 5300 in the block's
fatek-cli commands; a block with another program, such as socat, is not run). What is compared: the exit code (a "# exit N" comment, else 0) and the shape of the output, since the
demo ladder's values move: per line of standard output, a JSON object's keys, or else its first
word and its number of words; the standard error lines ("fatek-cli: ...") by count and by their
first two words. A documented line "..." stands for any number of lines (values that move).

    check_cli_examples.py [--sim FATEK_SIM] FATEK_CLI FILE.md...
Examples run in order in one scratch folder (one may read what an earlier one wrote)."""
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile


def examples(path, with_sim):
    """(line number, command, exit code, documented output lines, simulators to start first) of
    each example: fatek-cli --sim, and with `with_sim` those after a `$ fatek-sim ... &` of their
    block (its arguments)."""
    found = []
    in_block = False
    current = None
    sims = []
    runnable = True
    block = []
    for number, line in enumerate(open(path, encoding="utf-8"), 1):
        line = line.rstrip("\n")
        if line.startswith("```"):
            in_block = not in_block
            if current:
                block.append(current)
                current = None
            if not in_block and runnable:
                found += block
            block, sims, runnable = [], [], True
            continue
        if not in_block:
            continue
        if line.startswith("$ "):
            if current:
                block.append(current)
                current = None
            command = line[2:]
            if command.startswith("fatek-sim ") and command.rstrip().endswith("&"):
                sims.append(command.rstrip()[:-1].split()[1:])
            elif command.startswith("fatek-cli --sim") or (command.startswith("fatek-cli")
                                                          and sims and with_sim):
                code = 0
                match = re.search(r"#\s*exit (\d+)", command)
                if match:
                    code = int(match.group(1))
                command = command.split("#")[0].strip()
                current = (number, command, code, [], list(sims))
            elif not command.startswith("fatek-cli"):
                runnable = False  # socat and the like: not run here
            continue
        if current is not None and line.strip():
            current[3].append(line)
    return found


def start_sims(sim, sims):
    """Starts each `fatek-sim ARGS` on free ports; the processes and {documented port: port}."""
    processes, ports = [], {}
    for args in sims:
        args = list(args)
        wanted = {}
        for i, a in enumerate(args[:-1]):
            if a in ("--tcp", "--udp"):
                wanted[a[2:]] = args[i + 1]
                args[i + 1] = "0"
        p = subprocess.Popen([sim] + args, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                             text=True)
        processes.append(p)
        while len([k for k in wanted if (k, wanted[k]) in ports.get("_seen", set())]) < len(wanted):
            line = p.stdout.readline()
            if not line:
                break
            match = re.match(r"listening on (tcp|udp) \S+:(\d+)", line)
            if match and match.group(1) in wanted:
                ports[wanted[match.group(1)]] = match.group(2)
                ports.setdefault("_seen", set()).add((match.group(1), wanted[match.group(1)]))
    ports.pop("_seen", None)
    return processes, ports


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
    argv = sys.argv[1:]
    sim = None
    if argv[:1] == ["--sim"]:
        sim, argv = os.path.abspath(argv[1]), argv[2:]
    cli, files = os.path.abspath(argv[0]), argv[1:]
    failures = 0
    checked = 0
    with tempfile.TemporaryDirectory() as scratch:
        env = dict(os.environ, LANGUAGE="en")
        for path in files:
            for number, command, code, documented, sims in examples(path, sim is not None):
                processes, ports = start_sims(sim, sims) if sims else ([], {})
                for documented_port, port in ports.items():
                    command = re.sub(rf":{documented_port}\b", f":{port}", command)
                args = shlex.split(command)
                stdin = subprocess.DEVNULL
                if "<" in args:  # "< /dev/null"
                    args = args[: args.index("<")]
                head = None
                if "|" in args:  # "| head -6": the first lines
                    pipe = args[args.index("|") + 1:]
                    args = args[: args.index("|")]
                    head = int(pipe[1].lstrip("-")) if pipe[:1] == ["head"] else None
                try:
                    run = subprocess.run([cli] + args[1:], cwd=scratch, env=env, stdin=stdin,
                                         capture_output=True, text=True, timeout=120)
                finally:
                    for p in processes:
                        p.terminate()
                        p.wait()
                if head is not None:
                    run.stdout = "\n".join(run.stdout.splitlines()[:head])
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
