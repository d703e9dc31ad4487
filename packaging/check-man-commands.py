#!/usr/bin/env python3
"""The man page's COMMANDS section lists the same commands, with the same synopses, as the
program's --help (which prints them from its command table): a command added, renamed or given
new arguments cannot ship with a man page that does not say so. Likewise its EXIT STATUS lists
the codes of --help's exit code table (printed from the program's table), each naming the
commands --help names for it; its SYNOPSIS names every link option of --help; and monitor's
entry names every FORMAT --help lists.

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


def help_text(program):
    return subprocess.run([program, "--help"], capture_output=True, text=True, check=True).stdout


def man_section(page, name):
    text = open(page, encoding="utf-8").read()
    return text.split(f"\n.SH {name}\n", 1)[1].split("\n.SH ", 1)[0].replace("\\-", "-")


def exit_codes_from_help(text, commands):
    """{code: the command names its meaning mentions}."""
    codes, current = {}, None
    for line in text.split("\nExit codes:\n", 1)[1].splitlines():
        match = re.match(r"^  (\d+)\s+(.*)", line)
        if match:
            current = int(match.group(1))
            codes[current] = match.group(2)
        elif current is not None and line.startswith("       "):
            codes[current] += " " + line.strip()
    return {code: {c for c in commands if re.search(rf"(^|[^\w-]){re.escape(c)}([^\w-]|$)", t)}
            for code, t in codes.items()}


def exit_codes_from_man(page):
    """{code: its paragraph} of EXIT STATUS (".TP", ".B N", the text)."""
    lines = man_section(page, "EXIT STATUS").splitlines()
    codes, current = {}, None
    for i, line in enumerate(lines):
        match = re.match(r"^\.B (\d+)$", line)
        if match and i > 0 and lines[i - 1] == ".TP":
            current = int(match.group(1))
            codes[current] = ""
        elif line.startswith(".PP") or line == ".TP":
            if line.startswith(".PP"):
                current = None
        elif current is not None:
            codes[current] += " " + re.sub(r"^\.\w+\s*", "", line)
    return codes


def main():
    program, page = sys.argv[1], sys.argv[2]
    helped, documented = from_help(program), from_man(page)
    status = 0
    text = help_text(program)
    # The exit codes, and the commands each one names.
    commands = {re.split(r"[\s|]", s)[0] for s in helped} | {"restore-values", "checkout"}
    for code, named in sorted(exit_codes_from_help(text, commands).items()):
        man = exit_codes_from_man(page)
        if code not in man:
            print(f"{page}: EXIT STATUS lacks {code} (from {program} --help)", file=sys.stderr)
            status = 1
            continue
        for command in sorted(named):
            if not re.search(rf"(^|[^\w-]){re.escape(command)}([^\w-]|$)", man[code]):
                print(f"{page}: EXIT STATUS {code} does not name {command}, as --help does",
                      file=sys.stderr)
                status = 1
    for code in sorted(set(exit_codes_from_man(page)) - set(exit_codes_from_help(text, commands))):
        print(f"{page}: EXIT STATUS has {code}, which {program} --help does not list",
              file=sys.stderr)
        status = 1
    # The link options in the SYNOPSIS.
    link = text.split("\nLink", 1)[1].split("\n\n", 1)[0]
    synopsis = man_section(page, "SYNOPSIS")
    for option in sorted(set(re.findall(r"^  (--[a-z-]+)", link, re.M))):
        if option not in synopsis:
            print(f"{page}: SYNOPSIS lacks {option} (a link option of --help)", file=sys.stderr)
            status = 1
    # monitor's formats.
    formats = re.search(r"FORMAT: ([a-z, \n]+);", text)
    monitor = man_section(page, "COMMANDS").split("\n.BI monitor ", 1)[-1].split("\n.TP\n", 1)[0]
    for name in re.split(r"[,\s]+", formats.group(1).strip()) if formats else []:
        if not re.search(rf"\b{name}\b", monitor):
            print(f"{page}: monitor does not list the format {name}", file=sys.stderr)
            status = 1
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
