#!/usr/bin/env python3
"""Which sources clang-tidy must check again (tools/tidy.sh --changed), and the record of a full
run that passed (tools/tidy.sh --record), kept in the repository as .ci/tidy-baseline so that a
fresh clone, without history, knows it.

The record holds, for every translation unit checked, a hash of its compile command and of each
file it read (the source, our headers, generated moc/uic output), with the checkout's and the
build's folder names taken out, so it holds on any machine. A unit is checked again when any of
these differs or is new. Everything is checked again when the configuration changed (.clang-tidy,
the presets, the batching script, the compilers) or when the record is too old.

    tidyscope.py changed BUILD_DIR BASELINE MAX_COMMITS FILE...
        prints the FILEs to check, one per line; or "full: REASON" alone when all must be
    tidyscope.py record BUILD_DIR BASELINE COMMIT FILE...
        writes BASELINE for FILEs (call it only after they passed)
"""
import hashlib
import json
import os
import re
import shlex
import subprocess
import sys

# What decides the findings besides the sources: the checks, the presets' flags, how batches are
# joined, and the compilers (clang-tidy's own headers and GCC's, which the compile commands name).
CONFIG_FILES = [".clang-tidy", "CMakePresets.json", "tools/tidybatch.py"]
CONFIG_TOOLS = [["clang-tidy-14", "--version"], ["c++", "--version"]]


def digest(data):
    return hashlib.sha256(data).hexdigest()[:16]


class Tree:
    def __init__(self, build):
        self.source = os.getcwd()
        self.build = os.path.abspath(build)

    def normalise(self, data):
        """Content with the machine's folder names replaced: the same tree hashes the same in any
        clone (the build folder first: it lies inside the checkout)."""
        return data.replace(self.build.encode(), b"@BUILD@").replace(self.source.encode(), b"@SOURCE@")

    def key(self, path):
        """A dependency's name in the record: relative to the checkout or the build, or None for
        a system header (those change only with the compiler, which the configuration covers)."""
        p = os.path.normpath(os.path.join(self.build, path))
        for root, tag in ((self.build, "build"), (self.source, "source")):
            if p.startswith(root + os.sep):
                return tag + ":" + os.path.relpath(p, root)
        return None

    def file_hash(self, key):
        tag, rel = key.split(":", 1)
        path = os.path.join(self.build if tag == "build" else self.source, rel)
        try:
            with open(path, "rb") as f:
                return digest(self.normalise(f.read()))
        except OSError:
            return "missing"


def config_hash():
    h = hashlib.sha256()
    for name in CONFIG_FILES:
        try:
            with open(name, "rb") as f:
                h.update(name.encode() + b"\0" + f.read())
        except OSError:
            h.update(name.encode() + b"\0missing")
    for cmd in CONFIG_TOOLS:
        try:
            out = subprocess.run(cmd, capture_output=True, check=False).stdout
        except OSError:
            out = b"missing"
        h.update(out)
    return h.hexdigest()[:16]


def units(tree, files):
    """{source: (command hash, object)} for FILEs from the compile database."""
    with open(os.path.join(tree.build, "compile_commands.json"), encoding="utf-8") as f:
        db = json.load(f)
    wanted = {os.path.abspath(p): p for p in files}
    out = {}
    for entry in db:
        path = os.path.abspath(os.path.join(entry["directory"], entry["file"]))
        if path not in wanted:
            continue
        args = shlex.split(entry["command"])
        obj = args[args.index("-o") + 1] if "-o" in args else ""
        out[wanted[path]] = (digest(tree.normalise(entry["command"].encode())), obj)
    return out


def dependencies(tree):
    """{object: [dependency]} from ninja's record of what each compile read."""
    text = subprocess.run(["ninja", "-C", tree.build, "-t", "deps"], capture_output=True, check=True,
                          text=True).stdout
    deps, current = {}, None
    for line in text.splitlines():
        if not line.strip():
            current = None
        elif not line.startswith(" "):
            m = re.match(r"^(.*?): #deps", line)
            current = m.group(1) if m else None
            if current:
                deps[current] = []
        elif current:
            deps[current].append(line.strip())
    return deps


def state(tree, files):
    """{source: (command hash, {dependency key: hash})}."""
    deps = dependencies(tree)
    out, cache = {}, {}
    for src, (command, obj) in units(tree, files).items():
        hashes = {}
        for d in deps.get(obj, []):
            k = tree.key(d)
            if k is not None:
                if k not in cache:
                    cache[k] = tree.file_hash(k)
                hashes[k] = cache[k]
        k = "source:" + os.path.normpath(src)
        hashes.setdefault(k, cache.get(k) or tree.file_hash(k))
        out[src] = (command, hashes)
    return out


def read_baseline(path):
    base = {"units": {}, "files": {}}
    seen = set()
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line or line.startswith("#"):
                continue
            word, _, rest = line.partition(" ")
            if word in ("config", "commit"):
                if word in base:
                    raise ValueError(f"{path}:{number}: a second \"{word}\" line")
                base[word] = rest
            elif word in ("unit", "file"):
                value, _, name = rest.partition(" ")
                if (word, name) in seen:
                    raise ValueError(f"{path}:{number}: {name} is listed twice")
                seen.add((word, name))
                base["units" if word == "unit" else "files"][name] = value
            else:
                raise ValueError(f"{path}:{number}: \"{word}\" is not a known entry (config, commit, unit, file)")
    return base


def changed(build, baseline, max_commits, files):
    if not os.path.exists(baseline):
        return "full: no record of a full run (" + baseline + ")"
    try:
        base = read_baseline(baseline)
    except ValueError as e:
        return "full: " + str(e)
    if base.get("config") != config_hash():
        return "full: the configuration changed (.clang-tidy, the presets, tools/tidybatch.py or a compiler)"
    commits = os.environ.get("FATEK_TIDY_COMMITS", "")
    if commits.isdigit() and int(commits) >= max_commits:
        return f"full: the record is {commits} commits old (a full run at least every {max_commits})"
    tree = Tree(build)
    out = []
    for src, (command, hashes) in sorted(state(tree, files).items()):
        if base["units"].get(src) != command or any(base["files"].get(k) != h for k, h in hashes.items()):
            out.append(src)
    return out


def record(build, baseline, commit, files):
    tree = Tree(build)
    now = state(tree, files)
    lines = [
        "# The last full clang-tidy run that passed (tools/tidy.sh --record): CI checks only the",
        "# units whose command or files differ from these (tools/tidyscope.py says how).",
        "config " + config_hash(),
        "commit " + commit,
    ]
    files_seen = {}
    for src, (command, hashes) in sorted(now.items()):
        lines.append(f"unit {command} {src}")
        files_seen.update(hashes)
    lines += [f"file {h} {k}" for k, h in sorted(files_seen.items())]
    tmp = baseline + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, baseline)
    print(f"tidy: recorded {len(now)} units and {len(files_seen)} files in {baseline}")


def main(argv):
    if len(argv) < 5 or argv[1] not in ("changed", "record"):
        sys.stderr.write(__doc__)
        return 2
    if argv[1] == "changed":
        result = changed(argv[2], argv[3], int(argv[4]), argv[5:])
        if result:
            print(result if isinstance(result, str) else "\n".join(result))
    else:
        record(argv[2], argv[3], argv[4], argv[5:])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
