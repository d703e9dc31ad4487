#!/usr/bin/env python3
"""The man page's COMMANDS section lists the same commands, with the same synopses, as the
program's --help (which prints them from its command table): a command added, renamed or given
new arguments cannot ship with a man page that does not say so.

    check-man-commands.py PROGRAM PAGE"""
import re
import subprocess
import sys


def normal(synopsis):
    synopsis = re.sub(r"\s*\|\s*", "|", synopsis)
    return re.sub(r"\s+", " ", synopsis).strip()


def from_help(program):
    text = subprocess.run([program, "--help"], capture_output=True, text=True, check=True).stdout
    section = text.split("\nCommands:\n", 1)[1].split("\n\n", 1)[0]
    # A synopsis starts a line after two spaces; its summary follows after two or more spaces,
    # or on the next lines (indented further).
    return {normal(re.split(r"\s{2,}", line.strip())[0])
            for line in section.splitlines() if re.match(r"^  \S", line)}


def from_man(page):
    text = open(page, encoding="utf-8").read()
    section = text.split("\n.SH COMMANDS\n", 1)[1].split("\n.SH ", 1)[0]
    lines = section.splitlines()
    found = set()
    for i, line in enumerate(lines[:-1]):
        if line != ".TP":
            continue
        tag = re.sub(r"^\.(B|BI|BR|I|IR|RB|RI)\s+", "", lines[i + 1])
        tag = re.sub(r"\\f.", "", tag).replace('"', "").replace("\\-", "-")
        found.add(normal(tag))
    return found


def main():
    program, page = sys.argv[1], sys.argv[2]
    helped, documented = from_help(program), from_man(page)
    status = 0
    for synopsis in sorted(helped - documented):
        print(f"{page}: COMMANDS lacks \"{synopsis}\" (from {program} --help)", file=sys.stderr)
        status = 1
    for synopsis in sorted(documented - helped):
        print(f"{page}: COMMANDS has \"{synopsis}\", which {program} --help does not list",
              file=sys.stderr)
        status = 1
    if not helped:
        print(f"{program} --help lists no commands", file=sys.stderr)
        status = 1
    return status


if __name__ == "__main__":
    sys.exit(main())
